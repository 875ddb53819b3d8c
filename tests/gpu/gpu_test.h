// Shared set-up for GPU tests: a fresh EGL (llvmpipe) context per test with KHR_debug on;
// any GL error fails the test. Image helpers write the images and a diff on failure.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/context/gl_context.h"
#include "renderer/frame_renderer.h"
#include "renderer/image/image.h"
#include "renderer/image/image_compare.h"
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
// with radius defaultLightRadius x radiusScale; a share of them spots (cones of 20 to 60 degrees).
struct TestScene {
    Scene scene;
    std::vector<Light> lights;
};
TestScene testScene(const std::string& name, std::uint32_t count, std::uint32_t seed, float radiusScale = 1.0f,
                    float spotShare = 0.0f);

// A scene built in a test from quads: each a centre, two half-extent axes (the normal is
// u x v) and a base colour; one material per quad, drawn in the order given.
struct TestQuad {
    glm::vec3 center, u, v;
    glm::vec3 color{0.8f};
};
Scene quadScene(const std::vector<TestQuad>& quads);

// The accuracy contract of design.md against naive: max error on the 8-bit output, PSNR on the
// float output.
constexpr double kMaxAbs8Bit = 1.0 / 255.0 + 1e-9;
constexpr double kMinPsnrDb = 50.0;

// The clustered methods and deferred resolves the accuracy tests render.
struct ClusteredVariant {
    MethodKind kind;
    Resolve resolve;
    const char* name;
};
inline constexpr ClusteredVariant kClusteredVariants[] = {{MethodKind::ForwardPlus, Resolve::Compute, "forward-plus"},
                                                          {MethodKind::Deferred, Resolve::Compute, "deferred/compute"},
                                                          {MethodKind::Deferred, Resolve::Fragment, "deferred/fragment"},
                                                          {MethodKind::Visibility, Resolve::Compute, "visibility"}};

// Frame settings for a scene at a small size, the scene's suggested camera, clip planes fitted.
FrameSettings smallFrame(const Scene& scene, int width, int height);
// The same from `pose`, the lights still (a scene built in a test has no suggested view).
FrameSettings smallFrame(const Scene& scene, const CameraPose& pose, int width, int height);
// `model`, with the exposure and ambient render gives a built-in scene under its BRDF
// (app/frame_options.h, defaultLook): the seeds' unitless lights look as they did under
// Blinn-Phong, so the 8-bit tolerances and the golden images keep their meaning.
void setLightModel(FrameSettings& s, const LightModel& model);

// The reference frame a renderer's output is held to.
struct ReferenceFrame {
    FloatImage hdr;
    RgbaImage ldr;
};
ReferenceFrame readReference(const FrameRenderer& renderer);
// Renders animation frame `frame` with the renderer's current method (naive, as built) and keeps it.
ReferenceFrame renderReference(FrameRenderer& renderer, std::uint32_t frame);

// Compares the renderer's current frame with the reference, prints one line ("label max8 ...
// psnr ..."), and fails the test (writing the images under `imageName`) when the frame breaks
// the contract (imageName, or the label when empty). Returns the float-output difference.
ImageDifference expectWithinContract(const FrameRenderer& renderer, const ReferenceFrame& reference, const std::string& label,
                                     const std::string& imageName = "");
// Renders frame 0 with the renderer's current method (naive, as built), then holds each of
// kClusteredVariants to it (expectWithinContract, images named label_kind_resolve). Returns
// naive's frame; the renderer is left on the last variant.
ReferenceFrame expectClusteredVariantsMatchNaive(FrameRenderer& renderer, const std::string& label, std::uint32_t frame = 0);

// A test scene (seed 5; radius halved from 1024 lights up) rendered by naive forward at 160x90
// on one frame: the reference the methods rendered by `renderer` next are held to.
struct NaiveReferenceScene {
    NaiveReferenceScene(const char* scene, std::uint32_t lights, std::uint32_t frameIndex = 45);
    TestScene test;
    FrameRenderer renderer;
    std::uint32_t frame;
    ReferenceFrame reference;
};

// One clustered method's difference from naive on the same frame.
struct MethodError {
    std::string method;
    double max8Bit = 0.0;  // max abs error of the 8-bit output, in units of 1/255
    double psnrDb = 0.0;   // on the float output
    std::uint64_t droppedReferences = 0;
    std::uint64_t listEntries = 0;
    double emptyClusterShare = 0.0;
};

// Renders frame `frame` with naive, then with Forward+, clustered deferred and the visibility
// buffer (the clustering of s.method), and returns each one's error against naive.
std::vector<MethodError> clusteredErrors(const Scene& scene, const std::vector<Light>& lights, FrameSettings s,
                                         std::uint32_t frame = 0);
// Every method within the accuracy contract (design.md): 1/255 on 8 bits, 50 dB on floats.
void expectWithinContract(const std::vector<MethodError>& errors, const std::string& label);

// A parameter as a test name CTest lists readably: "--size 0x10" -> "size_0x10",
// "forward-plus" -> "forward_plus" (GoogleTest allows letters, digits and '_' only).
std::string testNameOf(const std::string& text);

// Runs the manylights executable with `args` (a shell-quoted string) in `workingDir` (if not
// empty), behind `wrapper` if given (e.g. "xvfb-run -a", "env -u DISPLAY"); returns the exit
// status, output (stdout and stderr together) in `output`.
int runManylights(const std::string& args, std::string& output, const std::string& workingDir = "",
                  const std::string& wrapper = "");

// Whether xvfb-run is installed: the window tests (`manylights view`) need an X server.
bool haveXvfb();

// Runs `manylights view <args>` on a private X server. -a takes the first free display from
// -n on; starting the search from this process's id keeps tests that CTest runs side by side
// from racing for the same number.
int runViewUnderXvfb(const std::string& args, std::string& output);

#define REQUIRE_XVFB() \
    if (!::ml::test::haveXvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb): the window tests need an X server"

}  // namespace ml::test
