// The accuracy contract at the size people look at (issue 29): third-party files of
// ../shared/corpus at 1280x720 with 4,096 generated lights plus the file's own, rendered as a
// user renders them (`manylights render --scene FILE --size 1280x720 --lights 4096`: the file's
// default camera or the one named, lights placed near its surfaces, automatic exposure, GGX), by
// naive once and then by every other method in its default settings, each held to the contract
// against that naive frame: at most 0.01 % of the 8-bit output's pixels more than 1/255 off.
// At 160x90 (the corpus target) mip levels blur every highlight and one pixel is 0.007 % of the
// frame, so the precision a G-buffer loses and the last bits a rebuilt texture coordinate differs
// by stay hidden; here they are 0.07-0.29 % of pixels (before the exact layout and the shared
// texture coordinates, docs/accuracy-and-stability.md). Label `fullsize`; the plain step runs
// it, the sanitizer step leaves it out (it renders what the corpus target already covers there).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "renderer/image/image.h"
#include "renderer/image/image_compare.h"
#include "tests/corpus/corpus.h"
#include "tests/gpu/gpu_test.h"

namespace ml::test {
namespace {

namespace fs = std::filesystem;

constexpr double kMaxBadShare = 1e-4;  // design.md's 99.99 %

struct FullSizeFrame {
    const char* name;      // the test's name
    const char* relative;  // under ../shared/corpus
    const char* camera;    // --camera: "default" or a camera of the file
};
// Glossy normal-mapped files, a million-triangle sweep of roughness, a file whose textures sit
// on mirrored UVs, alpha cut-outs and blends, a real interior's alpha-tested foliage and a real
// exterior's glass: each cause a method ever broke the contract for.
constexpr FullSizeFrame kFrames[] = {
    {"DamagedHelmet", "khronos/DamagedHelmet/glTF/DamagedHelmet.gltf", "default"},
    {"NormalTangentMirrorTest", "khronos/NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf", "default"},
    {"MetalRoughSpheresNoTextures", "khronos/MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf", "default"},
    {"ToyCar", "khronos/ToyCar/glTF/ToyCar.gltf", "default"},
    {"AlphaBlendModeTest", "khronos/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf", "default"},
    {"Sponza_camera0", "amd/sponza/Sponza.gltf", "gltf:0"},
    {"GasStation_camera0", "amd/gas_station/GasStation.gltf", "gltf:0"},
};

class FullSize : public ::testing::TestWithParam<FullSizeFrame> {};

// Renders one frame of the file by `method`; returns the PNG's path.
std::string renderFrame(const FullSizeFrame& f, const std::string& method) {
    const std::string out = (testOutputDir() / (method + ".png")).string();
    const std::string args = "render --scene '" + corpusPath(f.relative) + "' --camera " + f.camera +
                             " --size 1280x720 --lights 4096 --method " + method + " --out '" + out + "'";
    std::string output;
    const int status = runManylights(args, output);
    EXPECT_EQ(status, 0) << "manylights " << args << ":\n" << output;
    return out;
}

TEST_P(FullSize, EveryMethodsDefaultHoldsTheContractAgainstNaive) {
    const FullSizeFrame& f = GetParam();
    if (!fs::exists(corpusPath(f.relative))) GTEST_SKIP() << "no " << corpusPath(f.relative) << " (../shared/corpus): skipped";
    const RgbaImage naive = readPng(renderFrame(f, "naive"));
    for (const char* method : {"forward-plus", "deferred", "visibility"}) {
        const RgbaImage image = readPng(renderFrame(f, method));
        const ImageDifference d = compareImages(image, naive);
        const std::string label = std::string(f.name) + " " + method;
        std::printf("%-45s max %3.0f/255  over 1/255 %.4f %%\n", label.c_str(), d.maxAbs * 255.0, d.badPixelShare * 100.0);
        EXPECT_LE(d.badPixelShare, kMaxBadShare)
            << label << ": max " << d.maxAbs * 255.0 << "/255; images in " << writeFailureImages(testNameOf(method), image, naive);
    }
}

INSTANTIATE_TEST_SUITE_P(Corpus, FullSize, ::testing::ValuesIn(kFrames), [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ml::test
