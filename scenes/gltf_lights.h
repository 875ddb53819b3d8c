// glTF lights (KHR_lights_punctual) into SceneLight: point, spot and directional lights placed by
// their nodes' world transforms. Internal to scenes/gltf_*.cpp.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_nodes.h"
#include "scenes/scene.h"

namespace ml::gltf {

// One SceneLight per light instance, in node-walk order: the node's world position and its -z
// (normalised; scale does not matter). A light whose numbers make no light (an unknown type, a
// colour that is not 3 finite numbers >= 0, a negative or NaN intensity or range, a spot's outer
// angle outside (0, pi/2] or inner angle outside [0, outer]) or whose node gives it no position
// or direction throws SceneError naming `lights[i]`.
std::vector<SceneLight> convertLights(const std::string& path, const tinygltf::Model& model,
                                      const std::vector<LightInstance>& instances);

}  // namespace ml::gltf
