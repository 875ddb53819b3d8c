// The node hierarchy of a glTF file's default scene, flattened to world transforms. Internal to
// scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

namespace ml::gltf {

struct MeshInstance {
    std::size_t node;
    std::size_t mesh;
    glm::dmat4 world;
    // EXT_mesh_gpu_instancing: this instance's TRS inside its node (world = node world x it).
    glm::dmat4 instance{1.0};
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

// A node's local transform as the file gives it: a matrix, or translation, rotation (unit) and
// scale. Each array's length is checked (one line naming the node).
struct NodeTransform {
    std::optional<glm::dmat4> matrix;
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 scale{1.0};
    glm::dmat4 local() const;
};
NodeTransform nodeTransform(const std::string& path, const tinygltf::Node& node, std::size_t index);

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
