// `manylights render` as a user runs it: the default job, backends, and bad flags.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test.h"

namespace ml::test {
namespace {

int countLines(const std::string& text) {
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

TEST(RenderCommand, WithNoArgumentsWritesALitAtrium) {
    const std::string dir = testOutputDir().string();
    std::filesystem::remove(dir + "/manylights.png");
    std::string output;
    ASSERT_EQ(runManylights("", output, dir), 0) << output;
    const RgbaImage image = readPng(dir + "/manylights.png");
    EXPECT_EQ(image.width, 1280);
    EXPECT_EQ(image.height, 720);
    // Non-trivial: most pixels lit, a spread of brightness, and colour (many coloured lights).
    std::size_t lit = 0, coloured = 0;
    int minLuma = 255, maxLuma = 0;
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
        const int r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
        const int luma = (r * 3 + g * 6 + b) / 10;
        lit += luma > 8;
        coloured += std::max({r, g, b}) - std::min({r, g, b}) > 24;
        minLuma = std::min(minLuma, luma);
        maxLuma = std::max(maxLuma, luma);
    }
    const double pixels = image.pixels.size() / 4.0;
    EXPECT_GT(lit / pixels, 0.6) << "most of the frame should be lit geometry";
    EXPECT_GT(coloured / pixels, 0.05) << "coloured lights should tint the scene";
    EXPECT_GT(maxLuma - minLuma, 100) << "the frame should have contrast";
    EXPECT_NE(output.find("wrote manylights.png"), std::string::npos) << output;
}

TEST(RenderCommand, TimePrintsEveryPassAndTheTotal) {
    std::string output;
    const std::string out = (testOutputDir() / "t.png").string();
    ASSERT_EQ(runManylights("render --scene boxes --size 64x48 --lights 16 --time --out " + out, output), 0) << output;
    for (const char* pass : {"lights.animate", "deferred.gbuffer", "cluster.bounds", "assign.ranges", "assign.count",
                             "assign.scan", "assign.fill", "deferred.lighting-compute", "tonemap", "total"})
        EXPECT_NE(output.find(pass), std::string::npos) << pass << " missing in:\n" << output;
    EXPECT_NE(output.find("wall clock after glFinish"), std::string::npos) << "llvmpipe must be timed by wall clock";
}

TEST(RenderCommand, EglAndOsMesaGiveTheSameImage) {
    const std::string dir = testOutputDir().string();
    const std::string common = "render --scene boxes --size 160x90 --lights 64 --seed 3 --frames 10";
    std::string output;
    ASSERT_EQ(runManylights(common + " --backend egl --verbose --out " + dir + "/egl.png", output), 0) << output;
    EXPECT_NE(output.find("platform: EGL"), std::string::npos) << output;
    ASSERT_EQ(runManylights(common + " --backend osmesa --verbose --out " + dir + "/osmesa.png", output), 0) << output;
    EXPECT_NE(output.find("platform: OSMesa"), std::string::npos) << output;
    const RgbaImage egl = readPng(dir + "/egl.png");
    const RgbaImage osmesa = readPng(dir + "/osmesa.png");
    const ImageDifference d = compareImages(osmesa, egl);
    EXPECT_LE(d.maxAbs, 1.0 / 255.0 + 1e-9) << "images in " << writeFailureImages("backends", osmesa, egl);
}

TEST(RenderCommand, SavedLightsReproduceTheFrame) {
    // Naive sums lights in index order, so the same lights give the same bits.
    const std::string dir = testOutputDir().string();
    std::string output;
    ASSERT_EQ(runManylights("render --method naive --scene boxes --size 96x64 --lights 40 --seed 9 --frames 120 --out " + dir +
                                "/a.png --out-float " + dir + "/a.pfm --save-lights " + dir + "/lights.json",
                            output),
              0)
        << output;
    ASSERT_EQ(runManylights("render --method naive --scene boxes --size 96x64 --lights-file " + dir + "/lights.json --drift-speed 0 --out " +
                                dir + "/b.png --out-float " + dir + "/b.pfm",
                            output),
              0)
        << output;
    const ImageDifference d = compareImages(readPfm(dir + "/b.pfm"), readPfm(dir + "/a.pfm"));
    EXPECT_EQ(d.maxAbs, 0.0);
}

struct BadFlag {
    const char* args;
    const char* culprit;  // must appear in the one-line message
};

class RenderCommandBadFlag : public ::testing::TestWithParam<BadFlag> {};

TEST_P(RenderCommandBadFlag, FailsWithOneLineNamingTheCulprit) {
    std::string output;
    const int status = runManylights(std::string("render --out /dev/null ") + GetParam().args, output);
    EXPECT_NE(status, 0) << output;
    EXPECT_NE(output.find(GetParam().culprit), std::string::npos) << output;
    EXPECT_LE(countLines(output), 2) << output;
}

INSTANTIATE_TEST_SUITE_P(Flags, RenderCommandBadFlag,
    ::testing::Values(BadFlag{"--method magic", "magic"}, BadFlag{"--size 0x10", "--size"},
                      BadFlag{"--size 100", "--size"}, BadFlag{"--size -5x10", "--size"},
                      BadFlag{"--lights -1", "--lights"}, BadFlag{"--light-radius -2", "--light-radius"},
                      BadFlag{"--scene nowhere.gltf", "nowhere.gltf"}, BadFlag{"--scene colosseum", "colosseum"},
                      BadFlag{"--camera 1,2,3", "--camera"}, BadFlag{"--camera gltf:0", "the scene has no cameras"},
                      BadFlag{"--backend vulkan", "vulkan"},
                      BadFlag{"--near 5 --far 1", "--near"}, BadFlag{"--lights-file /nonexistent.json", "/nonexistent.json"},
                      BadFlag{"--size 100000x10", "--size"}, BadFlag{"--tiles-x 0", "--tiles-x"},
                      BadFlag{"--slices 5000", "--slices"}, BadFlag{"--workgroup 2048", "--workgroup"},
                      BadFlag{"--workgroup 48", "--workgroup"}, BadFlag{"--slicing cubic", "cubic"},
                      BadFlag{"--assign greedy", "greedy"}, BadFlag{"--resolve raytrace", "raytrace"},
                      BadFlag{"--view heat", "heat"}, BadFlag{"--cull obb", "obb"},
                      BadFlag{"--method forward-plus --normal-cones", "--normal-cones"},
                      BadFlag{"--method naive --normal-cones", "--normal-cones"},
                      BadFlag{"--assign capped --normal-cones", "--normal-cones"}, BadFlag{"--method naive --view light-count", "--view"},
                      BadFlag{"--scene boxes --size 320x180 --assign capped --tiles-x 64", "GL_MAX_SHADER_STORAGE_BLOCK_SIZE"},
                      // Every light reaches every cluster: the exact lists' candidates pass the limit, and
                      // so does their total, read back then (llvmpipe: 211 MiB against 128).
                      BadFlag{"--scene boxes --size 160x90 --lights 2000 --light-radius 1000", "GL_MAX_SHADER_STORAGE_BLOCK_SIZE"},
                      BadFlag{"--method naive --msaa 3", "--msaa 3"}, BadFlag{"--method naive --msaa 16", "--msaa 16"},
                      BadFlag{"--method forward-plus --msaa 0", "--msaa 0"},
                      BadFlag{"--method deferred --msaa 4", "one sample per pixel"},
                      BadFlag{"--method visibility --msaa 2", "one sample per pixel"},
                      BadFlag{"--method forward-plus --view overdraw --msaa 4", "--view overdraw"},
                      BadFlag{"--method naive --supersample 9", "--supersample 9"},
                      BadFlag{"--method naive --supersample 0", "--supersample 0"},
                      BadFlag{"--method naive --supersample 2 --msaa 2", "--supersample"},
                      BadFlag{"--method naive --scene boxes --lights 1 --size 5000x100 --supersample 4", "texture limit"},
                      BadFlag{"--brdf cook-torrance", "cook-torrance"}, BadFlag{"--light-sum auto", "--light-sum 'auto'"}, BadFlag{"--light-cutoff 0", "--light-cutoff"},
                      BadFlag{"--light-cutoff -0.5", "--light-cutoff"}, BadFlag{"--light-cutoff nan", "--light-cutoff"},
                      BadFlag{"--light-cutoff inf", "--light-cutoff"},
                      BadFlag{"--light-cutoff 0.01 --light-radius 2", "--light-cutoff"}, BadFlag{"--cutoff soft", "soft"},
                      BadFlag{"--cutoff stochastic", "--cutoff stochastic"}, BadFlag{"--cutoff none", "--cutoff none"},
                      BadFlag{"--accumulate 0", "--accumulate"},
                      BadFlag{"--light-cutoff 0.1 --cutoff stochastic --accumulate 4 --bloom", "--accumulate"}),
    [](const auto& info) { return testNameOf(info.param.args); });

}  // namespace
}  // namespace ml::test
