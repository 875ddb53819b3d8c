// KHR_draco_mesh_compression: primitives whose attributes and indices are a Draco stream, decoded
// (libdraco) into plain accessors before the meshes are planned. Internal to scenes/gltf_*.cpp.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

// Decodes each triangle primitive carrying the extension: every attribute the extension's
// "attributes" maps to a Draco attribute id becomes a new accessor of the type and component
// type the primitive's own accessor declares (the same values the uncompressed file holds), and
// the Draco faces become a new UNSIGNED_INT index accessor; the primitive is pointed at them.
// A primitive that cannot be decoded fails the load in one line naming the mesh, the primitive
// and the reason, unless the extension is optional and the primitive's accessors hold the
// uncompressed data: then those are kept, with the line returned as a warning.
std::vector<std::string> decodeDracoPrimitives(const std::string& path, tinygltf::Model& model);

}  // namespace ml::gltf
