// The glTF container: reading the file, checking a GLB container and the JSON text by hand,
// parsing with tinygltf, then checking the buffers and buffer views tinygltf leaves unchecked.
// Internal to scenes/gltf_*.cpp.
#pragma once

#include <string>

#include <tiny_gltf.h>

namespace ml::gltf {

struct ParsedGltf {
    tinygltf::Model model;
    std::string tinygltfWarnings;  // non-fatal messages, on one line
};

// Reads and parses a .gltf or .glb file. After it returns, every buffer view lies inside its
// buffer; accessors, nodes and the rest are checked where they are read.
ParsedGltf readGltfContainer(const std::string& path);

}  // namespace ml::gltf
