// EXT_meshopt_compression: buffer views whose bytes are meshoptimizer streams, decoded into plain
// bytes before any accessor reads them. Internal to scenes/gltf_*.cpp.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

// Decodes every buffer view carrying the extension (meshopt_decodeVertexBuffer, IndexBuffer or
// IndexSequence by its mode, then its filter: octahedral, quaternion or exponential) into a
// buffer of its own, and points the view there. A view that cannot be decoded fails the load in
// one line naming it and the reason, unless the extension is optional and the view's own buffer
// holds the uncompressed bytes: then those are kept, with the line returned as a warning.
std::vector<std::string> decodeMeshoptViews(const std::string& path, tinygltf::Model& model);

}  // namespace ml::gltf
