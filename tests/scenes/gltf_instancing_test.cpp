// EXT_mesh_gpu_instancing: each instance's TRANSLATION, ROTATION and SCALE, inside its node's
// world transform, becomes a mesh instance in world space; a malformed instance attribute is one
// line naming the node or the accessor.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

int vec4(Gltf& g, const std::vector<glm::vec4>& v) { return g.accessor(g.view(v.data(), v.size() * 16), kFloat, v.size(), "VEC4"); }

// The one-triangle mesh, instanced by node 0 with `attributes` under a parent translated by +10 x.
Gltf instanced(Gltf g, const json& attributes) {
    const int mesh = g.mesh({trianglePrimitive(g)});
    const int child = g.node({{"mesh", mesh}, {"scale", {2.0, 2.0, 2.0}},
                              {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}});
    g.scene({g.node({{"translation", {10.0, 0.0, 0.0}}, {"children", {child}}})});
    g.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    return g;
}

TEST(GltfInstancing, EachInstanceIsItsTrsInsideTheNode) {
    Gltf g;
    const float h = std::sqrt(0.5f);
    const int translation = g.vec3({{0, 0, 0}, {0, 5, 0}, {1, 0, 0}});
    const int rotation = vec4(g, {{0, 0, 0, 1}, {0, h, 0, h}, {0, 0, 0, 1}});  // x, y, z, w
    const int scale = g.vec3({{1, 1, 1}, {1, 1, 1}, {3, 1, 1}});
    const fs::path file = instanced(g, {{"TRANSLATION", translation}, {"ROTATION", rotation}, {"SCALE", scale}})
                              .writeGltf(testDir(), "instances");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(scene.vertices.size(), 9u);
    EXPECT_EQ(scene.triangleCount(), 3u);
    // world = parent (T +10x) * node (S 2) * instance (T R S); the triangle is (0,0,0) (1,0,0) (0,1,0).
    expectNear(scene.vertices[0].position, {10, 0, 0});
    expectNear(scene.vertices[1].position, {12, 0, 0});
    expectNear(scene.vertices[2].position, {10, 2, 0});
    expectNear(scene.vertices[3].position, {10, 10, 0});  // +5 y, doubled by the node
    expectNear(scene.vertices[4].position, {10, 10, -2});  // +x turned to -z about +y
    expectNear(scene.vertices[3].normal, {1, 0, 0});       // +z turned to +x
    expectNear(scene.vertices[6].position, {12, 0, 0});    // +1 x, doubled
    expectNear(scene.vertices[7].position, {18, 0, 0});    // scaled 3 along x, doubled
}

TEST(GltfInstancing, AnyOneAttributeIsEnough) {
    Gltf g;
    const int translation = g.vec3({{0, 0, 0}, {0, 0, 1}});
    const Scene scene = load(instanced(g, {{"TRANSLATION", translation}}).writeGlb(testDir(), "translation_only"));
    ASSERT_EQ(scene.vertices.size(), 6u);
    expectNear(scene.vertices[3].position, {10, 0, 2});
}

TEST(GltfInstancing, MalformedAttributesAreOneLine) {
    const fs::path dir = testDir();
    {
        Gltf g;
        const int translation = g.vec3({{0, 0, 0}, {0, 0, 1}});
        const int scale = g.vec3({{1, 1, 1}});
        expectFault(instanced(g, {{"TRANSLATION", translation}, {"SCALE", scale}}).writeGltf(dir, "counts"),
                    {"SCALE of nodes[0] EXT_mesh_gpu_instancing", "count 1 differs"});
    }
    {
        Gltf g;
        const int rotation = vec4(g, {{0, 0, 0, 0}});
        expectFault(instanced(g, {{"ROTATION", rotation}}).writeGltf(dir, "zero_rotation"),
                    {"nodes[0]", "ROTATION of instance 0 is a zero quaternion"});
    }
    {
        Gltf g;
        const int rotation = g.vec3({{0, 0, 0}});
        expectFault(instanced(g, {{"ROTATION", rotation}}).writeGltf(dir, "rotation_type"), {"ROTATION of nodes[0]", "VEC3"});
    }
    {
        Gltf g;
        expectFault(instanced(g, {{"_ID", 0}}).writeGltf(dir, "none"), {"nodes[0]", "none of TRANSLATION, ROTATION and SCALE"});
    }
    {
        Gltf g;
        expectFault(instanced(g, {{"TRANSLATION", 7}}).writeGltf(dir, "index"), {"nodes[0]", "TRANSLATION is not an accessor index"});
    }
    {
        // Instances cost nothing in a file whose accessor has no buffer view: they are capped.
        Gltf g;
        const int many = g.accessor(-1, kFloat, std::size_t{1} << 24, "VEC3");
        expectFault(instanced(g, {{"TRANSLATION", many}}).writeGltf(dir, "many"), {"TRANSLATION of nodes[0]", "over the limit"});
    }
}

}  // namespace
}  // namespace ml
