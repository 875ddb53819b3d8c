// --shadows rays (issue 62): a light counts only where nothing stands between it and the point.
// Cases whose shadow is worked out by hand (a wall on a floor: the floor behind it dark right to
// its foot; a floor alone at grazing light: nothing changes, so no acne), the rule for BLEND
// surfaces (they cast none), every light type, and every method held to naive with shadows on.
#include <gtest/gtest.h>

#include <cstdio>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "gpu_test.h"
#include "renderer/camera/camera.h"
#include "scenes/animation_pose.h"
#include "tests/scenes/gltf_animation_files.h"

namespace ml::test {
namespace {

class ShadowRaysTest : public GpuTest {};

constexpr int kWidth = 320, kHeight = 180;

// A 12 x 12 floor at y = 0 and a wall 4 wide and 2 tall standing on it in the plane z = 0,
// facing +z. The camera looks at the floor in front of the wall from above and in front.
Scene wallOnFloor() {
    return quadScene({{{0, 0, 0}, {6, 0, 0}, {0, 0, -6}, glm::vec3(0.7f)},    // u x v = +y
                      {{0, 1, 0}, {2, 0, 0}, {0, 1, 0}, glm::vec3(0.5f, 0.6f, 0.7f)}});  // u x v = +z
}
const CameraPose kWallView{{0.0f, 7.0f, 7.0f}, {0.0f, 0.0f, 0.5f}, 60.0f};

FrameSettings frameOf(const Scene& scene, const CameraPose& pose, Shadows shadows, MethodKind kind = MethodKind::Naive) {
    FrameSettings s = smallFrame(scene, pose, kWidth, kHeight);
    s.shadows = shadows;
    s.method.kind = kind;
    return s;
}

// The pixel a world point lands on, and the HDR value there (FloatImage's rows run top down).
glm::vec3 valueAt(const FloatImage& hdr, const FrameSettings& s, const glm::vec3& world) {
    const glm::vec4 clip = s.camera.projection(float(s.width) / float(s.height)) * s.camera.view() * glm::vec4(world, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const int x = static_cast<int>((ndc.x * 0.5f + 0.5f) * float(s.width));
    const int y = static_cast<int>((ndc.y * 0.5f + 0.5f) * float(s.height));
    EXPECT_TRUE(x >= 0 && x < s.width && y >= 0 && y < s.height) << "point off screen";
    const float* p = hdr.at(x, s.height - 1 - y);
    return {p[0], p[1], p[2]};
}

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The floor's value with no light on it: the ambient term a (diffuse + f0), a grey dielectric of
// albedo 0.7 (f0 = 0.04), with a hair of room for rounding.
float unlitFloor(const FrameSettings& s) { return luminance(glm::vec3(0.7f + 0.04f) * s.ambient) * 1.0001f + 1e-6f; }

TEST_F(ShadowRaysTest, AWallShadowsTheFloorBehindItRightToItsFoot) {
    const Scene scene = wallOnFloor();
    // Behind the wall, at half its height: the floor at z > 0 with |x| < 2 (z + 3) / 3 is hidden.
    const std::vector<Light> lights = {Light{{0.0f, 1.0f, -3.0f}, 20.0f, glm::vec3(8.0f)}};
    const FrameSettings s = frameOf(scene, kWallView, Shadows::Rays);
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    const FloatImage hdr = renderer.readHdr();
    const float unlit = unlitFloor(s);
    for (float z : {0.02f, 0.1f, 0.5f, 2.0f, 4.0f}) {
        SCOPED_TRACE("floor at z = " + std::to_string(z));
        EXPECT_LE(luminance(valueAt(hdr, s, {0.0f, 0.0f, z})), unlit) << "lit through the wall";
        EXPECT_LE(luminance(valueAt(hdr, s, {1.5f, 0.0f, z})), unlit) << "lit through the wall";
    }
    // Beside the shadow: the floor past |x| = 2 (z + 3) / 3 sees the light (5.8 away, at a slant:
    // about 1.3 times the ambient term on top of it).
    EXPECT_GT(luminance(valueAt(hdr, s, {4.5f, 0.0f, 0.5f})), 2.0f * unlit);
    EXPECT_GT(luminance(valueAt(hdr, s, {-4.5f, 0.0f, 0.5f})), 2.0f * unlit);

    // Without shadow rays the same floor is lit: the test sees the shadow, not a dark scene.
    FrameRenderer unshadowed(scene, lights, frameOf(scene, kWallView, Shadows::Off));
    unshadowed.render(0);
    EXPECT_GT(luminance(valueAt(unshadowed.readHdr(), s, {0.0f, 0.0f, 0.5f})), 4.0f * unlit);
    expectClusteredVariantsMatchNaive(renderer, "wall on floor, shadows");
}

// With nothing to cast a shadow on what the camera sees, --shadows rays renders the unshadowed
// frame to the bit in each of `kinds`.
void expectShadowsChangeNothing(const Scene& scene, const std::vector<Light>& lights, std::initializer_list<MethodKind> kinds,
                                const char* failure) {
    for (MethodKind kind : kinds) {
        SCOPED_TRACE(methodName(kind));
        FrameRenderer off(scene, lights, frameOf(scene, kWallView, Shadows::Off, kind));
        off.render(0);
        FrameRenderer rays(scene, lights, frameOf(scene, kWallView, Shadows::Rays, kind));
        rays.render(0);
        EXPECT_EQ(compareImages(rays.readHdr(), off.readHdr()).maxAbs, 0.0) << failure;
    }
}

// A floor alone under lights from every height, the lowest 1 cm above it a few metres away (a
// grazing angle of a fraction of a degree): nothing stands in the way, so the frame must be the
// unshadowed one to the bit. A ray that met its own surface (acne) would darken a pixel.
TEST_F(ShadowRaysTest, NothingInTheWayChangesNothingAtGrazingAngles) {
    const Scene floor = quadScene({{{0, 0, 0}, {6, 0, 0}, {0, 0, -6}, glm::vec3(0.8f)}});
    std::vector<Light> lights;
    for (int i = 0; i < 12; ++i) {
        const float angle = 0.5236f * float(i);
        const float height = i % 3 == 0 ? 0.01f : (i % 3 == 1 ? 0.05f : 1.5f);
        lights.push_back(Light{{7.0f * std::cos(angle), height, 7.0f * std::sin(angle)}, 16.0f, glm::vec3(30.0f)});
    }
    expectShadowsChangeNothing(floor, lights, {MethodKind::Naive, MethodKind::Visibility}, "a shadow where nothing stands");
}

// BLEND surfaces (glass) cast no shadow: one rule in every method (docs/lights-and-shading.md).
TEST_F(ShadowRaysTest, BlendSurfacesCastNoShadow) {
    Scene scene = wallOnFloor();
    scene.materials[1].alphaMode = AlphaMode::Blend;
    scene.materials[1].baseColorFactor.a = 0.4f;
    const std::vector<Light> lights = {Light{{0.0f, 1.0f, -3.0f}, 20.0f, glm::vec3(8.0f)}};
    expectShadowsChangeNothing(scene, lights, {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility},
                               "the glass cast a shadow");
}

// An alpha-tested (MASK) wall shadows the floor only where its base colour's alpha covers the
// hit: the wall's texture is clear on its left half (u < 0.5, x < 0) and solid on its right, so
// behind the wall the floor at x > 0 is dark and at x < 0 lit. The floor point (x, z) sees the
// light at (0, 1, -3) through the wall at x * 3 / (z + 3). A texture transform moving u by a half
// swaps the halves; a factor below the cut-off clears the wall. Every method traces the same rays.
TEST_F(ShadowRaysTest, AnAlphaTestedWallCastsItsTexturesShadow) {
    Scene scene = wallOnFloor();
    Image half;
    half.name = "half clear";
    half.width = half.height = 64;
    half.rgba8.assign(64 * 64 * 4, 255);
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 32; ++i) half.rgba8[(static_cast<std::size_t>(j) * 64 + i) * 4 + 3] = 0;
    scene.images.push_back(half);
    Material& wall = scene.materials[1];
    wall.alphaMode = AlphaMode::Mask;
    wall.alphaCutoff = 0.5f;
    wall.baseColorTexture.image = 0;
    const std::vector<Light> lights = {Light{{0.0f, 1.0f, -3.0f}, 20.0f, glm::vec3(8.0f)}};
    const glm::vec3 solidSide{1.5f, 0.0f, 0.5f}, clearSide{-1.5f, 0.0f, 0.5f};
    struct Case {
        const char* name;
        glm::vec2 offset;
        float factorAlpha;
        bool solidDark, clearDark;
    };
    for (const Case& c : {Case{"as drawn", {0.0f, 0.0f}, 1.0f, true, false}, Case{"offset by a half", {0.5f, 0.0f}, 1.0f, false, true},
                          Case{"factor below the cut-off", {0.0f, 0.0f}, 0.4f, false, false}}) {
        SCOPED_TRACE(c.name);
        wall.baseColorTexture.transform.offset = c.offset;
        wall.baseColorFactor.a = c.factorAlpha;
        const FrameSettings s = frameOf(scene, kWallView, Shadows::Rays);
        FrameRenderer renderer(scene, lights, s);
        ASSERT_NE(renderer.shadowRays(), nullptr);
        EXPECT_EQ(renderer.shadowRays()->stats().maskTriangles, 2u);
        renderer.render(0);
        const FloatImage hdr = renderer.readHdr();
        const float unlit = unlitFloor(s);
        for (const auto& [point, dark] : {std::pair{solidSide, c.solidDark}, std::pair{clearSide, c.clearDark}}) {
            const float value = luminance(valueAt(hdr, s, point));
            if (dark) {
                EXPECT_LE(value, unlit) << "lit through the wall's solid half at x = " << point.x;
            } else {
                EXPECT_GT(value, 2.0f * unlit) << "dark behind the wall's clear half at x = " << point.x;
            }
        }
        expectClusteredVariantsMatchNaive(renderer, std::string("MASK wall, ") + c.name);
    }
}

// Spot and directional lights stop at the wall as points do: the sun from behind the wall and
// above (its shadow on the floor in front runs 2 / tan(elevation) from the foot), a spot behind it.
TEST_F(ShadowRaysTest, SpotAndDirectionalLightsStopAtTheWall) {
    const Scene scene = wallOnFloor();
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f));  // 45 degrees: a shadow 2 deep
    sun.color = glm::vec3(2.0f);
    Light spot{{0.0f, 1.5f, -2.0f}, 20.0f, glm::vec3(10.0f)};
    spot.type = LightType::Spot;
    spot.direction = glm::vec3(0.0f, -0.3f, 1.0f);
    spot.outerConeAngle = 0.9f;
    spot.innerConeAngle = 0.6f;
    for (const Light& light : {sun, spot}) {
        SCOPED_TRACE(light.type == LightType::Spot ? "spot" : "directional");
        const FrameSettings s = frameOf(scene, kWallView, Shadows::Rays);
        FrameRenderer renderer(scene, {light}, s);
        renderer.render(0);
        const FloatImage hdr = renderer.readHdr();
        const float unlit = unlitFloor(s);
        EXPECT_LE(luminance(valueAt(hdr, s, {0.0f, 0.0f, 0.5f})), unlit) << "lit through the wall";
        if (light.type == LightType::Directional) {
            EXPECT_GT(luminance(valueAt(hdr, s, {0.0f, 0.0f, 3.0f})), 4.0f * unlit);
        }
        FrameRenderer unshadowed(scene, {light}, frameOf(scene, kWallView, Shadows::Off));
        unshadowed.render(0);
        EXPECT_GT(luminance(valueAt(unshadowed.readHdr(), s, {0.0f, 0.0f, 0.5f})), 4.0f * unlit);
        expectClusteredVariantsMatchNaive(renderer, std::string("wall, ") + (light.type == LightType::Spot ? "spot" : "sun"));
    }
}

// The ray count behind `bench`'s rays per second: a floor filling the frame, seen from straight
// above, under two lights that reach all of it, traces one ray a pixel a light in every method,
// no more (Forward+'s pre-pass shades each pixel once) and no fewer; counting leaves the frame as
// it was. With --shadows off there is nothing to count.
TEST_F(ShadowRaysTest, TheRayCountIsOneAPixelForEachLightThatReachesIt) {
    const Scene floor = quadScene({{{0, 0, 0}, {6, 0, 0}, {0, 0, -6}, glm::vec3(0.8f)}});
    const CameraPose above{{0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 60.0f};
    const std::vector<Light> lights = {Light{{0.5f, 2.0f, 0.0f}, 30.0f, glm::vec3(4.0f)}, Light{{-1.0f, 1.0f, 0.5f}, 30.0f, glm::vec3(2.0f)}};
    for (MethodKind kind : {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        SCOPED_TRACE(methodName(kind));
        FrameRenderer renderer(floor, lights, frameOf(floor, above, Shadows::Rays, kind));
        renderer.render(0);
        const FloatImage before = renderer.readHdr();
        const std::optional<std::uint64_t> rays = renderer.countShadowRays(0);
        ASSERT_TRUE(rays.has_value());
        EXPECT_EQ(*rays, 2u * kWidth * kHeight);
        renderer.render(0);
        EXPECT_EQ(compareImages(renderer.readHdr(), before).maxAbs, 0.0) << "counting changed the frame";
        FrameRenderer off(floor, lights, frameOf(floor, above, Shadows::Off, kind));
        EXPECT_FALSE(off.countShadowRays(0).has_value());
    }
}

// The atrium as it ships (glass, alpha-tested foliage, lanterns) under 64 lights, shadows on:
// every method within the contract of naive tracing the same rays, the glass receiving shadows.
TEST_F(ShadowRaysTest, EveryMethodMatchesNaiveOnTheAtrium) {
    const TestScene t = testScene("atrium", 64, 5);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.shadows = Shadows::Rays;
    FrameRenderer renderer(t.scene, t.lights, s);
    ASSERT_NE(renderer.shadowRays(), nullptr);
    const ReferenceFrame naive = expectClusteredVariantsMatchNaive(renderer, "atrium, shadows");
    // The shadows are there: fewer lights reach the frame than without them (64 small lights near
    // the surfaces at 160x90: 0.9 % of pixels change on llvmpipe; 62 % at 1024 lights, 640x360).
    FrameSettings off = s;
    off.shadows = Shadows::Off;
    FrameRenderer unshadowed(t.scene, t.lights, off);
    unshadowed.render(0);
    const ImageDifference d = compareImages(naive.hdr, unshadowed.readHdr());
    std::printf("atrium 160x90, 64 lights: shadows change %.1f %% of pixels\n", 100.0 * d.badPixelShare);
    EXPECT_GT(d.badPixelShare, 0.004);
}

// The node layout (--shadow-bvh-width) changes how the rays find a blocker, never whether one
// exists: at every width naive gives the default width's frame to the bit, and every method
// holds the contract against it.
TEST_F(ShadowRaysTest, EveryBvhWidthGivesTheSameFrame) {
    const TestScene t = testScene("atrium", 64, 7);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.shadows = Shadows::Rays;
    FrameRenderer reference(t.scene, t.lights, s);
    reference.render(0);
    const FloatImage expected = reference.readHdr();
    for (std::uint32_t width : {2u, 4u, 8u}) {
        SCOPED_TRACE("width " + std::to_string(width));
        FrameSettings w = s;
        w.shadowBvhWidth = width;
        FrameRenderer renderer(t.scene, t.lights, w);
        ASSERT_EQ(renderer.shadowRays()->width(), width);
        const ReferenceFrame naive = expectClusteredVariantsMatchNaive(renderer, "atrium, width " + std::to_string(width));
        EXPECT_EQ(compareImages(naive.hdr, expected).maxAbs, 0.0) << "naive's frame moved with the width";
    }
}

// The node-animated cube (gltf_animation_files.h: side 1, centre (2 t, 0, 0) at t seconds)
// standing on a floor at y = -0.5, a point light above and behind it at (-1, 1.5, 0).
Scene slidingCubeOnFloor() {
    Scene scene = gltf_test::load(gltf_test::animatedCube().writeGlb(testOutputDir(), "animated-cube"));
    const auto first = static_cast<std::uint32_t>(scene.vertices.size());
    for (const glm::vec3& p : {glm::vec3(-4, -0.5f, 4), glm::vec3(8, -0.5f, 4), glm::vec3(8, -0.5f, -4), glm::vec3(-4, -0.5f, -4)})
        scene.vertices.push_back(Vertex{p, {0, 1, 0}, {0, 0}});
    const auto firstIndex = static_cast<std::uint32_t>(scene.indices.size());
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + i);
    Material floor;
    floor.name = "floor";
    floor.baseColorFactor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
    floor.metallic = 0.0f;
    floor.roughness = 1.0f;
    scene.materials.push_back(floor);
    scene.draws.push_back(DrawRange{firstIndex, 6, static_cast<std::uint32_t>(scene.materials.size() - 1)});
    computeBounds(scene);
    return scene;
}

// An animated file's shadows follow its pose (ShadowRays::refit): the sliding cube at t = 1 s
// against the same scene posed on the CPU (applyPose) and drawn as a static scene, whose
// structure Embree builds afresh on the posed triangles: naive within the contract of it, every
// method within the contract of naive; and the shadow moved with the cube. From the light, the
// cube at rest shadows the floor from x = 0.5 to 2, and at t = 1 (x from 1.5 to 2.5) from 2.5 to 6,
// so x = 1 is lit now and x = 4.5 dark; a structure left at rest says the opposite.
TEST_F(ShadowRaysTest, AnAnimatedFilesShadowFollowsItsPose) {
    const Scene scene = slidingCubeOnFloor();
    ASSERT_NE(scene.animation, nullptr);
    const std::vector<Light> lights = {Light{{-1.0f, 1.5f, 0.0f}, 30.0f, glm::vec3(30.0f)}};
    const CameraPose view{{2.0f, 6.0f, 6.0f}, {2.5f, -0.5f, 0.0f}, 60.0f};
    FrameSettings s = frameOf(scene, view, Shadows::Rays);
    s.sceneAnimation.clip = 0;
    s.sceneAnimation.startSeconds = 1.0;
    FrameRenderer animated(scene, lights, s);
    ASSERT_NE(animated.shadowRays(), nullptr);
    EXPECT_TRUE(animated.shadowRays()->followsPose());
    const ReferenceFrame naive = expectClusteredVariantsMatchNaive(animated, "sliding cube at 1 s");

    Scene posed = scene;
    applyPose(posed, poseAt(*scene.animation, &scene.animation->clips[0], 1.0));
    posed.animation = nullptr;
    computeBounds(posed);
    FrameSettings still = frameOf(posed, view, Shadows::Rays);
    FrameRenderer reference(posed, lights, still);
    EXPECT_FALSE(reference.shadowRays()->followsPose());
    reference.render(0);
    const ImageDifference d = compareImages(naive.ldr, reference.readLdr());
    std::printf("sliding cube at 1 s, refit against a fresh build on the CPU's pose: max %.0f/255, %.4f %% of pixels over 1/255\n",
                255.0 * d.maxAbs, 100.0 * d.badPixelShare);
    EXPECT_LE(d.maxAbs, kMaxAbs8Bit);

    // The wide layouts refit alike (glsl/refit_shadow_bvh.comp at each width).
    for (std::uint32_t width : {4u, 8u}) {
        FrameSettings w = s;
        w.shadowBvhWidth = width;
        FrameRenderer wide(scene, lights, w);
        wide.render(0);
        EXPECT_EQ(compareImages(wide.readLdr(), naive.ldr).maxAbs, 0.0) << "width " << width;
    }

    FrameSettings off = s;
    off.shadows = Shadows::Off;
    FrameRenderer unshadowed(scene, lights, off);
    unshadowed.render(0);
    const FloatImage open = unshadowed.readHdr();
    for (const glm::vec3 floorPoint : {glm::vec3(1.0f, -0.5f, 0.0f), glm::vec3(4.5f, -0.5f, 0.0f)}) {
        const float lit = luminance(valueAt(open, s, floorPoint)), shadowed = luminance(valueAt(naive.hdr, s, floorPoint));
        EXPECT_GT(lit, 4.0f * unlitFloor(s)) << "the light reaches x = " << floorPoint.x;
        if (floorPoint.x < 2.0f) {
            EXPECT_EQ(shadowed, lit) << "the rest pose's shadow is still there";
        } else {
            EXPECT_LE(shadowed, unlitFloor(s)) << "the cube at 1 s casts no shadow";
        }
    }
}

TEST(ShadowsFlag, BadValueIsOneLine) {
    std::string output;
    EXPECT_NE(runManylights("render --size 32x18 --shadows maybe --out /dev/null", output), 0);
    EXPECT_NE(output.find("--shadows 'maybe': expected off"), std::string::npos) << output;
    EXPECT_NE(runManylights("render --size 32x18 --shadows rays --shadow-bvh-width 16 --out /dev/null", output), 0);
    EXPECT_NE(output.find("--shadow-bvh-width 16: must be 2, 4 or 8"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
