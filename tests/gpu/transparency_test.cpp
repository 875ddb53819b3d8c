// Transparent surfaces (glTF alphaMode BLEND) on files the tests write: what the blend shows
// (a half-transparent quad over a wall is both; overlapping panes blend back to front in the
// documented order, from either side), and every clustered method held to naive with
// transparency on, including a pane nearer than every opaque surface (outside the depth range
// the opaque depth buffer alone would fit), with --active-only, normal cones, z-binning and each
// --cull test: the places where the light lists only know the opaque samples.
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/scene/material_features.h"
#include "tests/gpu/gpu_test.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;
using test::GpuTest;

constexpr int kWidth = 160, kHeight = 90;
const CameraPose kBackView{{0.0f, 0.0f, -4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f};
const std::vector<Light> kOneLight{{{0.3f, 0.2f, 3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}};

// A rectangle facing +z at `center`, half extents (hx, hy).
json rect(Gltf& g, glm::vec3 center, float hx, float hy, int material) {
    const glm::vec3 c = center;
    return primitive({{"POSITION", g.vec3({{c.x - hx, c.y - hy, c.z}, {c.x + hx, c.y - hy, c.z}, {c.x + hx, c.y + hy, c.z}, {c.x - hx, c.y + hy, c.z}})},
                      {"NORMAL", g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}})}},
                     g.indices({0, 1, 2, 0, 2, 3}), material);
}

FloatImage renderNaive(const Scene& scene, const std::vector<Light>& lights, const CameraPose& pose) {
    FrameRenderer renderer(scene, lights, test::smallFrame(scene, pose, kWidth, kHeight));
    renderer.render(0);
    return renderer.readHdr();
}

glm::vec3 pixel(const FloatImage& image, int x, int y) {
    const float* p = &image.pixels[(std::size_t(y) * image.width + x) * 3];
    return {p[0], p[1], p[2]};
}

void expectColourNear(glm::vec3 actual, glm::vec3 expected, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], 1e-4f + 1e-3f * std::abs(expected[c])) << what << " channel " << c;
}

// Holds Forward+, deferred and the visibility buffer to naive with the clustering given.
void expectMethodsMatchNaive(const Scene& scene, const std::vector<Light>& lights, const CameraPose& pose,
                             const ClusteringSettings& clustering, const std::string& label) {
    FrameSettings s = test::smallFrame(scene, pose, kWidth, kHeight);
    s.method.clustering = clustering;
    test::expectWithinContract(test::clusteredErrors(scene, lights, s), label);
}

class Transparency : public GpuTest {};

// A red quad at alpha 0.5 over a green wall: where it covers the wall, the frame is exactly half
// the opaque quad's colour and half the bare wall's, in naive and every clustered method.
TEST_F(Transparency, HalfTransparentQuadShowsTheQuadAndTheWallBehind) {
    const auto scene = [&](const char* alphaMode, bool withQuad) {
        Gltf g;
        const int wall = colourMaterial(g, {0.1f, 0.8f, 0.1f, 1.0f}, "OPAQUE");
        const int quad = colourMaterial(g, {0.8f, 0.1f, 0.1f, 0.5f}, alphaMode);
        std::vector<json> prims{square(g, 0.0f, 2.5f, wall)};
        if (withQuad) prims.push_back(square(g, 1.0f, 1.0f, quad));
        return writeAndLoad(g, prims, std::string("quad_") + alphaMode + (withQuad ? "" : "_none"));
    };
    const Scene blended = scene("BLEND", true);
    EXPECT_TRUE(materialFeatures(blended) & ML_FEATURE_BLEND);
    const FloatImage mix = renderNaive(blended, kOneLight, kFrontView);
    const FloatImage quad = renderNaive(scene("OPAQUE", true), kOneLight, kFrontView);
    const FloatImage wall = renderNaive(scene("BLEND", false), kOneLight, kFrontView);
    const glm::vec3 centre = pixel(mix, kWidth / 2, kHeight / 2);
    EXPECT_GT(centre.r, 0.05f);
    EXPECT_GT(centre.g, 0.05f) << "the wall shows through";
    expectColourNear(centre, 0.5f * pixel(quad, kWidth / 2, kHeight / 2) + 0.5f * pixel(wall, kWidth / 2, kHeight / 2), "centre");
    // Beside the quad only the wall is there.
    expectColourNear(pixel(mix, 10, kHeight / 2), pixel(wall, 10, kHeight / 2), "beside the quad");
    expectMethodsMatchNaive(blended, kOneLight, kFrontView, ClusteringSettings{}, "blended quad");
}

// Two double-sided panes at alpha 0.5 over the black background, the nearer one listed first in
// the file: the farther one must be drawn first (back to front), from the front and from behind.
TEST_F(Transparency, OverlappingPanesBlendBackToFrontFromEitherSide) {
    const auto scene = [&](const char* alphaMode, bool red, bool blue) {
        Gltf g;
        const int redPane = colourMaterial(g, {0.9f, 0.05f, 0.05f, 0.5f}, alphaMode, true);
        const int bluePane = colourMaterial(g, {0.05f, 0.05f, 0.9f, 0.5f}, alphaMode, true);
        std::vector<json> prims;
        if (red) prims.push_back(square(g, 0.5f, 1.0f, redPane));
        if (blue) prims.push_back(square(g, -0.5f, 1.0f, bluePane));
        return writeAndLoad(g, prims, std::string("panes_") + alphaMode + (red ? "_red" : "") + (blue ? "_blue" : ""));
    };
    const Scene both = scene("BLEND", true, true);
    const std::vector<Light> lights{{{0.3f, 0.2f, 3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}, {{-0.3f, 0.1f, -3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}};
    for (const auto& [pose, side] : {std::pair{kFrontView, "front"}, std::pair{kBackView, "back"}}) {
        const FloatImage mix = renderNaive(both, lights, pose);
        const glm::vec3 red = pixel(renderNaive(scene("OPAQUE", true, false), lights, pose), kWidth / 2, kHeight / 2);
        const glm::vec3 blue = pixel(renderNaive(scene("OPAQUE", false, true), lights, pose), kWidth / 2, kHeight / 2);
        const bool redNearer = side == std::string("front");
        const glm::vec3 nearer = redNearer ? red : blue, farther = redNearer ? blue : red;
        // Over black: the farther pane at half, then the nearer one over it.
        expectColourNear(pixel(mix, kWidth / 2, kHeight / 2), 0.5f * nearer + 0.25f * farther, std::string("seen from the ") + side);
        expectMethodsMatchNaive(both, lights, pose, ClusteringSettings{}, std::string("panes from the ") + side);
    }
}

// Lights that reach only a pane in front of the wall (small radii, near the pane), over a
// pane nearer than every opaque surface: the clusters must hold them wherever the pane is seen.
Scene nearPaneScene() {
    Gltf g;
    const int wall = colourMaterial(g, {0.7f, 0.7f, 0.7f, 1.0f}, "OPAQUE");
    const int glass = colourMaterial(g, {0.3f, 0.6f, 0.9f, 0.4f}, "BLEND", true);
    const int amber = colourMaterial(g, {0.9f, 0.6f, 0.2f, 0.6f}, "BLEND");
    return writeAndLoad(g,
                        {square(g, -2.0f, 6.0f, wall), rect(g, {-0.6f, 0.0f, 2.2f}, 0.9f, 0.7f, glass),
                         rect(g, {0.7f, 0.3f, 1.0f}, 1.0f, 0.8f, amber)},
                        "near_panes");
}

std::vector<Light> lightsNearPanes() {
    std::vector<Light> lights;
    for (int i = 0; i < 48; ++i) {
        const float x = -2.0f + 4.0f * float(i % 8) / 7.0f, y = -1.2f + 2.4f * float(i / 8) / 5.0f;
        const float z = 1.6f + 0.25f * float(i % 3);  // around the panes, far in front of the wall
        lights.push_back({{x, y, z}, 0.6f + 0.1f * float(i % 4), {1.5f, 1.2f + 0.1f * float(i % 5), 1.0f}});
    }
    return lights;
}

struct ListCase {
    const char* name;
    void (*apply)(ClusteringSettings&);
};
const ListCase kListCases[] = {
    {"fitted", [](ClusteringSettings&) {}},
    {"active_only", [](ClusteringSettings& c) { c.activeOnly = true; }},
    {"zbin", [](ClusteringSettings& c) { c.assign = AssignMode::ZBin; }},
    {"cull_sphere", [](ClusteringSettings& c) { c.cull = CullMode::Sphere; }},
    {"cull_cone", [](ClusteringSettings& c) { c.cull = CullMode::Cone; }},
    {"per_cluster", [](ClusteringSettings& c) { c.assign = AssignMode::PerCluster; }},
    {"capped", [](ClusteringSettings& c) {
         c.assign = AssignMode::Capped;
         c.maxPerCluster = 64;  // no list overflows: capped lists are exact then
     }},
};

class TransparencyLists : public GpuTest, public ::testing::WithParamInterface<ListCase> {};

TEST_P(TransparencyLists, EveryMethodMatchesNaiveWithAPaneNearerThanEveryOpaqueSurface) {
    ClusteringSettings c;
    GetParam().apply(c);
    expectMethodsMatchNaive(nearPaneScene(), lightsNearPanes(), kFrontView, c, std::string("near panes ") + GetParam().name);
}

INSTANTIATE_TEST_SUITE_P(Lists, TransparencyLists, ::testing::ValuesIn(kListCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Normal cones know the opaque samples' normals only; the panes face the camera, the wall too,
// but lights between a pane and the wall face the wall and the pane's back: deferred and the
// visibility buffer (Forward+ has no normal cones) with the panes' samples marked.
TEST_F(Transparency, NormalConesHoldTheTransparentSamples) {
    const Scene scene = nearPaneScene();
    const std::vector<Light> lights = lightsNearPanes();
    FrameSettings s = test::smallFrame(scene, kFrontView, kWidth, kHeight);
    FrameRenderer renderer(scene, lights, s);
    const test::ReferenceFrame naive = test::renderReference(renderer, 0);
    for (bool activeOnly : {false, true}) {
        for (MethodKind kind : {MethodKind::Deferred, MethodKind::Visibility}) {
            MethodSettings m;
            m.kind = kind;
            m.clustering.normalCones = true;
            m.clustering.activeOnly = activeOnly;
            renderer.setMethod(m);
            renderer.render(0);
            test::expectWithinContract(renderer, naive, "normal cones " + methodName(kind) + (activeOnly ? " active-only" : ""));
        }
    }
}

// With --msaa the glass blends into every covered sample: Forward+ (with --active-only, whose
// transparent samples are marked at the same pixel centres the pass shades at) against naive at
// the same sample count.
TEST_F(Transparency, MultisampledForwardPlusMatchesNaiveOnTheGlass) {
    const Scene scene = nearPaneScene();
    const std::vector<Light> lights = lightsNearPanes();
    for (int samples : {2, 4}) {
        FrameSettings s = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        s.method.msaa = samples;
        FrameRenderer renderer(scene, lights, s);
        const test::ReferenceFrame naive = test::renderReference(renderer, 0);
        for (bool activeOnly : {false, true}) {
            MethodSettings m;
            m.kind = MethodKind::ForwardPlus;
            m.msaa = samples;
            m.clustering.activeOnly = activeOnly;
            renderer.setMethod(m);
            renderer.render(0);
            test::expectWithinContract(renderer, naive, "msaa " + std::to_string(samples) + (activeOnly ? " active-only" : ""));
        }
    }
}

// --transparency off draws the scene as if its BLEND ranges were not there.
TEST_F(Transparency, OffLeavesTheTransparentSurfacesOut) {
    Gltf g;
    const int wall = colourMaterial(g, {0.7f, 0.7f, 0.7f, 1.0f}, "OPAQUE");
    const int glass = colourMaterial(g, {0.9f, 0.1f, 0.1f, 0.5f}, "BLEND");
    const Scene withGlass = writeAndLoad(g, {square(g, 0.0f, 2.5f, wall), square(g, 1.0f, 1.0f, glass)}, "with_glass");
    Gltf h;
    const int bare = colourMaterial(h, {0.7f, 0.7f, 0.7f, 1.0f}, "OPAQUE");
    const Scene withoutGlass = writeAndLoad(h, {square(h, 0.0f, 2.5f, bare)}, "without_glass");
    for (MethodKind kind : {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        FrameSettings s = test::smallFrame(withGlass, kFrontView, kWidth, kHeight);
        s.method.kind = kind;
        s.transparency = false;
        FrameRenderer off(withGlass, kOneLight, s);
        off.render(0);
        FrameRenderer bareRenderer(withoutGlass, kOneLight, s);
        bareRenderer.render(0);
        const ImageDifference d = compareImages(off.readHdr(), bareRenderer.readHdr());
        EXPECT_EQ(d.maxAbs, 0.0) << methodName(kind);
    }
}

// The draw order: back to front by the distance to each range's bounding-box centre.
TEST_F(Transparency, RangesAreOrderedBackToFront) {
    Gltf g;
    std::vector<json> panes;
    for (float z : {1.0f, -1.0f, 0.0f}) panes.push_back(square(g, z, 1.0f, colourMaterial(g, {0.5f, 0.5f, 0.5f, 0.5f}, "BLEND")));
    const Scene scene = writeAndLoad(g, panes, "three_panes");
    SceneGpu gpu(scene);
    ASSERT_EQ(gpu.transparentRangeCount(), 3u);
    EXPECT_EQ(gpu.transparentOrder({0.0f, 0.0f, 5.0f}), (std::vector<std::uint32_t>{1, 2, 0}));
    EXPECT_EQ(gpu.transparentOrder({0.0f, 0.0f, -5.0f}), (std::vector<std::uint32_t>{0, 2, 1}));
    const auto range = gpu.transparentDepthRange(glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0)), 0.1f, 100.0f);
    ASSERT_TRUE(range.has_value());
    EXPECT_NEAR(range->x, 4.0f, 1e-5f);
    EXPECT_NEAR(range->y, 6.0f, 1e-5f);
    gpu.setTransparency(false);
    EXPECT_FALSE(gpu.hasTransparent());
}

}  // namespace
}  // namespace ml
