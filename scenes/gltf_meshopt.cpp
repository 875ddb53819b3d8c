// EXT_meshopt_compression (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Vendor/EXT_meshopt_compression)
// through meshoptimizer 0.18's decoders. Its decoders are safe on untrusted streams but assert on
// sizes they do not support, so every size is checked against the extension's rules first.
#include "scenes/gltf_meshopt.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include <meshoptimizer.h>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

// The most any meshoptimizer codec expands: a vertex stream spends at least two header bits per
// 16 bytes of one byte lane (64:1); index codecs spend at least a byte per triangle or index.
// A view claiming more than this from its bytes is refused before anything is allocated.
constexpr std::size_t kMaxExpansion = 64;

struct CompressedView {
    std::size_t buffer = 0, byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    std::string mode, filter = "NONE";
};

// Why a view cannot be decoded; empty when it can.
using Fault = std::string;

std::optional<std::size_t> wholeNumber(const tinygltf::Value& object, const char* key) {
    if (!object.Has(key)) return std::nullopt;
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsNumber()) return std::nullopt;
    const double d = v.GetNumberAsDouble();
    if (!(d >= 0.0) || d != std::floor(d) || d > 9.0e15) return std::nullopt;
    return static_cast<std::size_t>(d);
}

Fault parseExtension(const tinygltf::Value& ext, CompressedView& view) {
    if (!ext.IsObject()) return "the extension is not a JSON object";
    const auto required = [&](const char* key, std::size_t& out) -> Fault {
        const auto n = wholeNumber(ext, key);
        if (!n) return std::string("\"") + key + "\" is missing or not a non-negative integer";
        out = *n;
        return {};
    };
    const std::pair<const char*, std::size_t*> fields[] = {
        {"buffer", &view.buffer}, {"byteLength", &view.byteLength}, {"byteStride", &view.byteStride}, {"count", &view.count}};
    for (const auto& [key, out] : fields)
        if (Fault f = required(key, *out); !f.empty()) return f;
    if (ext.Has("byteOffset")) {
        const auto offset = wholeNumber(ext, "byteOffset");
        if (!offset) return "\"byteOffset\" is not a non-negative integer";
        view.byteOffset = *offset;
    }
    if (!ext.Has("mode") || !ext.Get("mode").IsString()) return "\"mode\" is missing";
    view.mode = ext.Get("mode").Get<std::string>();
    if (ext.Has("filter")) {
        if (!ext.Get("filter").IsString()) return "\"filter\" is not a string";
        view.filter = ext.Get("filter").Get<std::string>();
    }
    return {};
}

// The extension's rules on sizes (and meshoptimizer's asserts).
Fault checkSizes(const CompressedView& v) {
    if (v.mode == "ATTRIBUTES") {
        if (v.byteStride == 0 || v.byteStride % 4 != 0 || v.byteStride > 256)
            return "ATTRIBUTES byteStride " + std::to_string(v.byteStride) + " is not a multiple of 4 from 4 to 256";
    } else if (v.mode == "TRIANGLES" || v.mode == "INDICES") {
        if (v.byteStride != 2 && v.byteStride != 4)
            return v.mode + " byteStride " + std::to_string(v.byteStride) + " is not 2 or 4";
        if (v.mode == "TRIANGLES" && v.count % 3 != 0)
            return "TRIANGLES count " + std::to_string(v.count) + " is not a multiple of 3";
    } else {
        return "unknown mode '" + clip(v.mode, 40) + "' (expected ATTRIBUTES, TRIANGLES or INDICES)";
    }
    if (v.filter != "NONE") {
        if (v.mode != "ATTRIBUTES") return "filter " + clip(v.filter, 40) + " on a " + v.mode + " stream (filters apply to ATTRIBUTES)";
        if (v.filter == "OCTAHEDRAL") {
            if (v.byteStride != 4 && v.byteStride != 8) return "OCTAHEDRAL filter needs byteStride 4 or 8, not " + std::to_string(v.byteStride);
        } else if (v.filter == "QUATERNION") {
            if (v.byteStride != 8) return "QUATERNION filter needs byteStride 8, not " + std::to_string(v.byteStride);
        } else if (v.filter != "EXPONENTIAL") {
            return "unknown filter '" + clip(v.filter, 40) + "' (expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL)";
        }
    }
    return {};
}

std::string decoderFault(int code) {
    switch (code) {
        case -1: return "not a meshoptimizer stream of a supported version (bad header byte)";
        case -2: return "the stream is truncated or malformed";
        case -3: return "the stream does not end where its data does (trailing or missing bytes)";
        default: return "meshoptimizer decoder error " + std::to_string(code);
    }
}

// Decodes one view's stream; `out` receives count * byteStride bytes.
Fault decode(const tinygltf::Model& model, const CompressedView& v, std::vector<unsigned char>& out) {
    if (Fault f = checkSizes(v); !f.empty()) return f;
    if (v.buffer >= model.buffers.size())
        return "source buffer " + std::to_string(v.buffer) + " out of range (" + std::to_string(model.buffers.size()) + " buffers)";
    const std::vector<unsigned char>& source = model.buffers[v.buffer].data;
    if (v.byteOffset > source.size() || v.byteLength > source.size() - v.byteOffset)
        return "byteOffset " + std::to_string(v.byteOffset) + " + byteLength " + std::to_string(v.byteLength) +
               " overruns buffers[" + std::to_string(v.buffer) + "] (" + std::to_string(source.size()) + " bytes)";
    const std::size_t limit = std::min<std::size_t>(kMaxFileBytes, kMaxExpansion * v.byteLength);
    if (v.count > limit / v.byteStride)
        return "count " + std::to_string(v.count) + " x byteStride " + std::to_string(v.byteStride) + " is more than " +
               std::to_string(v.byteLength) + " compressed bytes can hold";
    out.assign(v.count * v.byteStride, 0);
    const unsigned char* bytes = source.data() + v.byteOffset;
    int code = 0;
    if (v.mode == "ATTRIBUTES") code = meshopt_decodeVertexBuffer(out.data(), v.count, v.byteStride, bytes, v.byteLength);
    else if (v.mode == "TRIANGLES") code = meshopt_decodeIndexBuffer(out.data(), v.count, v.byteStride, bytes, v.byteLength);
    else code = meshopt_decodeIndexSequence(out.data(), v.count, v.byteStride, bytes, v.byteLength);
    if (code != 0) return decoderFault(code);
    if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(out.data(), v.count, v.byteStride);
    else if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(out.data(), v.count, v.byteStride);
    else if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(out.data(), v.count, v.byteStride);
    return {};
}

}  // namespace

std::vector<std::string> decodeMeshoptViews(const std::string& path, tinygltf::Model& model) {
    std::vector<std::string> warnings;
    const bool required = lists(model.extensionsRequired, "EXT_meshopt_compression");
    // Buffers appended below are decoded views, not sources.
    const std::size_t fileBuffers = model.buffers.size();
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i) {
        const auto ext = model.bufferViews[i].extensions.find("EXT_meshopt_compression");
        if (ext == model.bufferViews[i].extensions.end()) continue;
        CompressedView compressed;
        std::vector<unsigned char> bytes;
        Fault fault = parseExtension(ext->second, compressed);
        if (fault.empty() && compressed.buffer >= fileBuffers) fault = "source buffer out of range";
        if (fault.empty()) fault = decode(model, compressed, bytes);

        tinygltf::BufferView& view = model.bufferViews[i];
        const std::string what = named("bufferViews", i, view.name) + ": EXT_meshopt_compression: ";
        if (!fault.empty()) {
            // The view's own bytes stand in where the file may be read without the extension.
            const bool fallback = view.buffer >= 0 && static_cast<std::size_t>(view.buffer) < fileBuffers &&
                                  view.byteOffset <= model.buffers[static_cast<std::size_t>(view.buffer)].data.size() &&
                                  view.byteLength <= model.buffers[static_cast<std::size_t>(view.buffer)].data.size() - view.byteOffset;
            if (required || !fallback) fail(path, what + fault);
            warnings.push_back(what + fault + "; its uncompressed bytes are used instead");
            continue;
        }
        if (bytes.size() > view.byteLength)
            fail(path, what + "decodes to " + std::to_string(bytes.size()) + " bytes, more than the view's byteLength " +
                           std::to_string(view.byteLength));
        tinygltf::Buffer decoded;
        decoded.data = std::move(bytes);
        model.buffers.push_back(std::move(decoded));
        view.buffer = static_cast<int>(model.buffers.size() - 1);
        view.byteOffset = 0;
        view.byteLength = model.buffers.back().data.size();
    }
    return warnings;
}

}  // namespace ml::gltf
