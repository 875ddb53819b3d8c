// Small animated glTF files for the animation tests (scene tests and GPU tests): a two-bone
// skinned strip, a morphed quad and a node-animated cube, each with a motion whose result is
// known in closed form.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "tests/scenes/gltf_test_files.h"

namespace ml::gltf_test {

inline int floats(Gltf& g, const std::vector<float>& v, const char* type, std::size_t components) {
    return g.accessor(g.view(v.data(), v.size() * 4), kFloat, v.size() / components, type);
}
inline int scalars(Gltf& g, const std::vector<float>& v) { return floats(g, v, "SCALAR", 1); }

// An animation of one channel: `path` of `node`, keyframes at `times`, `values` as glTF lays
// them out (three groups per key for CUBICSPLINE).
inline int addAnimation(Gltf& g, const char* name, int node, const char* path, const std::vector<float>& times,
                        const std::vector<float>& values, const char* type, std::size_t components,
                        const char* interpolation = "LINEAR") {
    const int input = scalars(g, times);
    const int output = floats(g, values, type, components);
    return g.add("animations", {{"name", name},
                                {"samplers", json::array({{{"input", input}, {"output", output}, {"interpolation", interpolation}}})},
                                {"channels", json::array({{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}})}});
}

// The skinned strip: six vertices at x = 0, 1, 2 and y = 0, 0.2 (z = 0), triangles facing +z.
// Joint 0 (node 1) sits at the origin, joint 1 (node 2, its child) at x = 1; the vertices at x =
// 0 follow joint 0, those at x = 2 joint 1, those at x = 1 both, half each. The clip "Bend"
// turns joint 1 about +z from 0 (t = 0) to 90 degrees (t = 1), LINEAR: at t = 1 the vertex
// (2, 0, 0) is at (1, 1, 0) and (2, 0.2, 0) at (0.8, 1, 0). The mesh node (node 0) is moved by
// (100, 0, 0), which a skinned mesh ignores (glTF).
struct SkinnedStrip {
    Gltf g;
    int jointsAccessor = -1, weightsAccessor = -1, inverseBindAccessor = -1, skin = -1;
};
inline SkinnedStrip skinnedStrip(const json& jointsOverride = json(), bool inverseBindShort = false) {
    SkinnedStrip s;
    Gltf& g = s.g;
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0.2f, 0}, {1, 0.2f, 0}, {2, 0.2f, 0}};
    const std::vector<std::uint8_t> joints = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0};
    const std::vector<float> weights = {1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0, 1, 0, 0, 0};
    s.jointsAccessor = g.accessor(g.view(joints.data(), joints.size()), kUByte, 6, "VEC4");
    s.weightsAccessor = floats(g, weights, "VEC4", 4);
    json attributes = {{"POSITION", g.vec3(positions)}, {"JOINTS_0", s.jointsAccessor}, {"WEIGHTS_0", s.weightsAccessor}};
    const int mesh = g.mesh({primitive(attributes, g.indices({0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4}))});
    // Column-major: joint 1's inverse bind undoes its translation by (1, 0, 0).
    std::vector<float> inverseBind = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                      1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};
    if (inverseBindShort) inverseBind.resize(16);
    s.inverseBindAccessor = floats(g, inverseBind, "MAT4", 16);
    g.node({{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}});
    g.node({{"children", {2}}});
    g.node({{"translation", {1, 0, 0}}});
    s.skin = g.add("skins", {{"joints", jointsOverride.is_null() ? json::array({1, 2}) : jointsOverride},
                             {"inverseBindMatrices", s.inverseBindAccessor}});
    g.scene({0, 1});
    const float h = std::sqrt(0.5f);
    addAnimation(g, "Bend", 2, "rotation", {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, h, h}, "VEC4", 4);
    return s;
}

// The morphed quad: a unit square at z = 0 facing +z whose one morph target moves every vertex
// by (0, 0, 1), its weight animated 0, 0.5, 1 at t = 0, 1, 2 (LINEAR): the square sits at z = w.
inline Gltf morphedQuad(const char* interpolation = "LINEAR") {
    Gltf g;
    const int delta = g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    json prim = square(g, 0.0f, 0.5f, -1);
    prim["targets"] = json::array({{{"POSITION", delta}}});
    const int mesh = g.mesh({prim});
    g.doc["meshes"][mesh]["weights"] = {0.25};
    g.scene({g.node({{"mesh", mesh}})});
    addAnimation(g, "Morph", 0, "weights", {0.0f, 1.0f, 2.0f}, {0.0f, 0.5f, 1.0f}, "SCALAR", 1, interpolation);
    return g;
}

// The node-animated cube: a cube of side 1 around the origin whose node moves from (0, 0, 0) at
// t = 0 to (4, 0, 0) at t = 2 (LINEAR), so at t its centre is at (2 t, 0, 0).
inline Gltf animatedCube() {
    Gltf g;
    std::vector<glm::vec3> p;
    std::vector<std::uint16_t> idx;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = static_cast<float>(sign);
            u[(axis + 1) % 3] = 0.5f;
            v[(axis + 2) % 3] = 0.5f * static_cast<float>(sign);
            const auto base = static_cast<std::uint16_t>(p.size());
            for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                p.push_back(0.5f * n + c.x * u + c.y * v);
            for (std::uint16_t k : {0, 1, 2, 0, 2, 3}) idx.push_back(static_cast<std::uint16_t>(base + k));
        }
    const int mesh = g.mesh({primitive({{"POSITION", g.vec3(p)}}, g.indices(idx))});
    g.scene({g.node({{"mesh", mesh}})});
    addAnimation(g, "Slide", 0, "translation", {0.0f, 2.0f}, {0, 0, 0, 4, 0, 0}, "VEC3", 3);
    return g;
}

}  // namespace ml::gltf_test
