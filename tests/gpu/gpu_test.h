// Shared set-up for GPU tests: a fresh EGL (llvmpipe) context per test with KHR_debug on;
// any GL error fails the test. Image helpers write the images and a diff on failure.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "renderer/context/gl_context.h"
#include "renderer/frame_renderer.h"
#include "renderer/image.h"
#include "renderer/image_compare.h"
#include "scenes/scene.h"

namespace ml::test {

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
    std::unique_ptr<GlContext> context_;
};

// Where tests may write files: $ML_TEST_TMP/<suite>.<test>/, created on demand.
std::filesystem::path testOutputDir();

// Writes test.png, reference.png and diff.png under testOutputDir()/name and returns that path.
std::string writeFailureImages(const std::string& name, const RgbaImage& test, const RgbaImage& reference);

// A built-in scene at test detail (0.25) and `count` lights from `seed` in its light volume,
// with radius defaultLightRadius x radiusScale.
struct TestScene {
    Scene scene;
    std::vector<PointLight> lights;
};
TestScene testScene(const std::string& name, std::uint32_t count, std::uint32_t seed, float radiusScale = 1.0f);

// A scene built in a test from quads: each a centre, two half-extent axes (the normal is
// u x v) and a base colour; one material per quad, drawn in the order given.
struct TestQuad {
    glm::vec3 center, u, v;
    glm::vec3 color{0.8f};
};
Scene quadScene(const std::vector<TestQuad>& quads);

// Frame settings for a scene at a small size, the scene's suggested camera, clip planes fitted.
FrameSettings smallFrame(const Scene& scene, int width, int height);
// The same from `pose`, the lights still (a scene built in a test has no suggested view).
FrameSettings smallFrame(const Scene& scene, const CameraPose& pose, int width, int height);

// A frame kept to compare others with: float and 8-bit output.
struct ReferenceFrame {
    FloatImage hdr;
    RgbaImage ldr;
};
// Renders animation frame `frame` with the renderer's current method (naive, as built) and keeps it.
ReferenceFrame renderReference(FrameRenderer& renderer, std::uint32_t frame);

// The accuracy contract against the reference frame (design.md): max error <= 1/255 on the
// 8-bit output and PSNR >= 50 dB on the float output. Expects both, prints the numbers under
// `label`, writes the images on failure; returns the float difference.
ImageDifference expectWithinContract(const std::string& label, const FrameRenderer& renderer, const ReferenceFrame& reference);

// Runs the manylights executable with `args` (a shell-quoted string) in `workingDir` (if not
// empty), behind `wrapper` if given (e.g. "xvfb-run -a", "env -u DISPLAY"); returns the exit
// status, output (stdout and stderr together) in `output`.
int runManylights(const std::string& args, std::string& output, const std::string& workingDir = "",
                  const std::string& wrapper = "");

}  // namespace ml::test
