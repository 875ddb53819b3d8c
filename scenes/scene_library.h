// Scene lookup by name (atrium, plane, boxes) or by path to a .gltf/.glb file.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace ml {

struct SceneRequest {
    std::string nameOrPath = "atrium";
    float detail = 1.0f;  // procedural tessellation scale
};

// The names of the built-in scenes, for help texts and error messages.
const std::vector<std::string>& builtinSceneNames();

// Throws SceneError for an unknown name or a file that cannot be loaded.
Scene loadScene(const SceneRequest& request, std::vector<std::string>& warnings);

}  // namespace ml
