// glTF triangle strips and fans render as their triangle-list twins do, byte for byte: the loader
// turns them into the same triangles with the same winding, so culling and shading cannot tell.
// The files carry a camera, which the frame uses (Scene::cameras, cameraFromSceneCamera).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gpu_test.h"
#include "renderer/camera/camera.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml::test {
namespace {

using namespace gltf_test;

class GltfStripFan : public GpuTest {};

// A bent ribbon of 8 vertices (zig-zag order, as a strip lists them, top first so that the first
// triangle is counter-clockwise from +z) and a bent fan of 7, each with a normal per vertex,
// drawn as `stripMode` / `fanMode` primitives with these index lists.
Scene ribbonAndFan(const std::string& name, int stripMode, const std::vector<std::uint16_t>& stripIndices, int fanMode,
                   const std::vector<std::uint16_t>& fanIndices) {
    Gltf g;
    std::vector<glm::vec3> ribbon, ribbonNormals, fan, fanNormals;
    for (int i = 0; i < 8; ++i) {
        const float x = -1.2f + 0.35f * static_cast<float>(i / 2), y = (i % 2 == 0) ? -0.2f : -1.0f;
        ribbon.push_back({x, y, 0.2f * std::sin(2.0f * x)});
        ribbonNormals.push_back(glm::normalize(glm::vec3(-0.4f * std::cos(2.0f * x), 0.0f, 1.0f)));
    }
    fan.push_back({0.5f, 0.4f, 0.3f});
    fanNormals.push_back({0, 0, 1});
    for (int i = 0; i < 6; ++i) {
        const float a = 0.5f * static_cast<float>(i);
        fan.push_back({0.5f + 0.7f * std::cos(a), 0.4f + 0.6f * std::sin(a), 0.1f * static_cast<float>(i % 2)});
        fanNormals.push_back(glm::normalize(glm::vec3(0.2f * std::cos(a), 0.2f * std::sin(a), 1.0f)));
    }
    const auto drawn = [&](const std::vector<glm::vec3>& p, const std::vector<glm::vec3>& n, int mode,
                           const std::vector<std::uint16_t>& indices) {
        json prim = primitive({{"POSITION", g.vec3(p)}, {"NORMAL", g.vec3(n)}}, indices.empty() ? -1 : g.indices(indices));
        prim["mode"] = mode;
        return prim;
    };
    const int mesh = g.mesh({drawn(ribbon, ribbonNormals, stripMode, stripIndices), drawn(fan, fanNormals, fanMode, fanIndices)});
    g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}, {"zfar", 20.0}}}}};
    // The camera 3.5 units up +z, looking down -z at the middle.
    const int camera = g.node({{"camera", 0}, {"translation", {0.0, 0.0, 3.5}}});
    g.scene({g.node({{"mesh", mesh}}), camera});
    return load(g.writeGlb(testDir(), name));
}

RgbaImage renderNaive(const Scene& scene) {
    const std::vector<Light> lights = {Light{{0.3f, 0.2f, 1.5f}, 6.0f, {2.0f, 2.0f, 2.0f}},
                                            Light{{-0.8f, -0.5f, 0.8f}, 3.0f, {1.0f, 0.8f, 0.6f}}};
    EXPECT_EQ(scene.cameras.size(), 1u);
    FrameSettings s = smallFrame(scene, scene.cameras.at(0).pose, 160, 90);
    s.camera = cameraFromSceneCamera(scene.cameras.at(0));
    fitClipPlanes(s.camera, scene.bounds, scene.cameras.at(0));
    s.method.kind = MethodKind::Naive;
    s.backfaceCulling = true;
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    return renderer.readLdr();
}

TEST_F(GltfStripFan, StripsAndFansRenderAsTheirTriangleLists) {
    constexpr int kTriangles = 4, kStrip = 5, kFan = 6;
    // Strip triangle i: (i, i+1, i+2), its winding swapped on odd i. Fan triangle i: (0, i+1, i+2).
    std::vector<std::uint16_t> stripList, fanList;
    for (std::uint16_t i = 0; i + 2 < 8; ++i)
        stripList.insert(stripList.end(), {i, static_cast<std::uint16_t>(i + 1 + i % 2), static_cast<std::uint16_t>(i + 2 - i % 2)});
    for (std::uint16_t i = 0; i + 2 < 7; ++i)
        fanList.insert(fanList.end(), {0, static_cast<std::uint16_t>(i + 1), static_cast<std::uint16_t>(i + 2)});

    const RgbaImage lists = renderNaive(ribbonAndFan("lists", kTriangles, stripList, kTriangles, fanList));
    const RgbaImage strips = renderNaive(ribbonAndFan("strip_fan", kStrip, {}, kFan, {}));
    const RgbaImage indexed = renderNaive(ribbonAndFan("strip_fan_indexed", kStrip, {0, 1, 2, 3, 4, 5, 6, 7}, kFan, {0, 1, 2, 3, 4, 5, 6}));
    // The ribbon and the fan cover about 7% of the frame: count pixels unlike the corner's background.
    std::size_t covered = 0;
    for (std::size_t i = 0; i < lists.pixels.size(); i += 4)
        covered += !std::equal(&lists.pixels[i], &lists.pixels[i] + 3, lists.pixels.data());
    EXPECT_GT(covered, 160u * 90u / 30u) << "the twins should cover a good part of the frame";
    if (strips.pixels != lists.pixels) {
        ADD_FAILURE() << "strip/fan differs from its triangle list: " << writeFailureImages("strip_fan", strips, lists);
    }
    if (indexed.pixels != lists.pixels) {
        ADD_FAILURE() << "indexed strip/fan differs from its triangle list: " << writeFailureImages("strip_fan_indexed", indexed, lists);
    }
}

}  // namespace
}  // namespace ml::test
