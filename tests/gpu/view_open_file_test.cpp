// `manylights view` opening another file without restarting (GLFW's drop callback, exercised
// through --drop), and following `--camera orbit:` as render does. Under xvfb-run (Mesa llvmpipe
// through GLX); skipped, in one line, where xvfb-run or the corpus (../shared/corpus) is absent.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "gpu_test.h"

namespace ml::test {
namespace {

constexpr double kMaxAbs = 1.0 / 255.0 + 1e-9;  // GLX against EGL, same Mesa: one step of slack

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

int runViewUnderXvfb(const std::string& args, std::string& output) {
    const std::string server = std::to_string(100 + getpid() % 800);
    return runManylights("view " + args, output, "", "xvfb-run -a -n " + server + " -s '-screen 0 1024x768x24'");
}

TEST(ViewOpenFile, ADroppedFileShowsWhatRenderShowsOfIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb): the window tests need an X server";
    const std::filesystem::path file = std::filesystem::path(ML_CORPUS_DIR) / "khronos/BoxTexturedNonPowerOfTwo/glTF/BoxTexturedNonPowerOfTwo.gltf";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "third-party corpus not found at " << ML_CORPUS_DIR;
    const std::string dir = testOutputDir().string();
    const std::string common = " --size 160x90 --lights 32 --frames 3";
    std::string output;
    // Starts on the built-in boxes; the file arrives through the drop callback before frame 1.
    ASSERT_EQ(runViewUnderXvfb("--scene boxes --detail 0.5" + common + " --drop " + file.string() + " --screenshot " + dir +
                                   "/dropped.png",
                               output),
              0)
        << output;
    EXPECT_NE(output.find("opened " + file.string()), std::string::npos) << output;
    EXPECT_NE(output.find("camera: framed from the front"), std::string::npos) << "the file's own defaults:\n" << output;
    ASSERT_EQ(runManylights("render --scene " + file.string() + common + " --out " + dir + "/rendered.png", output), 0) << output;
    const RgbaImage view = readPng(dir + "/dropped.png");
    const RgbaImage render = readPng(dir + "/rendered.png");
    EXPECT_LE(compareImages(view, render).maxAbs, kMaxAbs) << writeFailureImages("dropped", view, render);

    // A file that cannot be opened leaves the scene as it was and says why.
    ASSERT_EQ(runViewUnderXvfb("--scene boxes --detail 0.5" + common + " --drop /nonexistent.glb --screenshot " + dir +
                                   "/kept.png",
                               output),
              0)
        << output;
    EXPECT_NE(output.find("could not open /nonexistent.glb"), std::string::npos) << output;
}

TEST(ViewOpenFile, OrbitIsFollowedAsRenderFollowsIt) {
    if (!haveXvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb): the window tests need an X server";
    const std::string dir = testOutputDir().string();
    const std::string common = "--scene boxes --detail 0.5 --size 160x90 --lights 16 --camera orbit:frames=8 --frames 3";
    std::string output;
    ASSERT_EQ(runViewUnderXvfb(common + " --screenshot " + dir + "/orbit_view.png", output), 0) << output;
    ASSERT_EQ(runManylights("render " + common + " --out " + dir + "/orbit_render.png", output), 0) << output;
    const RgbaImage view = readPng(dir + "/orbit_view.png");
    const RgbaImage render = readPng(dir + "/orbit_render.png");
    EXPECT_LE(compareImages(view, render).maxAbs, kMaxAbs) << writeFailureImages("orbit", view, render);
}

}  // namespace
}  // namespace ml::test
