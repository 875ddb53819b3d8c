// glTF cameras into SceneCamera: perspective cameras placed by their nodes' world transforms.
// Internal to scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_nodes.h"
#include "scenes/scene.h"

namespace ml::gltf {

// One SceneCamera per perspective camera instance, in node-walk order. Orthographic cameras are
// not modelled: they are counted in `orthographicSkipped`. A camera whose numbers make no
// projection (yfov outside (0, pi), znear <= 0, zfar <= znear, NaN) or whose node gives it no
// direction throws SceneError naming it.
std::vector<SceneCamera> convertCameras(const std::string& path, const tinygltf::Model& model,
                                        const std::vector<CameraInstance>& instances, std::size_t& orthographicSkipped);

}  // namespace ml::gltf
