#include "scenes/gltf_compressed_json.h"

#include <string_view>

#include <nlohmann/json.hpp>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

using json = nlohmann::json;

const json* member(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

json* member(json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

json* extension(json& object, const char* name) {
    json* extensions = member(object, "extensions");
    return extensions ? member(*extensions, name) : nullptr;
}

bool moveDracoIndices(json& doc) {
    bool moved = false;
    json* meshes = member(doc, "meshes");
    if (!meshes || !meshes->is_array()) return false;
    for (json& mesh : *meshes) {
        json* primitives = member(mesh, "primitives");
        if (!primitives || !primitives->is_array()) continue;
        for (json& primitive : *primitives) {
            json* draco = extension(primitive, "KHR_draco_mesh_compression");
            json* indices = member(primitive, "indices");
            if (!draco || !draco->is_object() || !indices) continue;
            (*draco)[kSetAsideIndicesKey] = *indices;
            primitive.erase("indices");
            moved = true;
        }
    }
    return moved;
}

// A GLB's buffer 0 without a uri is its BIN chunk; any other buffer without one is a fallback.
bool replaceFallbackBuffers(json& doc, bool binary, SetAside& aside) {
    json* buffers = member(doc, "buffers");
    if (!buffers || !buffers->is_array()) return false;
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        json& buffer = (*buffers)[i];
        const json* meshopt = extension(buffer, "EXT_meshopt_compression");
        const json* fallback = meshopt ? member(*meshopt, "fallback") : nullptr;
        if (!fallback || *fallback != true || member(buffer, "uri") || (binary && i == 0)) continue;
        // tinygltf decodes no empty data URI, so one byte stands in.
        buffer["uri"] = "data:application/octet-stream;base64,AA==";
        buffer["byteLength"] = 1;
        aside.fallbackBuffers.push_back(i);
    }
    return !aside.fallbackBuffers.empty();
}

}  // namespace

std::optional<std::string> setAsideForTinyGltf(std::string_view text, bool binary, SetAside& aside) {
    if (!contains(text, "KHR_draco_mesh_compression") && !contains(text, "EXT_meshopt_compression")) return std::nullopt;
    json doc = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return std::nullopt;  // discarded or not a glTF root: tinygltf says why
    const bool draco = moveDracoIndices(doc);
    const bool meshopt = replaceFallbackBuffers(doc, binary, aside);
    if (!draco && !meshopt) return std::nullopt;
    return doc.dump(-1, ' ', false, json::error_handler_t::replace);
}

void putBack(const SetAside& aside, tinygltf::Model& model) {
    for (tinygltf::Mesh& mesh : model.meshes) {
        for (tinygltf::Primitive& primitive : mesh.primitives) {
            const auto it = primitive.extensions.find("KHR_draco_mesh_compression");
            if (it == primitive.extensions.end() || !it->second.IsObject()) continue;
            auto& object = it->second.Get<tinygltf::Value::Object>();
            const auto indices = object.find(kSetAsideIndicesKey);
            if (indices == object.end()) continue;
            // A non-integer index stays out of range, so the plan reports it.
            primitive.indices = indices->second.IsInt() ? indices->second.GetNumberAsInt() : INT_MAX;
            object.erase(indices);
        }
    }
    for (const std::size_t b : aside.fallbackBuffers) {
        if (b >= model.buffers.size()) continue;
        model.buffers[b].uri.clear();
        model.buffers[b].data.clear();
    }
}

}  // namespace ml::gltf
