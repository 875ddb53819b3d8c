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

// The default scene's mesh instances with their world transforms. Nodes are walked with an
// explicit stack (a 100,000-deep chain must not recurse), and each node may be entered once:
// glTF nodes form disjoint trees, and re-entering would loop on a cycle or multiply a shared
// subtree exponentially.
std::vector<MeshInstance> flattenNodes(const std::string& path, const tinygltf::Model& model);

}  // namespace ml::gltf
