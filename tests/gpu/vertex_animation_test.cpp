// The vertex animation pre-pass (glsl/animate_vertices.comp) on llvmpipe: the posed vertices it
// writes into the scene's buffers equal the CPU mirror (scenes/animation_pose.h), an animated
// file renders differently at two times and byte for byte the same at one time, and a static
// scene (or --animation off) has no such pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "gpu_test.h"
#include "renderer/gl/gl_api.h"
#include "scenes/animation_pose.h"
#include "scenes/scene_library.h"
#include "tests/scenes/gltf_animation_files.h"

namespace ml::test {
namespace {

using namespace gltf_test;

class VertexAnimation : public GpuTest {};

const std::vector<Light> kLights = {Light{{0.5f, 0.5f, 1.5f}, 6.0f, {2.0f, 2.0f, 2.0f}},
                                    Light{{-0.8f, 0.3f, 1.0f}, 4.0f, {1.0f, 0.7f, 0.5f}}};

Scene cesiumMan() {
    const std::string path = std::string(ML_CORPUS_DIR) + "/khronos/CesiumMan/glTF/CesiumMan.gltf";
    if (!std::filesystem::exists(path)) return {};
    std::vector<std::string> warnings;
    return loadScene(SceneRequest{path, 1.0f}, warnings);
}

// Within 1e-5 of the CPU's value, relative to its size (1 at least).
void expectClose(const glm::vec3& gpu, const glm::vec3& cpu, const char* what, std::size_t vertex, std::size_t& misses) {
    const float tolerance = 1e-5f * std::max(1.0f, glm::length(cpu));
    if (glm::length(gpu - cpu) <= tolerance) return;
    if (++misses <= 3)
        ADD_FAILURE() << what << " of vertex " << vertex << ": GPU (" << gpu.x << ", " << gpu.y << ", " << gpu.z << "), CPU (" << cpu.x
                      << ", " << cpu.y << ", " << cpu.z << ")";
}

// Renders `scene` at `seconds` with its first clip and holds the GPU's posed vertices to the CPU's.
void expectPrePassEqualsCpu(const Scene& scene, double seconds) {
    ASSERT_NE(scene.animation, nullptr);
    FrameSettings s = smallFrame(scene, CameraPose{{0, 1, 4}, {0, 0.5f, 0}, 60.0f}, 64, 36);
    s.method.kind = MethodKind::Naive;
    s.sceneAnimation.startSeconds = seconds;
    FrameRenderer renderer(scene, kLights, s);
    ASSERT_NE(renderer.vertexAnimation(), nullptr);
    renderer.render(0);
    const std::vector<Vertex> gpu = renderer.scene().downloadVertices();
    Scene cpu = scene;
    applyPose(cpu, poseAt(*scene.animation, sceneClip(scene, 0), seconds));
    ASSERT_EQ(gpu.size(), cpu.vertices.size());
    std::size_t misses = 0;
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        expectClose(gpu[i].position, cpu.vertices[i].position, "position", i, misses);
        expectClose(gpu[i].normal, cpu.vertices[i].normal, "normal", i, misses);
    }
    const std::vector<glm::vec4> tangents = renderer.scene().downloadTangents();
    for (std::size_t i = 0; i < tangents.size(); ++i) {
        expectClose(glm::vec3(tangents[i]), glm::vec3(cpu.tangents[i]), "tangent", i, misses);
        if (tangents[i].w != cpu.tangents[i].w && ++misses <= 3) ADD_FAILURE() << "tangent w of vertex " << i;
    }
    EXPECT_EQ(misses, 0u);
}

TEST_F(VertexAnimation, SkinnedStripOnTheGpuEqualsTheCpu) {
    const Scene scene = load(skinnedStrip().g.writeGlb(testDir(), "skinned-strip"));
    for (double t : {0.0, 0.3, 0.75}) expectPrePassEqualsCpu(scene, t);
}

TEST_F(VertexAnimation, MorphedQuadOnTheGpuEqualsTheCpu) {
    const Scene scene = load(morphedQuad().writeGlb(testDir(), "morphed-quad"));
    for (double t : {0.0, 1.0, 1.7}) expectPrePassEqualsCpu(scene, t);
}

TEST_F(VertexAnimation, AnimatedCubeOnTheGpuEqualsTheCpu) {
    const Scene scene = load(animatedCube().writeGlb(testDir(), "animated-cube"));
    expectPrePassEqualsCpu(scene, 0.6);
}

TEST_F(VertexAnimation, CesiumManOnTheGpuEqualsTheCpu) {
    const Scene scene = cesiumMan();
    if (scene.vertices.empty()) GTEST_SKIP() << "no CesiumMan in " << ML_CORPUS_DIR;
    for (double t : {0.5, 1.25}) expectPrePassEqualsCpu(scene, t);
    // The pre-pass alone on llvmpipe (printed; tests assert no timing).
    FrameSettings s = smallFrame(scene, 64, 36);
    FrameRenderer renderer(scene, kLights, s);
    renderer.render(0);
    VertexAnimationPass pass(scene, 0, renderer.scene().hasTangentStream());
    constexpr int kRuns = 20;
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    for (int i = 1; i <= kRuns; ++i) pass.run(renderer.scene(), 0.01 * i);
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / kRuns;
    std::printf("CesiumMan vertex animation pre-pass: %zu vertices, %.3f ms a frame (llvmpipe, CPU pose and upload included)\n",
                pass.vertexCount(), ms);
}

// A normal-mapped square with TANGENT, mirrored by its node (scale -1 in x) and turned about +y
// from 0 to 90 degrees: tangents turn with it, their w flipped by the mirror.
Scene mirroredNormalMappedSquare() {
    Gltf g;
    const std::vector<std::uint8_t> pixel = {128, 128, 255, 255};
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, pixel))}});
    g.add("textures", {{"source", 0}});
    const int material = g.add("materials", {{"normalTexture", {{"index", 0}}}});
    const std::vector<float> tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
    const int tangent = floats(g, tangents, "VEC4", 4);
    const int mesh = g.mesh({square(g, 0.0f, 0.5f, material, {{"TANGENT", tangent}})});
    g.scene({g.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}})});
    const float h = std::sqrt(0.5f);
    addAnimation(g, "Turn", 0, "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, h, 0, h}, "VEC4", 4);
    return load(g.writeGlb(testDir(), "mirrored-normal-mapped"));
}

TEST_F(VertexAnimation, TangentsOfAMirroredTurningSquareOnTheGpuEqualTheCpu) {
    const Scene scene = mirroredNormalMappedSquare();
    ASSERT_FALSE(scene.tangents.empty());
    EXPECT_EQ(scene.tangents[0].w, -1.0f);  // the mirror, at rest
    for (double t : {0.0, 0.4}) expectPrePassEqualsCpu(scene, t);
}

RgbaImage renderAt(const Scene& scene, double seconds, MethodKind method = MethodKind::Deferred) {
    FrameSettings s = smallFrame(scene, CameraPose{{1, 0.4f, 3.5f}, {1, 0.4f, 0}, 60.0f}, 160, 90);
    s.method.kind = method;
    s.sceneAnimation.startSeconds = seconds;
    FrameRenderer renderer(scene, kLights, s);
    renderer.render(0);
    return renderer.readLdr();
}

TEST_F(VertexAnimation, DiffersBetweenTimesAndRepeatsAtOne) {
    const Scene scene = load(skinnedStrip().g.writeGlb(testDir(), "skinned-strip"));
    const RgbaImage early = renderAt(scene, 0.1), late = renderAt(scene, 0.8), again = renderAt(scene, 0.1);
    EXPECT_GT(compareImages(late, early).badPixelShare, 0.01);
    EXPECT_EQ(again.pixels, early.pixels);
    // One renderer going back to a time it showed before: the same bytes (a frame is a pure function of time).
    FrameSettings s = smallFrame(scene, CameraPose{{1, 0.4f, 3.5f}, {1, 0.4f, 0}, 60.0f}, 160, 90);
    s.sceneAnimation.startSeconds = 0.1;
    FrameRenderer renderer(scene, kLights, s);
    renderer.render(42);
    renderer.render(0);
    EXPECT_EQ(renderer.readLdr().pixels, early.pixels);
}

// Every method against naive on the bent strip, as the corpus holds them (99.99 % within 1/255).
TEST_F(VertexAnimation, EveryMethodMatchesNaiveOnAPosedFrame) {
    const Scene scene = load(skinnedStrip().g.writeGlb(testDir(), "skinned-strip"));
    const RgbaImage naive = renderAt(scene, 0.6, MethodKind::Naive);
    for (MethodKind kind : {MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        const RgbaImage image = renderAt(scene, 0.6, kind);
        const ImageDifference d = compareImages(image, naive);
        EXPECT_LE(d.badPixelShare, 1e-4) << methodName(kind) << ": max " << d.maxAbs * 255.0 << "/255; images in "
                                         << writeFailureImages(methodName(kind), image, naive);
    }
}

// Transparent ranges blend back to front by their boxes: a glass cube sliding past a glass square
// changes their order as it passes (the boxes are refitted to the posed vertices each frame).
TEST_F(VertexAnimation, TransparentOrderFollowsTheAnimation) {
    Gltf g = animatedCube();
    const int cubeGlass = colourMaterial(g, {0.2f, 0.4f, 1.0f, 0.5f}, "BLEND");
    const int squareGlass = colourMaterial(g, {1.0f, 0.4f, 0.2f, 0.5f}, "BLEND");
    g.doc["meshes"][0]["primitives"][0]["material"] = cubeGlass;
    const int square = g.mesh({gltf_test::square(g, 0.0f, 0.5f, squareGlass)});
    g.doc["scenes"][0]["nodes"].push_back(g.node({{"mesh", square}, {"translation", {2, 0, 0}}}));
    const Scene scene = load(g.writeGlb(testDir(), "sliding-glass"));
    const glm::vec3 eye(10.0f, 0.0f, 0.0f);
    const auto orderAt = [&](double seconds) {
        FrameSettings s = smallFrame(scene, CameraPose{eye, {0, 0, 0}, 60.0f}, 32, 18);
        s.sceneAnimation.startSeconds = seconds;
        FrameRenderer renderer(scene, kLights, s);
        renderer.render(0);
        return renderer.scene().transparentOrder(eye);
    };
    ASSERT_EQ(scene.animation->meshes.size(), 1u);  // the cube moves, the square does not
    const std::vector<std::uint32_t> before = orderAt(0.0), after = orderAt(1.9);  // the cube at x = 0, then 3.8
    ASSERT_EQ(before.size(), 2u);
    EXPECT_EQ(after[0], before[1]);
    EXPECT_EQ(after[1], before[0]);
}

TEST_F(VertexAnimation, StaticScenesAndAnimationOffHaveNoPass) {
    const TestScene boxes = testScene("boxes", 8, 1);
    FrameSettings s = smallFrame(boxes.scene, 32, 18);
    s.timing = true;
    s.clock = TimingClock::WallClockAfterFinish;
    FrameRenderer renderer(boxes.scene, boxes.lights, s);
    EXPECT_EQ(renderer.vertexAnimation(), nullptr);
    const std::vector<PassTime> passes = renderer.render(0);
    EXPECT_FALSE(passes.empty());
    for (const PassTime& pass : passes) EXPECT_NE(pass.name, "scene.animate");

    const Scene strip = load(skinnedStrip().g.writeGlb(testDir(), "skinned-strip"));
    FrameSettings off = smallFrame(strip, 32, 18);
    off.sceneAnimation.clip = std::nullopt;
    EXPECT_EQ(FrameRenderer(strip, kLights, off).vertexAnimation(), nullptr);
}

}  // namespace
}  // namespace ml::test

namespace ml::test {
namespace {

using namespace gltf_test;

// `render` on an animated file: a sequence's frame is the single frame of the same number, and a
// clip the file does not have is one line naming it and the clips there are.
TEST(VertexAnimationCommand, SequencesRepeatSingleFramesAndBadClipsAreOneLine) {
    const fs::path dir = testDir();
    const std::string file = skinnedStrip().g.writeGlb(dir, "skinned-strip").string();
    const std::string common = "render --scene " + file + " --size 96x54 --lights 16 --scene-time 0.25 ";
    std::string output;
    ASSERT_EQ(runManylights(common + "--frames 0..2 --out seq_%d.png --overwrite", output, dir.string()), 0) << output;
    ASSERT_EQ(runManylights(common + "--frames 2 --out single.png", output, dir.string()), 0) << output;
    EXPECT_EQ(readPng((dir / "seq_2.png").string()).pixels, readPng((dir / "single.png").string()).pixels);
    EXPECT_NE(readPng((dir / "seq_0.png").string()).pixels, readPng((dir / "seq_2.png").string()).pixels);

    for (const auto& [flag, culprits] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"--animation Walk", {"--animation 'Walk'", "1 clip: 0 'Bend'"}},
             {"--animation 3", {"--animation '3'", "0 'Bend'"}},
             {"--scene-time nan", {"--scene-time"}}}) {
        const int status = runManylights("render --out /dev/null --scene " + file + " " + flag, output, dir.string());
        EXPECT_NE(status, 0) << flag;
        for (const std::string& culprit : culprits) EXPECT_NE(output.find(culprit), std::string::npos) << flag << ": " << output;
        EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    }
    EXPECT_NE(runManylights("render --out /dev/null --scene boxes --animation 0", output), 0);
    EXPECT_NE(output.find("the scene has no animation clips"), std::string::npos) << output;
    // By name and off work.
    EXPECT_EQ(runManylights(common + "--animation Bend --out named.png", output, dir.string()), 0) << output;
    EXPECT_EQ(runManylights(common + "--animation off --out off.png", output, dir.string()), 0) << output;
}

}  // namespace
}  // namespace ml::test
