// The glTF container: reading the file, checking a GLB container and the JSON text by hand,
// parsing with tinygltf, then checking the buffers and buffer views tinygltf leaves unchecked.
// Internal to scenes/gltf_*.cpp.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

struct ParsedGltf {
    tinygltf::Model model;
    std::string tinygltfWarnings;  // non-fatal messages, on one line
    std::vector<std::string> warnings;  // compressed views read from their fallback, one line each
};

// Reads and parses a .gltf or .glb file and decodes its EXT_meshopt_compression views. After it
// returns, every buffer view lies inside its buffer; accessors, nodes and the rest are checked
// where they are read.
ParsedGltf readGltfContainer(const std::string& path);

}  // namespace ml::gltf
