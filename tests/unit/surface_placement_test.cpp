// Generated lights near a scene's surfaces (renderer/lights/surface_placement.h) and the share of
// lights whose sphere reaches a surface (renderer/lights/surface_reach.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "renderer/camera/default_camera.h"
#include "renderer/hash.h"
#include "renderer/lights/surface_placement.h"
#include "renderer/lights/surface_reach.h"
#include "scenes/scene_library.h"

namespace ml {
namespace {

Scene boxes() {
    std::vector<std::string> warnings;
    return loadScene(SceneRequest{"boxes", 0.5f}, warnings);
}

// One unit square in the y = 0 plane, lit from above.
Scene floorTile() {
    Scene s;
    for (const glm::vec3& p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 0, 1), glm::vec3(0, 0, 1)})
        s.vertices.push_back(Vertex{p, glm::vec3(0, 1, 0), glm::vec2(0)});
    s.indices = {0, 2, 1, 0, 3, 2};
    s.draws = {DrawRange{0, 6, 0}};
    s.materials.resize(1);
    computeBounds(s);
    return s;
}

LightGeneration generation(std::uint32_t count, float radius, std::uint32_t seed) {
    LightGeneration g;
    g.count = count;
    g.radius = radius;
    g.seed = seed;
    return g;
}

TEST(SurfacePlacement, SameSeedSamePlacesAndColoursKept) {
    const Scene scene = boxes();
    const auto a = generateLights(scene, generation(256, 0.5f, 7), LightPlacement::Surfaces);
    const auto b = generateLights(scene, generation(256, 0.5f, 7), LightPlacement::Surfaces);
    const auto c = generateLights(scene, generation(256, 0.5f, 8), LightPlacement::Surfaces);
    const auto volume = generateLights(scene, generation(256, 0.5f, 7), LightPlacement::Volume);
    ASSERT_EQ(a.size(), 256u);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        moved += a[i].position != c[i].position;
    }
    EXPECT_GT(moved, 250u) << "another seed, other places";
    // Each set is in spatial order of its own places, so a light's index differs between
    // placements; its colour goes with it.
    const auto colours = [](const std::vector<Light>& lights) {
        std::vector<std::array<float, 3>> c;
        for (const Light& l : lights) c.push_back({l.color.r, l.color.g, l.color.b});
        std::sort(c.begin(), c.end());
        return c;
    };
    EXPECT_EQ(colours(a), colours(volume)) << "a light keeps its colour whichever placement";
}

TEST(SurfacePlacement, LightsSitAQuarterRadiusAboveTheSurface) {
    const Scene tile = floorTile();
    const auto lights = generateLights(tile, generation(64, 0.4f, 1), LightPlacement::Surfaces);
    for (const Light& l : lights) {
        EXPECT_NEAR(l.position.y, kSurfaceOffsetShare * 0.4f, 1e-6f) << "along the normal, on the lit side";
        EXPECT_GE(l.position.x, 0.0f);
        EXPECT_LE(l.position.x, 1.0f);
        EXPECT_GE(l.position.z, 0.0f);
        EXPECT_LE(l.position.z, 1.0f);
    }
}

TEST(SurfaceReach, EverySurfaceLightReachesVolumeLightsOftenDoNot) {
    const Scene scene = boxes();
    const float radius = 0.05f * glm::length(scene.bounds.size());
    const SurfaceReach surfaces = measureSurfaceReach(scene, generateLights(scene, generation(512, radius, 3), LightPlacement::Surfaces));
    const SurfaceReach volume = measureSurfaceReach(scene, generateLights(scene, generation(512, radius, 3), LightPlacement::Volume));
    EXPECT_EQ(surfaces.lights, 512u);
    EXPECT_EQ(surfaces.reaching, 512u);
    EXPECT_LT(volume.share(), 0.9);
}

TEST(SurfaceReach, SphereAgainstATriangleIsExact) {
    const Scene tile = floorTile();
    Light l;
    l.radius = 0.5f;
    l.position = {0.5f, 0.49f, 0.5f};  // above the middle, just reaching
    EXPECT_EQ(measureSurfaceReach(tile, {l}).reaching, 1u);
    l.position = {0.5f, 0.51f, 0.5f};
    EXPECT_EQ(measureSurfaceReach(tile, {l}).reaching, 0u);
    l.position = {1.3f, 0.0f, 1.3f};  // beside the corner: 0.42 away
    EXPECT_EQ(measureSurfaceReach(tile, {l}).reaching, 1u);
    l.position = {1.4f, 0.0f, 1.4f};  // 0.57 away
    EXPECT_EQ(measureSurfaceReach(tile, {l}).reaching, 0u);
}

TEST(DefaultCamera, FramingHoldsTheBoundingSphereInTheNarrowerFieldOfView) {
    const Scene tile = floorTile();
    const BoundingSphere sphere = boundingSphere(tile);
    EXPECT_NEAR(sphere.radius, std::sqrt(0.5f), 1e-6f);
    for (const float aspect : {16.0f / 9.0f, 0.5f}) {
        const Camera c = frontFramingCamera(sphere, aspect);
        const float distance = glm::length(c.eye - sphere.centre);
        const float halfV = glm::radians(0.5f * c.fovyDegrees);
        const float halfH = std::atan(std::tan(halfV) * aspect);
        EXPECT_NEAR(std::sin(std::min(halfV, halfH)) * distance, sphere.radius, 1e-4f) << "aspect " << aspect;
        EXPECT_GT(c.eye.z, sphere.centre.z) << "from the front (+z)";
        EXPECT_GT(c.eye.y, sphere.centre.y) << "slightly above";
    }
}

// A room of 10 x 3 x 10 (floor and back wall), with one small triangle 1000 units away as an
// exporter leaves a stray helper object behind.
Scene room(bool withStray) {
    Scene s;
    const auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
        const auto base = static_cast<std::uint32_t>(s.vertices.size());
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (const glm::vec3& p : {a, b, c, d}) s.vertices.push_back(Vertex{p, n, glm::vec2(0)});
        s.indices.insert(s.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    };
    quad({0, 0, 0}, {0, 0, 10}, {10, 0, 10}, {10, 0, 0});
    quad({0, 0, 0}, {10, 0, 0}, {10, 3, 0}, {0, 3, 0});
    if (withStray) {
        const auto base = static_cast<std::uint32_t>(s.vertices.size());
        for (const glm::vec3& p : {glm::vec3(1000, 0, 0), glm::vec3(1000.1f, 0, 0), glm::vec3(1000, 0.1f, 0)})
            s.vertices.push_back(Vertex{p, glm::vec3(0, 0, 1), glm::vec2(0)});
        s.indices.insert(s.indices.end(), {base, base + 1, base + 2});
    }
    s.draws = {DrawRange{0, static_cast<std::uint32_t>(s.indices.size()), 0}};
    s.materials.resize(1);
    computeBounds(s);
    return s;
}

TEST(DefaultCamera, FramesTheSurfaceAroundTheMiddleOfItsAreaNotAStray) {
    const Scene strayed = room(true);
    EXPECT_GT(boundingSphere(strayed).radius, 400.0f) << "the raw bounds reach the stray";
    const FramedSurface framed = framedSurface(strayed);
    // The whole room, floor and wall to their edges, and nothing of the stray.
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(framed.framed.min[a], 0.0f, 1e-4f) << "axis " << a;
        EXPECT_NEAR(framed.framed.max[a], a == 1 ? 3.0f : 10.0f, 1e-4f) << "axis " << a;
    }
    EXPECT_NEAR(framed.sphere.radius, 0.5f * glm::length(glm::vec3(10, 3, 10)), 1e-3f);
    const DefaultCamera d = defaultCamera(strayed, 16.0f / 9.0f);
    EXPECT_LT(glm::length(d.camera.eye - glm::vec3(5, 1.5f, 5)), 30.0f);
    EXPECT_GT(d.camera.farPlane, 1000.0f) << "the clip planes still hold everything";
    EXPECT_NE(d.choice.find("the surface around the middle 96 % of its area"), std::string::npos) << d.choice;
}

TEST(DefaultCamera, AModelWithoutStraysFramesAsItsBoundingSphere) {
    for (const Scene& scene : {floorTile(), room(false)}) {
        const BoundingSphere whole = boundingSphere(scene);
        const FramedSurface framed = framedSurface(scene);
        EXPECT_NEAR(framed.sphere.radius, whole.radius, 1e-4f * whole.radius);
        EXPECT_LT(glm::length(framed.sphere.centre - whole.centre), 1e-4f * whole.radius);
    }
}

TEST(DefaultCamera, BuiltInScenesKeepTheirViewFilesTheirFirstCamera) {
    Scene scene = boxes();
    const DefaultCamera builtIn = defaultCamera(scene, 16.0f / 9.0f);
    EXPECT_EQ(builtIn.camera.eye, scene.suggestedView->eye);
    EXPECT_TRUE(builtIn.choice.empty());
    scene.suggestedView.reset();
    SceneCamera first;
    first.name = "Main";
    first.pose = CameraPose{glm::vec3(1, 2, 3), glm::vec3(0), 40.0f};
    first.nearPlane = 0.05f;
    scene.cameras = {first, SceneCamera{}};
    const DefaultCamera fromFile = defaultCamera(scene, 16.0f / 9.0f);
    EXPECT_EQ(fromFile.camera.eye, first.pose.eye);
    EXPECT_EQ(fromFile.camera.nearPlane, 0.05f);
    EXPECT_NE(fromFile.choice.find("gltf:0 'Main'"), std::string::npos) << fromFile.choice;
}


// The same surface stored in another order: triangles shuffled, each triangle's corners turned
// (winding kept), the vertices renumbered, as a re-export, Draco or gltfpack may store it.
Scene reordered(const Scene& scene, std::uint32_t seed) {
    Scene out = scene;
    const std::size_t n = scene.vertices.size(), triangles = scene.triangleCount();
    std::vector<std::uint32_t> vertexOrder(n), triangleOrder(triangles);
    for (std::uint32_t i = 0; i < n; ++i) vertexOrder[i] = i;
    for (std::uint32_t t = 0; t < triangles; ++t) triangleOrder[t] = t;
    // Fisher-Yates with the project's integer hash: the same shuffle on every machine.
    const auto shuffle = [&](std::vector<std::uint32_t>& v, std::uint32_t salt) {
        for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[pcgHash(seed ^ salt ^ static_cast<std::uint32_t>(i)) % i]);
    };
    shuffle(vertexOrder, 0x1234u);
    shuffle(triangleOrder, 0x5678u);
    std::vector<std::uint32_t> newIndexOf(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        out.vertices[i] = scene.vertices[vertexOrder[i]];
        newIndexOf[vertexOrder[i]] = i;
    }
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t* from = &scene.indices[3 * triangleOrder[t]];
        const std::size_t turn = t % 3;
        for (std::size_t k = 0; k < 3; ++k) out.indices[3 * t + k] = newIndexOf[from[(k + turn) % 3]];
    }
    out.draws = {DrawRange{0, static_cast<std::uint32_t>(out.indices.size()), 0}};
    return out;
}

TEST(SurfacePlacement, TheSurfaceNotItsStorageOrderPlacesTheLights) {
    Scene scene = boxes();
    scene.tangents.clear();
    scene.uv1.clear();
    scene.colors.clear();
    const Scene twin = reordered(scene, 3);
    ASSERT_NE(twin.indices, scene.indices);
    ASSERT_EQ(twin.bounds.min, scene.bounds.min);
    const auto a = generateLights(scene, generation(512, 0.5f, 7), LightPlacement::Surfaces);
    const auto b = generateLights(twin, generation(512, 0.5f, 7), LightPlacement::Surfaces);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position) << i;
        EXPECT_EQ(a[i].color, b[i].color) << i;
    }
}

TEST(DefaultCamera, TheSurfaceNotItsStorageOrderFramesTheView) {
    Scene scene = boxes();
    scene.suggestedView.reset();  // framed, as a file without a camera is
    const Scene twin = reordered(scene, 11);
    const DefaultCamera a = defaultCamera(scene, 16.0f / 9.0f), b = defaultCamera(twin, 16.0f / 9.0f);
    EXPECT_EQ(a.camera.eye, b.camera.eye);
    EXPECT_EQ(a.camera.target, b.camera.target);
    EXPECT_EQ(a.camera.nearPlane, b.camera.nearPlane);
    EXPECT_EQ(a.camera.farPlane, b.camera.farPlane);
}

}  // namespace
}  // namespace ml
