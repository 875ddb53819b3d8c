// The accuracy contract at the size people look at (issue 29): third-party files of
// ../shared/corpus at 1280x720 with 4,096 generated lights plus the file's own, rendered as a
// user renders them (`manylights render --scene FILE --size 1280x720 --lights 4096`: the file's
// default camera or the one named, lights placed near its surfaces, automatic exposure, GGX), by
// naive once and then by every other method in its default settings, each held to the contract
// against that naive frame: at most 0.01 % of the 8-bit output's pixels more than 1/255 off.
// At 160x90 (the corpus target) mip levels blur every highlight and one pixel is 0.007 % of the
// frame, so the precision a G-buffer loses and the last bits a rebuilt texture coordinate differs
// by stay hidden; here they are 0.07-0.29 % of pixels (before the exact layout and the shared
// texture coordinates, docs/accuracy-and-stability.md). With shadows on (`--shadows rays`, issue
// 62) every method traces naive's rays, so the same contract holds for the files that fit the
// time an llvmpipe run can give them (CorpusShadowRays/...). Label `fullsize`; the plain step runs
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
    const char* name;             // the test's name
    const char* relative;         // under ../shared/corpus
    const char* camera;           // --camera: "default" or a camera of the file
    int lights = 4096;            // --lights: generated lights, beside the file's own
    const char* shadows = "off";  // --shadows
};
constexpr FullSizeFrame kDamagedHelmet{"DamagedHelmet", "khronos/DamagedHelmet/glTF/DamagedHelmet.gltf", "default"};
constexpr FullSizeFrame kNormalTangentMirrorTest{
    "NormalTangentMirrorTest", "khronos/NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf", "default"};
constexpr FullSizeFrame kMetalRoughSpheres{
    "MetalRoughSpheresNoTextures", "khronos/MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf", "default"};
constexpr FullSizeFrame kAlphaBlendModeTest{"AlphaBlendModeTest", "khronos/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf",
                                            "default"};
// Glossy normal-mapped files, a million-triangle sweep of roughness, a file whose textures sit
// on mirrored UVs, alpha cut-outs and blends, a real interior's alpha-tested foliage and a real
// exterior's glass: each cause a method ever broke the contract for. And glTF's material
// extensions' test files (issue 65): clear coat (ToyCar too, with its sheen and glass),
// anisotropy, thin films, transmission (maps, MASK, metals) and volumes (thickness maps, node
// scales), where the exact G-buffer's extra targets and the transparent pass's view of the opaque
// frame must hold at full size.
constexpr FullSizeFrame kFrames[] = {
    kDamagedHelmet,
    kNormalTangentMirrorTest,
    kMetalRoughSpheres,
    {"ToyCar", "khronos/ToyCar/glTF/ToyCar.gltf", "default"},
    kAlphaBlendModeTest,
    {"ClearCoatTest", "khronos/ClearCoatTest/glTF/ClearCoatTest.gltf", "default"},
    {"AnisotropyStrengthTest", "khronos/AnisotropyStrengthTest/glTF/AnisotropyStrengthTest.gltf", "default"},
    {"IridescenceSuzanne", "khronos/IridescenceSuzanne/glTF/IridescenceSuzanne.gltf", "default"},
    {"TransmissionTest", "khronos/TransmissionTest/glTF/TransmissionTest.gltf", "default"},
    {"AttenuationTest", "khronos/AttenuationTest/glTF/AttenuationTest.gltf", "default"},
    {"Sponza_camera0", "amd/sponza/Sponza.gltf", "gltf:0"},
    {"GasStation_camera0", "amd/gas_station/GasStation.gltf", "gltf:0"},
};

constexpr FullSizeFrame withShadowRays(FullSizeFrame f, int lights) {
    f.shadows = "rays";
    f.lights = lights;
    return f;
}
// The same frames with a shadow ray for every (pixel, light) pair that adds light (issue 62). On
// llvmpipe naive pays for every light at every pixel and then for the rays: on two cores, naive
// alone at 4,096 lights takes 46 s on DamagedHelmet, 13-14 s on NormalTangentMirrorTest and
// AlphaBlendModeTest, 105 s on the million-triangle spheres, 143 s on ToyCar, 186 s on the gas
// station and over 10 minutes on Sponza. The glossy, the mirrored and the alpha-tested files
// (whose MASK panels shadow by their texture's alpha) keep their 4,096 lights; the spheres take
// 1,024 (27 s naive), which keeps the four files' 16 frames near three minutes (187 s measured,
// 72 of them on DamagedHelmet). ToyCar's four frames take about three minutes even at 1,024
// lights, so it is left out, with Sponza and the gas station.
constexpr FullSizeFrame kShadowRayFrames[] = {
    withShadowRays(kDamagedHelmet, 4096),
    withShadowRays(kNormalTangentMirrorTest, 4096),
    withShadowRays(kAlphaBlendModeTest, 4096),
    withShadowRays(kMetalRoughSpheres, 1024),
};

class FullSize : public ::testing::TestWithParam<FullSizeFrame> {};

// Renders one frame of the file by `method`; returns the PNG's path.
std::string renderFrame(const FullSizeFrame& f, const std::string& method) {
    const std::string out = (testOutputDir() / (method + ".png")).string();
    const std::string args = "render --scene '" + corpusPath(f.relative) + "' --camera " + f.camera +
                             " --size 1280x720 --lights " + std::to_string(f.lights) + " --shadows " + f.shadows +
                             " --method " + method + " --out '" + out + "'";
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
        const std::string label = std::string(f.name) + " " + method +
                                  (std::string(f.shadows) == "off" ? "" : " shadows " + std::string(f.shadows));
        std::printf("%-52s max %3.0f/255  over 1/255 %.4f %%\n", label.c_str(), d.maxAbs * 255.0, d.badPixelShare * 100.0);
        EXPECT_LE(d.badPixelShare, kMaxBadShare)
            << label << ": max " << d.maxAbs * 255.0 << "/255; images in " << writeFailureImages(testNameOf(method), image, naive);
    }
}

const auto kTestName = [](const auto& info) { return std::string(info.param.name); };
INSTANTIATE_TEST_SUITE_P(Corpus, FullSize, ::testing::ValuesIn(kFrames), kTestName);
INSTANTIATE_TEST_SUITE_P(CorpusShadowRays, FullSize, ::testing::ValuesIn(kShadowRayFrames), kTestName);

}  // namespace
}  // namespace ml::test
