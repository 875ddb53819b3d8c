// What every part of the glTF loader shares: the limits that bound its allocations and the
// one-line messages it fails and warns with. Internal to scenes/gltf_*.cpp.
#pragma once

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace ml::gltf {

// --- Limits --------------------------------------------------------------------------------------
// tinygltf passes sizes as int / unsigned int, so files past 2 GiB cannot be handed to it.
inline constexpr std::uintmax_t kMaxFileBytes = INT_MAX;
// tinygltf turns `extras` and `extensions` into tinygltf::Value recursively; a 100,000-deep
// array would overflow the C stack. Real glTF nests well under 20 levels.
inline constexpr int kMaxJsonDepth = 256;
// After flattening instances: 64 Mi vertices (2 GiB of Vertex) and 256 Mi indices (1 GiB). An
// accessor without a buffer view costs nothing in the file, so its count needs a cap of its own.
inline constexpr std::size_t kMaxVertices = std::size_t{1} << 26;
inline constexpr std::size_t kMaxIndices = std::size_t{1} << 28;
// EXT_mesh_gpu_instancing's instances, all nodes together: each becomes a copy of its mesh in
// world space, and an accessor without a buffer view can ask for any number at no cost.
inline constexpr std::size_t kMaxInstances = std::size_t{1} << 20;
// Animation keyframes, all samplers together (times and values): 32 Mi floats (128 MiB). An
// accessor without a buffer view costs nothing in the file.
inline constexpr std::size_t kMaxKeyframeFloats = std::size_t{1} << 25;
// Morph target deltas, vertices x targets over all deformed meshes: 2 Mi (96 MiB on the GPU,
// under the 128 MiB a storage buffer may hold on llvmpipe).
inline constexpr std::size_t kMaxMorphDeltas = std::size_t{1} << 21;
// Decoded base-colour textures, all together: 256 Mi texels (1 GiB of RGBA8).
inline constexpr int kMaxImageSide = 16384;
inline constexpr std::uint64_t kMaxImageTexels = std::uint64_t{1} << 28;

// --- Messages ------------------------------------------------------------------------------------

std::string_view trim(std::string_view s);

// A piece of text fit for a one-line message: control characters become spaces, and long text
// (a data URI echoed by tinygltf, say) is cut short.
std::string clip(std::string_view s, std::size_t maxChars = 400);

// tinygltf reports one problem per line, sometimes a million of them. A SceneError or a warning is
// one line, so keep the first few and say how many more there were.
std::string oneLine(std::string_view text, std::size_t maxLines = 3);

// Throws SceneError("<path>: <fault>"), the fault cut to one line.
[[noreturn]] void fail(const std::string& path, const std::string& fault);

// "meshes[2] 'Body'": an index always, the name when there is one.
std::string named(const char* kind, std::size_t index, const std::string& name);

// "1 mesh", "3 meshes".
std::string counted(std::size_t n, const char* singular, const char* plural);

inline bool isOneOf(int value, std::initializer_list<int> options) {
    return std::find(options.begin(), options.end(), value) != options.end();
}

// Whether `names` (extensionsUsed or extensionsRequired) lists `name`.
inline bool lists(const std::vector<std::string>& names, std::string_view name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

inline bool startsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }
inline bool contains(std::string_view s, std::string_view part) { return s.find(part) != std::string_view::npos; }

}  // namespace ml::gltf
