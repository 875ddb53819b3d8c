// Golden-image regression: small frames of each scene and method compared with PNGs stored
// under tests/golden/, so an unintended change to any path shows even when all methods
// change together. After an intended change, regenerate them with: tools/update-golden
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "gpu_test.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

// Stated tolerances: the same Mesa gives identical images; these leave room for another
// llvmpipe version's rounding, not for a changed shading path.
constexpr double kMaxAbs = 4.0 / 255.0;
constexpr double kMeanAbs = 0.25 / 255.0;

struct GoldenCase {
    const char* scene;
    const char* method;
    std::string name() const { return std::string(scene) + "_" + method; }
};

class GoldenImage : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

TEST_P(GoldenImage, MatchesTheStoredFrame) {
    const GoldenCase c = GetParam();
    const TestScene t = testScene(c.scene, 64, 7);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.method.kind = parseMethod(c.method);
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(30);
    const RgbaImage image = renderer.readLdr();

    const std::filesystem::path golden = std::filesystem::path(ML_GOLDEN_DIR) / (c.name() + ".png");
    if (std::getenv("ML_UPDATE_GOLDEN")) {
        writePng(golden.string(), image);
        GTEST_SKIP() << "wrote " << golden;
    }
    ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing; run tools/update-golden";
    const RgbaImage reference = readPng(golden.string());
    const ImageDifference d = compareImages(image, reference);
    EXPECT_LE(d.maxAbs, kMaxAbs) << "images in " << writeFailureImages(c.name(), image, reference);
    EXPECT_LE(d.meanAbs, kMeanAbs) << "images in " << writeFailureImages(c.name(), image, reference);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenImage,
    ::testing::Values(GoldenCase{"atrium", "naive"}, GoldenCase{"atrium", "forward-plus"}, GoldenCase{"atrium", "deferred"},
                      GoldenCase{"atrium", "visibility"},
                      GoldenCase{"boxes", "naive"}, GoldenCase{"boxes", "forward-plus"}, GoldenCase{"boxes", "deferred"},
                      GoldenCase{"plane", "naive"}, GoldenCase{"plane", "forward-plus"}, GoldenCase{"plane", "deferred"}),
    [](const auto& info) {
        std::string name = info.param.name();
        for (char& ch : name) if (ch == '-') ch = '_';
        return name;
    });

}  // namespace
}  // namespace ml::test
