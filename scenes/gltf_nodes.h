// The node hierarchy of a glTF file's default scene, flattened to world transforms. Internal to
// scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace ml::gltf {

struct MeshInstance {
    std::size_t node;
    std::size_t mesh;
    glm::dmat4 world;
};

struct CameraInstance {
    std::size_t node;
    std::size_t camera;  // checked against model.cameras
    glm::dmat4 world;
};

struct LightInstance {
    std::size_t node;
    std::size_t light;  // KHR_lights_punctual: checked against model.lights
    glm::dmat4 world;
};

// What the default scene places, in node-walk order (depth first, children in their order).
struct FlatScene {
    std::vector<MeshInstance> meshes;
    std::vector<CameraInstance> cameras;
    std::vector<LightInstance> lights;
};

// The default scene's mesh, camera and light instances with their world transforms. Nodes are walked
// with an explicit stack (a 100,000-deep chain must not recurse), and each node may be entered
// once: glTF nodes form disjoint trees, and re-entering would loop on a cycle or multiply a
// shared subtree exponentially.
FlatScene flattenNodes(const std::string& path, const tinygltf::Model& model);

}  // namespace ml::gltf
