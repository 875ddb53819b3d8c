// glTF 2.0 (.gltf and .glb) into the scene model, through tinygltf.
#pragma once

#include <string>
#include <vector>

#include "scenes/scene.h"

namespace ml {

// Loads the default scene of a glTF file (or the first, if none is marked default) and flattens
// its node hierarchy into world space. Throws SceneError ("<path>: <fault>") on input it cannot
// use. Features the scene model does not hold are skipped: each kind adds one line to warnings.
Scene loadGltf(const std::string& path, std::vector<std::string>& warnings);

// True for the glTF extensions the loader models (reads, or whose absence changes nothing it
// reads); any other that a file uses is skipped with a warning.
bool isModelledGltfExtension(const std::string& name);

}  // namespace ml
