// What tinygltf 2.7 refuses in compressed files, set aside before it parses the JSON and put
// back after. Internal to scenes/gltf_*.cpp.
//
//   KHR_draco_mesh_compression  a compressed primitive's `indices` accessor has no bufferView (its
//                               data is in the Draco stream); tinygltf fails the whole file on that
//                               ("accessor[0] invalid bufferView") while marking index buffer
//                               views. The index moves into the primitive's Draco extension object
//                               (under kSetAsideIndicesKey) and comes back after parsing.
//   EXT_meshopt_compression     the fallback buffer (`"fallback": true`) may have no uri; tinygltf
//                               refuses that in a .gltf ("'uri' is missing from non binary glTF
//                               file buffer") and reads the BIN chunk in its place in a .glb. It
//                               is parsed as a one-byte placeholder and comes back empty: its
//                               views are decoded into buffers of their own (gltf_meshopt).
//
// Files that name neither extension are not touched (one substring search of the JSON text).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

inline constexpr const char* kSetAsideIndicesKey = "manylights:indices";

struct SetAside {
    std::vector<std::size_t> fallbackBuffers;  // parsed as placeholders, to be emptied
};

// The JSON text of a .gltf (or a .glb's JSON chunk) rewritten where tinygltf would refuse it;
// nothing when it would not. JSON that does not parse is left for tinygltf to report.
std::optional<std::string> setAsideForTinyGltf(std::string_view json, bool binary, SetAside& aside);

// Undoes the rewrite on the parsed model.
void putBack(const SetAside& aside, tinygltf::Model& model);

}  // namespace ml::gltf
