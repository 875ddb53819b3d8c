// The compute lighting pass culls each cluster list against the 8x8 pixel block that reads it
// (glsl/deferred_lighting.comp). A light it drops adds exactly zero and the rest add in list
// order, so its frame must equal, bit for bit, the fragment resolve's, which walks the whole list
// for every pixel. Held on frames where blocks straddle many tiles and depth edges, where lights
// are small against their clusters (most of a list is dropped), where lights lie in and about
// the planes of the surfaces (the pass drops those behind every point of a block), and for every
// list the pass serves: exact, capped, per (cluster, normal bin), and the views that shade nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "gpu_test.h"

namespace ml::test {
namespace {

struct LightingCase {
    const char* name;
    const char* scene;
    int width, height;
    std::uint32_t tilesX;
    std::uint32_t lights;
    float radiusScale;
    AssignMode assign = AssignMode::Exact;
    bool normalCones = false;
    DebugView view = DebugView::Shaded;
};

void PrintTo(const LightingCase& c, std::ostream* os) { *os << c.name; }

class WorkgroupCulledLighting : public GpuTest, public ::testing::WithParamInterface<LightingCase> {};

// The deferred compute lighting's frame against the fragment resolve's, pixel by pixel.
void expectComputeEqualsPerPixelLoop(const Scene& scene, const std::vector<Light>& lights, const FrameSettings& s, const char* name) {
    FrameRenderer renderer(scene, lights, s);
    renderer.render(30);
    const FloatImage compute = renderer.readHdr();
    MethodSettings fragment = s.method;
    fragment.resolve = Resolve::Fragment;
    renderer.setMethod(fragment);
    renderer.render(30);
    const FloatImage perPixel = renderer.readHdr();

    ASSERT_EQ(compute.pixels.size(), perPixel.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < compute.pixels.size(); i += 3)
        if (std::memcmp(&compute.pixels[i], &perPixel.pixels[i], 3 * sizeof(float)) != 0) ++differing;
    const ImageDifference d = compareImages(compute, perPixel);
    std::printf("%s: %zu of %zu pixels differ (max %.3g)\n", name, differing, compute.pixels.size() / 3, d.maxAbs);
    EXPECT_EQ(differing, 0u) << name;
}

TEST_P(WorkgroupCulledLighting, EqualsThePerPixelLoopBitForBit) {
    const LightingCase c = GetParam();
    const TestScene t = testScene(c.scene, c.lights, 11, c.radiusScale);
    FrameSettings s = smallFrame(t.scene, c.width, c.height);
    s.method.kind = MethodKind::Deferred;
    s.method.clustering.grid.tilesX = c.tilesX;
    s.method.clustering.assign = c.assign;
    s.method.clustering.maxPerCluster = 4096;  // capped, but never full: which lights a full list keeps is a race
    s.method.clustering.normalCones = c.normalCones;
    s.method.clustering.view = c.view;
    expectComputeEqualsPerPixelLoop(t.scene, t.lights, s, c.name);
}

// Two tilted walls meeting at a corner, lit by lights in and about their planes: on each plane,
// 1 cm, 0.1 mm and 1 um in front and behind, and 20 cm behind. A light behind every point of a
// block adds nothing there and is dropped; one a rounding's width in front must not be (its N.L
// is positive at some pixel), nor one at a block that holds both walls.
class WorkgroupNormalBound : public GpuTest {};

TEST_F(WorkgroupNormalBound, LightsAboutTheWallsPlanesEqualThePerPixelLoop) {
    const glm::vec3 leftU = glm::normalize(glm::vec3(1.0f, 0.0f, 0.45f)), rightU = glm::normalize(glm::vec3(1.0f, 0.0f, -0.6f));
    const glm::vec3 up = glm::normalize(glm::vec3(0.0f, 1.0f, 0.15f));
    const TestQuad left{-1.0f * leftU, 1.0f * leftU, 1.5f * up, {0.8f, 0.7f, 0.6f}};
    const TestQuad right{1.0f * rightU, 1.0f * rightU, 1.5f * up, {0.6f, 0.7f, 0.8f}};
    const Scene scene = quadScene({left, right});
    std::vector<Light> lights;
    for (const TestQuad& q : {left, right}) {
        const glm::vec3 n = glm::normalize(glm::cross(q.u, q.v));
        for (float offset : {0.01f, 1e-4f, 1e-6f, 0.0f, -1e-6f, -1e-4f, -0.01f, -0.2f})
            for (int i = 0; i < 5; ++i)
                for (int j = 0; j < 5; ++j) {
                    const glm::vec3 p = q.center + q.u * (-0.9f + 0.45f * i) + q.v * (-0.9f + 0.45f * j) + n * offset;
                    lights.push_back(Light{p, 0.6f, {1.0f, 0.9f, 0.8f}});
                }
    }
    FrameSettings s = smallFrame(scene, CameraPose{{0.2f, 0.3f, 4.0f}, {0.0f, 0.0f, -0.3f}, 50.0f}, 160, 90);
    s.method.kind = MethodKind::Deferred;
    for (bool ggx : {true, false}) {
        setLightModel(s, LightModel{ggx ? Brdf::Ggx : Brdf::BlinnPhong});
        expectComputeEqualsPerPixelLoop(scene, lights, s, ggx ? "walls, GGX" : "walls, Blinn-Phong");
    }
}

INSTANTIATE_TEST_SUITE_P(
    Frames, WorkgroupCulledLighting,
    ::testing::Values(
        // Tiles of 5 pixels: every 8x8 block holds parts of several tiles and slices.
        LightingCase{"fine_tiles", "atrium", 160, 90, 32, 1024, 0.5f},
        // Small lights: a list is mostly lights that reach no pixel of a block.
        LightingCase{"small_lights", "atrium", 160, 90, 8, 4096, 0.2f},
        // 29-pixel tiles and a size no multiple of 8: blocks cut by tile and screen edges.
        LightingCase{"odd_size", "atrium", 203, 97, 7, 1024, 1.0f},
        LightingCase{"boxes", "boxes", 160, 90, 16, 1024, 0.5f},
        LightingCase{"tiny_viewport", "atrium", 3, 2, 1, 256, 1.0f},
        LightingCase{"capped", "atrium", 160, 90, 16, 1024, 0.5f, AssignMode::Capped},
        LightingCase{"normal_cones", "atrium", 160, 90, 16, 1024, 0.5f, AssignMode::Exact, true},
        LightingCase{"overflow_view", "atrium", 160, 90, 16, 1024, 0.5f, AssignMode::Capped, false, DebugView::Overflow},
        LightingCase{"light_count_view", "atrium", 160, 90, 16, 1024, 0.5f, AssignMode::Exact, false, DebugView::LightCount}),
    [](const ::testing::TestParamInfo<LightingCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ml::test
