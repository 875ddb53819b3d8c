// Spot and directional lights on the GPU: a spot over a plane lights exactly the disk its outer
// cone cuts, in every method; a glTF file's lights land where its nested transforms put them;
// spots, points and a sun mixed stay within the accuracy contract against naive for every
// assignment, cull test and normal cones; the light animation turns spots as its CPU mirror does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"
#include "scenes/scene_library.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml::test {
namespace {

class SpotLights : public GpuTest {};

// The plane y = 0, 8 x 8 around the origin, facing +y.
Scene floorScene() { return quadScene({{{0.0f, 0.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -4.0f}, glm::vec3(0.8f)}}); }

// Where the pixel's ray meets the plane y = 0.
glm::vec3 floorPoint(const FrameRenderer& r, int x, int y, int width, int height) {
    const glm::vec2 ndc((x + 0.5f) / width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / height * 2.0f);  // images: top row first
    const glm::mat4 inverse = glm::inverse(r.uniforms().viewProj);
    glm::vec4 a = inverse * glm::vec4(ndc, 1.0f, 1.0f), b = inverse * glm::vec4(ndc, 0.0f, 1.0f);  // near, far
    const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
    return p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
}

TEST_F(SpotLights, ASpotOverAPlaneLightsExactlyTheDiskItsOuterConeCuts) {
    const Scene scene = floorScene();
    Light spot{{0.3f, 2.0f, -0.2f}, 6.0f, {3.0f, 3.0f, 3.0f}};
    spot.type = LightType::Spot;
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerConeAngle = 0.35f;
    spot.outerConeAngle = 0.5f;
    const float diskRadius = 2.0f * std::tan(spot.outerConeAngle);
    const int width = 160, height = 120;
    FrameSettings s = smallFrame(scene, CameraPose{{0.0f, 6.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 50.0f}, width, height);
    s.ambient = 0.0f;
    FrameRenderer renderer(scene, {spot}, s);
    std::vector<std::pair<MethodSettings, std::string>> methods = {{MethodSettings{}, "naive"}};
    for (const ClusteredVariant& v : kClusteredVariants) {
        MethodSettings m;
        m.kind = v.kind;
        m.resolve = v.resolve;
        m.clustering.grid = ClusterGridConfig{8, 8, Slicing::Fitted, 64};
        methods.emplace_back(m, v.name);
    }
    for (const auto& [method, name] : methods) {
        renderer.setMethod(method);
        renderer.render(0);
        const FloatImage hdr = renderer.readHdr();
        std::size_t lit = 0, dark = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const glm::vec3 p = floorPoint(renderer, x, y, width, height);
                if (std::abs(p.x) > 3.9f || std::abs(p.z) > 3.9f) continue;  // off the plane, or at its edge
                const float fromAxis = glm::length(glm::vec2(p.x - spot.position.x, p.z - spot.position.z));
                const float value = hdr.pixels[(std::size_t(y) * width + x) * 3];
                if (fromAxis < diskRadius * 0.99f) {
                    EXPECT_GT(value, 0.0f) << name << ": pixel " << x << "," << y << " inside the disk is dark";
                    ++lit;
                } else if (fromAxis > diskRadius * 1.01f) {
                    EXPECT_EQ(value, 0.0f) << name << ": pixel " << x << "," << y << " outside the disk is lit";
                    ++dark;
                }
            }
        }
        std::printf("%-20s %zu pixels lit inside the disk, %zu dark outside\n", name.c_str(), lit, dark);
        EXPECT_GT(lit, 500u) << name;
        EXPECT_GT(dark, 2000u) << name;
    }
}

// The seeds' model, and glTF's BRDF with glTF's falloff at a hard cut-off and with stochastic
// ranges (every clustering exact for the drawn ranges).
class MixedLights : public GpuTest, public ::testing::WithParamInterface<LightModel> {};

TEST_P(MixedLights, SpotsPointsAndASunMatchNaiveForEveryAssignmentAndCullTest) {
    TestScene t = testScene("atrium", 300, 7, 1.0f, 0.5f);
    const LightModel model = GetParam();
    if (model.cutoff > 0.0f) applyCutoffRadii(t.lights, model.cutoff);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.3f, -1.0f, 0.2f};
    sun.color = {0.3f, 0.28f, 0.25f};
    t.lights.insert(t.lights.begin() + 17, sun);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    setLightModel(s, model);
    s.animation = verticalDrift(lightVolume(t.scene.bounds), 0.5f);  // spots turn as they drift
    struct Variant {
        AssignMode assign;
        CullMode cull;
        bool normalCones;
    };
    const Variant variants[] = {{AssignMode::Exact, CullMode::Aabb, false},     {AssignMode::Exact, CullMode::Sphere, false},
                                {AssignMode::Exact, CullMode::Cone, false},     {AssignMode::Capped, CullMode::Aabb, false},
                                {AssignMode::PerCluster, CullMode::Cone, false}, {AssignMode::ZBin, CullMode::Aabb, false},
                                {AssignMode::Exact, CullMode::Aabb, true}};
    for (const Variant& v : variants) {
        s.method.clustering.grid = ClusterGridConfig{16, 12, Slicing::Fitted, 64};
        s.method.clustering.assign = v.assign;
        s.method.clustering.cull = v.cull;
        s.method.clustering.normalCones = v.normalCones;
        const std::string label = std::string(assignModeName(v.assign)) + " " + cullModeName(v.cull) + (v.normalCones ? " normal-cones" : "");
        expectWithinContract(clusteredErrors(t.scene, t.lights, s, 40), label);
    }
}

INSTANTIATE_TEST_SUITE_P(LightModels, MixedLights,
                         ::testing::Values(LightModel{Brdf::BlinnPhong}, LightModel{Brdf::Ggx, Falloff::Gltf, 0.3f},
                                           LightModel{Brdf::Ggx, Falloff::Stochastic, 0.3f}),
                         [](const auto& info) {
                             return testNameOf(std::string(brdfName(info.param.brdf)) + "_" + falloffName(info.param.falloff));
                         });

// A points-only light set compiles every spot path out (ML_SPOT_LIGHTS 0); a renderer whose lights
// gain spots rebuilds its programs with them, and back without them gives the first frame again.
TEST_F(SpotLights, ProgramsFollowWhetherTheLightsHoldSpots) {
    const TestScene points = testScene("atrium", 200, 3);
    const TestScene spots = testScene("atrium", 200, 3, 1.0f, 0.5f);
    for (MethodKind kind : {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        FrameSettings s = smallFrame(points.scene, 160, 90);
        s.method.kind = kind;
        FrameRenderer renderer(points.scene, points.lights, s);
        EXPECT_FALSE(renderer.settings().method.clustering.spotLights);
        renderer.render(20);
        const RgbaImage pointsOnly = renderer.readLdr();
        renderer.setLights(spots.lights);
        EXPECT_TRUE(renderer.settings().method.clustering.spotLights);
        renderer.render(20);
        const RgbaImage withSpots = renderer.readLdr();
        EXPECT_NE(withSpots.pixels, pointsOnly.pixels) << methodName(kind) << ": the spots should show";
        MethodSettings m = renderer.settings().method;
        renderer.setLights(points.lights);
        EXPECT_FALSE(renderer.settings().method.clustering.spotLights);
        renderer.render(20);
        EXPECT_EQ(renderer.readLdr().pixels, pointsOnly.pixels) << methodName(kind);
        m.clustering.spotLights = true;
        FrameRenderer general(points.scene, points.lights, s);
        general.setMethod(m);
        EXPECT_FALSE(general.settings().method.clustering.spotLights) << "the renderer decides from its lights";
    }
}

TEST_F(SpotLights, TheAnimationTurnsSpotsAsItsCpuMirrorDoes) {
    const TestScene t = testScene("boxes", 500, 3, 1.0f, 0.5f);
    FrameSettings s = smallFrame(t.scene, 32, 32);
    s.animation = verticalDrift(lightVolume(t.scene.bounds), 0.7f);
    FrameRenderer renderer(t.scene, t.lights, s);
    const std::uint32_t frame = 377;
    renderer.render(frame);
    const std::vector<Light> gpu = renderer.lights().downloadAnimated();
    ASSERT_EQ(gpu.size(), t.lights.size());
    std::size_t spots = 0;
    for (std::uint32_t i = 0; i < gpu.size(); ++i) {
        const Light cpu = animateLight(t.lights[i], i, frame * kSecondsPerFrame, s.animation);
        EXPECT_EQ(gpu[i].type, cpu.type);
        EXPECT_NEAR(gpu[i].position.y, cpu.position.y, 1e-4f) << i;
        if (cpu.type != LightType::Spot) continue;
        ++spots;
        EXPECT_LT(glm::length(gpu[i].direction - cpu.direction), 1e-4f) << i;
        EXPECT_EQ(gpu[i].direction.y, cpu.direction.y) << i;  // turned about +y only
    }
    EXPECT_GT(spots, 150u);
}

// A plane with a quad mesh, and lights on nested, rotated and scaled nodes.
std::filesystem::path writeLitFloor() {
    using namespace gltf_test;
    Gltf g;
    const json attributes = {{"POSITION", g.vec3({{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}})},
                             {"NORMAL", g.vec3({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}})}};
    const int mesh = g.mesh({primitive(attributes, g.indices({0, 2, 1, 0, 3, 2}))});
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    const json spot = {{"type", "spot"}, {"color", {1.0, 0.6, 0.3}}, {"intensity", 4.0}, {"range", 5.0},
                       {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.45}}}};
    const json point = {{"type", "point"}, {"color", {0.2, 0.5, 1.0}}, {"intensity", 2.0}, {"range", 3.0}};
    g.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {spot, point}}}}};
    const double s = std::sqrt(0.5);
    // The spot: parent at (1, 3, 0) scaled by 2; child 0.5 further up (1 in the world), turned
    // 90 degrees about +x so its -z points down -y: at (1, 4, 0), pointing straight down.
    const int spotNode = g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0.5, 0}},
                                 {"rotation", {-s, 0.0, 0.0, s}}});
    const int parent = g.node({{"translation", {1, 3, 0}}, {"scale", {2, 2, 2}}, {"children", {spotNode}}});
    const int pointNode = g.node({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"translation", {-2, 1, 1}}});
    g.scene({g.node({{"mesh", mesh}}), parent, pointNode});
    return g.writeGlb(testOutputDir(), "lit_floor");
}

TEST_F(SpotLights, AFilesLightsAtNestedTransformsLandWhereTheyShould) {
    std::vector<std::string> warnings;
    const Scene scene = loadScene(SceneRequest{writeLitFloor().string(), 1.0f}, warnings);
    const std::vector<Light> fromFile = lightsFromScene(scene);
    ASSERT_EQ(fromFile.size(), 2u);
    // The same lights placed by hand where the transforms put them.
    Light spot{{1.0f, 4.0f, 0.0f}, 5.0f, {4.0f, 2.4f, 1.2f}};
    spot.type = LightType::Spot;
    spot.direction = {0.0f, -1.0f, 0.0f};
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.45f;
    const Light point{{-2.0f, 1.0f, 1.0f}, 3.0f, {0.4f, 1.0f, 2.0f}};
    FrameSettings s = smallFrame(scene, CameraPose{{0.0f, 7.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, 55.0f}, 160, 120);
    FrameRenderer byHand(scene, {spot, point}, s);
    byHand.render(0);
    const ReferenceFrame expected = readReference(byHand);
    for (const ClusteredVariant& v : kClusteredVariants) {
        s.method.kind = v.kind;
        s.method.resolve = v.resolve;
        FrameRenderer renderer(scene, fromFile, s);
        renderer.render(0);
        expectWithinContract(renderer, expected, std::string("file's lights, ") + v.name);
    }
    // And they light something: the spot's disk is brighter than the ambient floor.
    float brightest = 0.0f;
    for (float value : expected.hdr.pixels) brightest = std::max(brightest, value);
    EXPECT_GT(brightest, 0.1f);
}

}  // namespace
}  // namespace ml::test
