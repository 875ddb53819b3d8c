// `manylights view` in a real window: under xvfb-run (Mesa llvmpipe through GLX) its scripted
// screenshots are compared with the same frame from `render` (EGL). Skipped, with a message,
// where xvfb-run is missing (Debian package xvfb).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "gpu_test.h"

namespace ml::test {
namespace {

// Same Mesa, same shaders: GLX and EGL contexts give the same pixels. One step of slack for a
// driver that rounds a blit differently, none for a different frame.
constexpr double kMaxAbs = 1.0 / 255.0 + 1e-9;

TEST(ViewCommand, ScreenshotMatchesRenderForEveryMethod) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    for (const std::string& method : methodNames()) {
        const std::string common = "--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3 --method " + method;
        std::string output;
        ASSERT_EQ(runViewUnderXvfb(common + " --frames 12 --screenshot " + dir + "/view_" + method + ".png", output), 0)
            << output;
        EXPECT_NE(output.find("frame 12"), std::string::npos) << output;
        ASSERT_EQ(runManylights("render " + common + " --frames 12 --out " + dir + "/render_" + method + ".png", output), 0)
            << output;
        const RgbaImage view = readPng(dir + "/view_" + method + ".png");
        const RgbaImage render = readPng(dir + "/render_" + method + ".png");
        ASSERT_EQ(view.width, 160);
        ASSERT_EQ(view.height, 90);
        const ImageDifference d = compareImages(view, render);
        EXPECT_LE(d.maxAbs, kMaxAbs) << method << ": images in " << writeFailureImages(method, view, render);
    }
    // The comparison can tell frames apart: the lights drift, so frame 11 is not frame 12.
    std::string output;
    const std::string common = "--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3 --method naive";
    ASSERT_EQ(runManylights("render " + common + " --frames 11 --out " + dir + "/render_11.png", output), 0) << output;
    EXPECT_GT(compareImages(readPng(dir + "/view_naive.png"), readPng(dir + "/render_11.png")).maxAbs, kMaxAbs);
}

// --msaa in the window: the same resolved frame as `render --msaa`.
TEST(ViewCommand, MsaaScreenshotMatchesRender) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    const std::string common = "--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3 --method forward-plus --msaa 4";
    std::string output;
    ASSERT_EQ(runViewUnderXvfb(common + " --frames 12 --screenshot " + dir + "/view.png", output), 0) << output;
    ASSERT_EQ(runManylights("render " + common + " --frames 12 --out " + dir + "/render.png", output), 0) << output;
    const RgbaImage view = readPng(dir + "/view.png");
    const RgbaImage render = readPng(dir + "/render.png");
    EXPECT_LE(compareImages(view, render).maxAbs, kMaxAbs) << "images in " << writeFailureImages("msaa", view, render);
}

// The panel's BRDF and cut-off controls, set by --panel as if changed there before frame 1: the
// lights are rebuilt by render's rule (radii from E) and the exposure and ambient follow the BRDF,
// so the frame is the one `render` gives with the same flags.
TEST(ViewCommand, PanelBrdfAndCutoffGiveTheFrameRenderGives) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    const std::string common = "--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3 --method deferred --frames 12";
    struct Case {
        const char* name;
        std::string start, panel, render;
    };
    for (const Case& c : {Case{"stochastic", "", "brdf=blinn-phong,cutoff=stochastic,light-cutoff=0.05",
                               "--brdf blinn-phong --cutoff stochastic --light-cutoff 0.05"},
                          Case{"back", "--brdf blinn-phong --light-cutoff 0.1", "brdf=ggx,cutoff=radius", ""}}) {
        std::string output;
        ASSERT_EQ(runViewUnderXvfb(common + " " + c.start + " --panel " + c.panel + " --screenshot " + dir + "/panel_" + c.name + ".png",
                                   output),
                  0)
            << output;
        ASSERT_EQ(runManylights("render " + common + " " + c.render + " --out " + dir + "/render_" + c.name + ".png", output), 0)
            << output;
        ASSERT_EQ(runManylights("render " + common + " " + c.start + " --out " + dir + "/start_" + c.name + ".png", output), 0)
            << output;
        const RgbaImage view = readPng(dir + "/panel_" + std::string(c.name) + ".png");
        const RgbaImage render = readPng(dir + "/render_" + std::string(c.name) + ".png");
        EXPECT_LE(compareImages(view, render).maxAbs, kMaxAbs) << c.name << ": images in " << writeFailureImages(c.name, view, render);
        // The controls changed the frame: it is not the one the view started with.
        EXPECT_GT(compareImages(view, readPng(dir + "/start_" + std::string(c.name) + ".png")).maxAbs, 8.0 / 255.0) << c.name;
    }
    // What the panel refuses, it refuses in one line: no cluster holds untruncated lights.
    std::string refused;
    EXPECT_NE(runViewUnderXvfb(common + " --panel cutoff=none", refused), 0);
    EXPECT_NE(refused.find("--cutoff none: needs --method naive"), std::string::npos) << refused;
}

// The panel's light sum, set by --panel: every method, naive included, then adds its lights in
// 64-bit fixed point over unsorted lists, and the frame is the one `render --light-sum fixed` gives.
// The two sums differ in the float output's last bits, which the 8-bit screenshot rarely shows, so
// the pass times (--time) show the switch: the clustered methods' lists are no longer sorted.
TEST(ViewCommand, PanelLightSumGivesTheFrameRenderGives) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    for (const char* method : {"naive", "visibility"}) {
        const std::string common = std::string("--scene boxes --detail 0.5 --size 160x90 --lights 64 --seed 3 --frames 3 --method ") + method;
        std::string output;
        const std::string view = dir + "/panel_fixed_" + method + ".png", render = dir + "/render_fixed_" + method + ".png";
        ASSERT_EQ(runViewUnderXvfb(common + " --time --panel light-sum=fixed --screenshot " + view, output), 0) << output;
        EXPECT_EQ(output.find("assign.sort"), std::string::npos) << method << ": fixed sums need no sort\n" << output;
        ASSERT_EQ(runManylights("render " + common + " --light-sum fixed --out " + render, output), 0) << output;
        EXPECT_EQ(compareImages(readPng(view), readPng(render)).maxAbs, 0.0) << method << ": images in " << dir;
    }
    std::string sorted;
    ASSERT_EQ(runViewUnderXvfb("--scene boxes --detail 0.5 --size 160x90 --lights 64 --frames 3 --method visibility --time --panel light-sum=float", sorted), 0)
        << sorted;
    EXPECT_NE(sorted.find("assign.sort"), std::string::npos) << "float sums sort the lists\n" << sorted;
    std::string refused;
    EXPECT_NE(runViewUnderXvfb("--scene boxes --detail 0.5 --size 160x90 --frames 1 --panel light-sum=double", refused), 0);
    EXPECT_NE(refused.find("--panel 'light-sum=double'"), std::string::npos) << refused;
}

TEST(ViewCommand, MsaaForAOneSampleMethodIsRefusedBeforeAWindowOpens) {
    std::string output;
    EXPECT_NE(runManylights("view --scene boxes --detail 0.25 --method visibility --msaa 4", output, "",
                            "env -u DISPLAY -u WAYLAND_DISPLAY"),
              0);
    EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    EXPECT_NE(output.find("one sample per pixel"), std::string::npos) << output;
}

// On llvmpipe the view starts at a reduced internal resolution, says so in one line, and still
// fills the window; --render-scale 1 turns it off.
TEST(ViewCommand, RenderScaleEngagesOnASoftwareRenderer) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    const std::string common = "--scene boxes --detail 0.5 --size 640x360 --lights 32 --frames 2 --hide-panel";
    std::string output;
    ASSERT_EQ(runViewUnderXvfb(common + " --screenshot-window " + dir + "/scaled_window.png", output), 0) << output;
    EXPECT_NE(output.find("software GL renderer: drawn at 0.50 scale (320x180, 8 tiles across)"), std::string::npos) << output;
    const RgbaImage window = readPng(dir + "/scaled_window.png");
    EXPECT_EQ(window.width, 640);
    EXPECT_EQ(window.height, 360);
    ASSERT_EQ(runViewUnderXvfb(common + " --render-scale 1 --screenshot-window " + dir + "/full_window.png", output), 0) << output;
    EXPECT_EQ(output.find("software GL renderer"), std::string::npos) << output;
    // An explicit scale applies to the renderer's own image too.
    ASSERT_EQ(runViewUnderXvfb(common + " --render-scale 0.25 --screenshot " + dir + "/quarter.png", output), 0) << output;
    EXPECT_EQ(readPng(dir + "/quarter.png").width, 160);
    EXPECT_NE(runViewUnderXvfb(common + " --render-scale 2", output), 0);
    EXPECT_NE(output.find("--render-scale"), std::string::npos) << output;
}

TEST(ViewCommand, CameraPathIsFollowedFrameByFrame) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    {
        std::ofstream path(dir + "/path.json");
        path << R"({"keyframes": [
            {"frame": 0,  "eye": [8, 8, 14],  "target": [0, 1, 0], "fovy": 50},
            {"frame": 10, "eye": [12, 6, 10], "target": [2, 1, 0], "fovy": 70}]})";
    }
    const std::string common = "--scene boxes --detail 0.5 --size 128x96 --lights 48 --seed 5 --method forward-plus";
    std::string output;
    ASSERT_EQ(runViewUnderXvfb(common + " --frames 5 --camera-path " + dir + "/path.json --screenshot " + dir + "/view.png",
                               output),
              0)
        << output;
    // Halfway between the keyframes, exactly representable.
    ASSERT_EQ(runManylights("render " + common + " --frames 5 --camera 10,7,12,1,1,0,60 --out " + dir + "/render.png", output), 0)
        << output;
    const RgbaImage view = readPng(dir + "/view.png");
    const RgbaImage render = readPng(dir + "/render.png");
    const ImageDifference d = compareImages(view, render);
    EXPECT_LE(d.maxAbs, kMaxAbs) << "images in " << writeFailureImages("path", view, render);
}

TEST(ViewCommand, WindowScreenshotShowsThePanelOverTheSameFrame) {
    REQUIRE_XVFB();
    const std::string dir = testOutputDir().string();
    std::string output;
    ASSERT_EQ(runViewUnderXvfb("--scene boxes --detail 0.5 --size 1024x640 --lights 32 --method deferred --frames 2"
                               " --screenshot " + dir + "/scene.png --screenshot-window " + dir + "/window.png",
                               output),
              0)
        << output;
    EXPECT_NE(output.find("panel shown"), std::string::npos) << output;
    const RgbaImage scene = readPng(dir + "/scene.png");
    const RgbaImage window = readPng(dir + "/window.png");
    ASSERT_EQ(window.width, scene.width);
    ASSERT_EQ(window.height, scene.height);
    // The controls sit at the top left (from 10, 10), under 560 pixels tall, the statistics at
    // the top right, from x = 630, a line per pass (deferred's reach y = 586 since its depth
    // pre-pass); below the controls and left of the statistics the window is the scene's image.
    std::size_t panelDiffers = 0, restDiffers = 0, panelPixels = 0, restPixels = 0;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            const bool differs = !std::equal(scene.at(x, y), scene.at(x, y) + 3, window.at(x, y));
            if (x >= 20 && x < 380 && y >= 20 && y < 120) {
                ++panelPixels;
                panelDiffers += differs;
            } else if (y >= 580 && x < 620) {
                ++restPixels;
                restDiffers += differs;
            }
        }
    }
    EXPECT_GT(panelDiffers, panelPixels / 2) << "no panel in " << dir << "/window.png";
    EXPECT_EQ(restDiffers, 0u) << "outside the panel the window should show the scene image: " << dir;
}

TEST(ViewCommand, WithoutADisplaySaysSoInOneLineAndPointsToRender) {
    std::string output;
    const int status = runManylights("view --scene boxes --detail 0.25", output, "", "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_NE(status, 0);
    EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    EXPECT_NE(output.find("manylights render"), std::string::npos) << output;
}

TEST(ViewCommand, ABadCameraPathIsReportedBeforeAWindowOpens) {
    const std::string dir = testOutputDir().string();
    {
        std::ofstream path(dir + "/bad.json");
        path << R"({"keyframes": [{"frame": 0, "eye": [0, 0, 5]}]})";
    }
    std::string output;
    // No display needed: the file is read first.
    EXPECT_NE(runManylights("view --scene boxes --detail 0.25 --camera-path " + dir + "/bad.json", output, "",
                            "env -u DISPLAY -u WAYLAND_DISPLAY"),
              0);
    EXPECT_NE(output.find("keyframe 0: missing \"target\""), std::string::npos) << output;
}

// Another file without restarting: --drop hands it to GLFW's drop callback, as a file dropped
// on the window arrives.
TEST(ViewCommand, ADroppedFileShowsWhatRenderShowsOfIt) {
    REQUIRE_XVFB();
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

TEST(ViewCommand, OrbitIsFollowedAsRenderFollowsIt) {
    REQUIRE_XVFB();
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
