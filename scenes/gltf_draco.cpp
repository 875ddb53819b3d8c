// KHR_draco_mesh_compression (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Khronos/KHR_draco_mesh_compression)
// through Debian's libdraco 1.5.5. Draco returns its faults as a Status, never by throwing; what
// it hands back is still checked (counts against the loader's limits, every value's bytes
// against its attribute's buffer) before a byte of it is copied. Values are read here rather
// than through Draco's ConvertValue, which loads a stream's bool or misaligned data as typed
// values (undefined behaviour a fuzzed stream reaches).
#include "scenes/gltf_draco.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <type_traits>

#include <draco/compression/decode.h>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

// Why a primitive cannot be decoded; empty when it can.
using Fault = std::string;

struct DracoPrimitive {
    int bufferView = -1;
    std::map<std::string, int> attributes;  // glTF attribute name -> Draco unique id
};

Fault parseExtension(const tinygltf::Value& ext, DracoPrimitive& out) {
    if (!ext.IsObject()) return "the extension is not a JSON object";
    if (!ext.Has("bufferView") || !ext.Get("bufferView").IsInt()) return "\"bufferView\" is missing or not an index";
    out.bufferView = ext.Get("bufferView").GetNumberAsInt();
    if (!ext.Has("attributes") || !ext.Get("attributes").IsObject()) return "\"attributes\" is missing or not an object";
    const tinygltf::Value& attributes = ext.Get("attributes");
    for (const std::string& name : attributes.Keys()) {
        const tinygltf::Value& id = attributes.Get(name);
        if (!id.IsInt() || id.GetNumberAsInt() < 0) return "attribute " + clip(name, 40) + " has no Draco attribute id";
        out.attributes[name] = id.GetNumberAsInt();
    }
    return {};
}

// A Draco component type the glTF accessors can hold: its size, whether it is an integer, and
// its largest value (for normalized integers).
struct DracoComponent {
    std::size_t size = 0;
    bool integer = false;
    double max = 1.0;
};
DracoComponent dracoComponent(draco::DataType type) {
    switch (type) {
        case draco::DT_INT8: return {1, true, 127.0};
        case draco::DT_UINT8: return {1, true, 255.0};
        case draco::DT_INT16: return {2, true, 32767.0};
        case draco::DT_UINT16: return {2, true, 65535.0};
        case draco::DT_INT32: return {4, true, 2147483647.0};
        case draco::DT_UINT32: return {4, true, 4294967295.0};
        case draco::DT_FLOAT32: return {4, false, 1.0};
        default: return {};  // 64-bit, bool: no glTF attribute holds them
    }
}

double readComponent(const std::uint8_t* p, draco::DataType type) {
    const auto as = [p](auto value) {
        std::memcpy(&value, p, sizeof value);
        return static_cast<double>(value);
    };
    switch (type) {
        case draco::DT_INT8: return as(std::int8_t{});
        case draco::DT_UINT8: return as(std::uint8_t{});
        case draco::DT_INT16: return as(std::int16_t{});
        case draco::DT_UINT16: return as(std::uint16_t{});
        case draco::DT_INT32: return as(std::int32_t{});
        case draco::DT_UINT32: return as(std::uint32_t{});
        default: return as(float{});
    }
}

// Every value of a Draco attribute, per point, as the accessor's component type: the same type
// as a rule (copied as is), else integers widened or read as floats (divided by their largest
// value where Draco marks them normalized). Each read is checked against Draco's buffer and
// copied byte-wise, whatever the stream claimed about its layout.
template <class T>
Fault convertAttribute(const draco::PointAttribute& attribute, std::size_t points, std::size_t components,
                       std::vector<unsigned char>& out) {
    const DracoComponent from = dracoComponent(attribute.data_type());
    if (from.size == 0) return "Draco data type " + std::to_string(attribute.data_type()) + " is not a glTF component type";
    if (std::is_integral_v<T> && !from.integer) return "float values for an integer accessor";
    const std::size_t stored = std::min<std::size_t>(attribute.num_components(), components);
    const std::size_t bufferSize = attribute.buffer() ? attribute.buffer()->data_size() : 0;
    const auto* data = attribute.buffer() ? attribute.buffer()->data() : nullptr;
    out.assign(points * components * sizeof(T), 0);
    for (std::size_t p = 0; p < points; ++p) {
        const draco::AttributeValueIndex index = attribute.mapped_index(draco::PointIndex(static_cast<std::uint32_t>(p)));
        const auto offset = static_cast<std::uint64_t>(attribute.byte_offset()) +
                            static_cast<std::uint64_t>(attribute.byte_stride()) * index.value();
        if (attribute.byte_offset() < 0 || attribute.byte_stride() < 0 || offset + stored * from.size > bufferSize)
            return "point " + std::to_string(p) + " reads past the attribute's values";
        for (std::size_t c = 0; c < stored; ++c) {
            double value = readComponent(data + offset + c * from.size, attribute.data_type());
            if constexpr (std::is_integral_v<T>) {
                if (value < double(std::numeric_limits<T>::min()) || value > double(std::numeric_limits<T>::max()))
                    return "a value does not fit the accessor's component type";
            } else if (from.integer && attribute.normalized()) {
                value /= from.max;
            }
            const T converted = static_cast<T>(value);
            std::memcpy(out.data() + (p * components + c) * sizeof(T), &converted, sizeof(T));
        }
    }
    return {};
}

Fault convertAttribute(const draco::PointAttribute& attribute, std::size_t points, const tinygltf::Accessor& accessor,
                       std::vector<unsigned char>& out) {
    const std::size_t components = componentCount(accessor.type);
    if (components == 0 || components > 4) return "accessor type is not SCALAR or VEC2 to VEC4";
    switch (accessor.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return convertAttribute<float>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_BYTE: return convertAttribute<std::int8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convertAttribute<std::uint8_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return convertAttribute<std::int16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convertAttribute<std::uint16_t>(attribute, points, components, out);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convertAttribute<std::uint32_t>(attribute, points, components, out);
        default: return "accessor componentType " + std::to_string(accessor.componentType) + " is not a glTF component type";
    }
}

// Appends bytes as a buffer, a view of all of it and an accessor like `like` reading it.
int appendAccessor(tinygltf::Model& model, std::vector<unsigned char> bytes, tinygltf::Accessor like, std::size_t count) {
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteLength = bytes.size();
    model.buffers.emplace_back().data = std::move(bytes);
    like.bufferView = static_cast<int>(model.bufferViews.size());
    model.bufferViews.push_back(std::move(view));
    like.byteOffset = 0;
    like.count = count;
    like.sparse = {};
    model.accessors.push_back(std::move(like));
    return static_cast<int>(model.accessors.size() - 1);
}

struct Decoded {
    std::vector<unsigned char> indices;  // UNSIGNED_INT
    std::size_t indexCount = 0, points = 0;
    std::map<std::string, std::vector<unsigned char>> attributes;
};

Fault decode(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const DracoPrimitive& draco, Decoded& out) {
    if (draco.bufferView < 0 || static_cast<std::size_t>(draco.bufferView) >= model.bufferViews.size())
        return "bufferView " + std::to_string(draco.bufferView) + " out of range (" +
               std::to_string(model.bufferViews.size()) + " buffer views)";
    // Buffer views lie inside their buffers (checked by the container).
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(draco.bufferView)];
    const auto* bytes = model.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), view.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok()) return "cannot decode bufferViews[" + std::to_string(draco.bufferView) + "]: " + clip(result.status().error_msg_string(), 200);
    const std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    if (!mesh) return "cannot decode bufferViews[" + std::to_string(draco.bufferView) + "]: not a Draco mesh";

    out.points = mesh->num_points();
    const std::size_t faces = mesh->num_faces();
    if (out.points > kMaxVertices) return std::to_string(out.points) + " points, over the vertex limit";
    if (faces > kMaxIndices / 3) return std::to_string(faces) + " faces, over the index limit";
    out.indexCount = 3 * faces;
    out.indices.resize(out.indexCount * sizeof(std::uint32_t));
    for (std::size_t f = 0; f < faces; ++f) {
        const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(static_cast<std::uint32_t>(f)));
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = face[k].value();
            std::memcpy(out.indices.data() + (3 * f + k) * sizeof(std::uint32_t), &index, sizeof(index));
        }
    }
    for (const auto& [name, id] : draco.attributes) {
        const auto it = primitive.attributes.find(name);
        if (it == primitive.attributes.end()) continue;  // compressed, but not read by this primitive
        if (it->second < 0 || static_cast<std::size_t>(it->second) >= model.accessors.size())
            return name + " accessor index " + std::to_string(it->second) + " out of range";
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
        if (attribute == nullptr) return name + ": the stream has no attribute with id " + std::to_string(id);
        Fault fault = convertAttribute(*attribute, out.points, model.accessors[static_cast<std::size_t>(it->second)],
                                       out.attributes[name]);
        if (!fault.empty()) return name + ": " + fault;
    }
    return {};
}

// Whether the primitive's own accessors hold its data, so a reader without Draco could draw it.
bool hasUncompressedData(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
    const auto stored = [&](int accessor) {
        return accessor >= 0 && static_cast<std::size_t>(accessor) < model.accessors.size() &&
               model.accessors[static_cast<std::size_t>(accessor)].bufferView >= 0;
    };
    if (primitive.indices >= 0 && !stored(primitive.indices)) return false;
    return std::all_of(primitive.attributes.begin(), primitive.attributes.end(),
                       [&](const auto& attribute) { return stored(attribute.second); });
}

}  // namespace

std::vector<std::string> decodeDracoPrimitives(const std::string& path, tinygltf::Model& model) {
    std::vector<std::string> warnings;
    const bool required = lists(model.extensionsRequired, "KHR_draco_mesh_compression");
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            const auto ext = primitive.extensions.find("KHR_draco_mesh_compression");
            // Draco streams hold triangle lists; points and lines are skipped by the plan anyway.
            if (ext == primitive.extensions.end() ||
                !isOneOf(primitive.mode, {TINYGLTF_MODE_TRIANGLES, TINYGLTF_MODE_TRIANGLE_STRIP}))
                continue;
            DracoPrimitive draco;
            Decoded decoded;
            Fault fault = parseExtension(ext->second, draco);
            if (fault.empty()) fault = decode(model, primitive, draco, decoded);
            const std::string what =
                named("meshes", m, model.meshes[m].name) + " primitive " + std::to_string(p) + ": KHR_draco_mesh_compression: ";
            if (!fault.empty()) {
                if (required || !hasUncompressedData(model, primitive)) fail(path, what + fault);
                warnings.push_back(what + fault + "; its uncompressed accessors are used instead");
                continue;
            }
            for (auto& [name, bytes] : decoded.attributes) {
                const tinygltf::Accessor like = model.accessors[static_cast<std::size_t>(primitive.attributes[name])];
                primitive.attributes[name] = appendAccessor(model, std::move(bytes), like, decoded.points);
            }
            tinygltf::Accessor indices;
            indices.type = TINYGLTF_TYPE_SCALAR;
            indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
            primitive.indices = appendAccessor(model, std::move(decoded.indices), indices, decoded.indexCount);
            primitive.mode = TINYGLTF_MODE_TRIANGLES;  // Draco's faces are a triangle list
        }
    }
    return warnings;
}

}  // namespace ml::gltf
