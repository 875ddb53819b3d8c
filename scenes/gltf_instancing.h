// EXT_mesh_gpu_instancing: a node that draws its mesh once per instance, each placed by its own
// TRANSLATION, ROTATION and SCALE inside the node. Internal to scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_nodes.h"

namespace ml::gltf {

// The mesh instances `placed` stands for: itself where its node has no EXT_mesh_gpu_instancing,
// else one per instance, with world = node world * T * R * S (the extension's order), so that
// they are flattened, and drawn by every method, as any other instance. `budget` is what is left
// of kMaxInstances for the file; a node asking for more fails the load in one line.
std::vector<MeshInstance> gpuInstances(const std::string& path, const tinygltf::Model& model, const AccessorReader& reader,
                                       const MeshInstance& placed, std::size_t& budget);

}  // namespace ml::gltf
