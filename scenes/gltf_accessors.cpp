#include "scenes/gltf_accessors.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>

#include "scenes/gltf_common.h"

namespace ml::gltf {

std::size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;  // DOUBLE is tinygltf's, not glTF 2.0's
    }
}

std::size_t componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

namespace {

std::string typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "type " + std::to_string(type);
    }
}

std::string componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return std::to_string(componentType);
    }
}


}  // namespace

std::string describe(const tinygltf::Model& model, int accessor, const Use& use) {
    std::string s = "accessors[" + std::to_string(accessor) + "]";
    if (use.owner != nullptr) return s + " (" + use.attribute + " of " + *use.owner + ")";
    if (use.instancedNode >= 0) {
        const auto node = static_cast<std::size_t>(use.instancedNode);
        return s + " (" + use.attribute + " of " + named("nodes", node, model.nodes[node].name) + " EXT_mesh_gpu_instancing)";
    }
    const auto& mesh = model.meshes[static_cast<std::size_t>(use.mesh)];
    return s + " (" + use.attribute + " of " + named("meshes", static_cast<std::size_t>(use.mesh), mesh.name) +
           " primitive " + std::to_string(use.primitive) + ")";
}

const Format kPositionFormat{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT", [](const tinygltf::Accessor& a, bool quantized) {
                                 return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                        (quantized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE,
                                                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                                                TINYGLTF_COMPONENT_TYPE_SHORT,
                                                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
                             }};
const Format kNormalFormat{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT", [](const tinygltf::Accessor& a, bool quantized) {
                               return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                      (quantized && a.normalized &&
                                       isOneOf(a.componentType,
                                               {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}));
                           }};
const Format kTexcoordFormat{
    TINYGLTF_TYPE_VEC2, "VEC2 FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT",
    [](const tinygltf::Accessor& a, bool quantized) {
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) return true;
        const bool unsignedType = isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
        const bool signedType =
            isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT});
        return (unsignedType && a.normalized) || (quantized && (unsignedType || signedType));
    }};
const Format kTangentFormat{TINYGLTF_TYPE_VEC4, "VEC4 FLOAT", [](const tinygltf::Accessor& a, bool quantized) {
                                return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                       (quantized && a.normalized &&
                                        isOneOf(a.componentType,
                                                {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}));
                            }};
const Format kColorFormat{TINYGLTF_TYPE_VEC4, "VEC3 or VEC4: FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT",
                          [](const tinygltf::Accessor& a, bool) {
                              return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                     (a.normalized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                                                TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
                          },
                          TINYGLTF_TYPE_VEC3};
const Format kIndexFormat{TINYGLTF_TYPE_SCALAR, "SCALAR UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT",
                          [](const tinygltf::Accessor& a, bool) {
                              return isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
                          }};

namespace {

bool elementsFit(std::size_t offset, std::size_t stride, std::size_t count, std::size_t elementSize,
                 std::size_t limit) {
    if (offset > limit || elementSize > limit - offset) return false;
    const std::size_t room = limit - offset - elementSize;
    return count - 1 == 0 || (stride != 0 && count - 1 <= room / stride);
}

float componentToFloat(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<std::int8_t>(p[0]);
            return normalized ? std::max(v / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
        }
        default: return 0.0f;  // excluded by the format checks
    }
}

std::uint32_t componentToIndex(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

}  // namespace


std::vector<float> AccessorReader::floats(int index, const Use& use, const Format& format, std::size_t maxCount) const {
    const tinygltf::Accessor& a = checked(index, use, format, maxCount);
    const std::size_t n = componentCount(a.type), bytes = componentBytes(a.componentType);
    std::vector<float> out(a.count * n, 0.0f);
    const auto readElement = [&](std::size_t i, const unsigned char* p) {
        for (std::size_t c = 0; c < n; ++c) out[i * n + c] = componentToFloat(p + c * bytes, a.componentType, a.normalized);
    };
    forEachElement(index, a, use, readElement);
    return out;
}

std::vector<std::uint32_t> AccessorReader::indices(int index, const Use& use, std::size_t maxCount) const {
    const tinygltf::Accessor& a = checked(index, use, kIndexFormat, maxCount);
    std::vector<std::uint32_t> out(a.count, 0);
    forEachElement(index, a, use, [&](std::size_t i, const unsigned char* p) { out[i] = componentToIndex(p, a.componentType); });
    return out;
}


void AccessorReader::failAt(int index, const Use& use, const std::string& fault) const {
    fail(path_, describe(model_, index, use) + ": " + fault);
}

const tinygltf::Accessor& AccessorReader::checked(int index, const Use& use, const Format& format, std::size_t maxCount) const {
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];  // index checked by the plan
    if ((a.type != format.type && a.type != format.otherType) || !format.allows(a, quantized_))
        failAt(index, use,
               "type " + typeName(a.type) + " with componentType " + componentTypeName(a.componentType) +
                   (a.normalized ? " (normalized)" : "") + " is not valid for " + use.attribute + " (expected " +
                   format.expected + ")");
    // Elements in a buffer view are bounded by the file; check that first, as the real fault.
    if (a.bufferView >= 0 && a.count > 0) {
        const unsigned char* base = nullptr;
        std::size_t stride = 0;
        locate(index, a, use, componentBytes(a.componentType) * componentCount(a.type), base, stride);
    }
    if (a.count > maxCount)
        failAt(index, use, "count " + std::to_string(a.count) + " is over the limit (" + std::to_string(maxCount) + ")");
    return a;
}

template <class Fn>
void AccessorReader::forEachElement(int index, const tinygltf::Accessor& a, const Use& use, Fn fn) const {
    const std::size_t elementSize = componentBytes(a.componentType) * componentCount(a.type);
    if (a.count > 0 && a.bufferView >= 0) {
        const unsigned char* base = nullptr;
        std::size_t stride = 0;
        locate(index, a, use, elementSize, base, stride);
        for (std::size_t i = 0; i < a.count; ++i) fn(i, base + i * stride);
    }
    if (a.sparse.isSparse) forEachSparse(index, a, use, elementSize, fn);
}

void AccessorReader::locate(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize,
            const unsigned char*& base, std::size_t& stride) const {
    const tinygltf::BufferView& view = viewOf(index, use, a.bufferView, "bufferView");
    if (view.byteStride != 0 && view.byteStride < elementSize)
        failAt(index, use, "byteStride " + std::to_string(view.byteStride) + " of bufferViews[" +
                               std::to_string(a.bufferView) + "] is smaller than an element (" +
                               std::to_string(elementSize) + " bytes)");
    stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (!elementsFit(a.byteOffset, stride, a.count, elementSize, view.byteLength))
        failAt(index, use, "byteOffset " + std::to_string(a.byteOffset) + " + byteStride " + std::to_string(stride) +
                               " * (count " + std::to_string(a.count) + " - 1) + element size " +
                               std::to_string(elementSize) + " overruns bufferViews[" +
                               std::to_string(a.bufferView) + "] (" + std::to_string(view.byteLength) + " bytes)");
    base = bufferBytes(view) + a.byteOffset;
}

template <class Fn>
void AccessorReader::forEachSparse(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize, Fn fn) const {
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > a.count)
        failAt(index, use, "sparse count " + std::to_string(sparse.count) + " is out of range (1.." +
                               std::to_string(a.count) + ")");
    const std::size_t n = static_cast<std::size_t>(sparse.count);
    const int indexType = sparse.indices.componentType;
    if (!isOneOf(indexType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                             TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}))
        failAt(index, use, "sparse indices componentType " + componentTypeName(indexType) + " is not unsigned");
    const std::size_t indexSize = componentBytes(indexType);
    const unsigned char* indices = sparseBytes(index, use, sparse.indices.bufferView, sparse.indices.byteOffset,
                                               n, indexSize, "sparse indices");
    const unsigned char* values = sparseBytes(index, use, sparse.values.bufferView, sparse.values.byteOffset, n,
                                              elementSize, "sparse values");
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t target = componentToIndex(indices + k * indexSize, indexType);
        if (target >= a.count)
            failAt(index, use, "sparse index " + std::to_string(target) + " is out of range (count " +
                                   std::to_string(a.count) + ")");
        fn(target, values + k * elementSize);
    }
}

const unsigned char* AccessorReader::sparseBytes(int index, const Use& use, int viewIndex, int byteOffset, std::size_t count,
                                 std::size_t elementSize, const char* what) const {
    const tinygltf::BufferView& view = viewOf(index, use, viewIndex, what);
    if (byteOffset < 0 || !elementsFit(static_cast<std::size_t>(byteOffset), elementSize, count, elementSize, view.byteLength))
        failAt(index, use, std::string(what) + " (byteOffset " + std::to_string(byteOffset) + ", " +
                               std::to_string(count) + " x " + std::to_string(elementSize) +
                               " bytes) overrun bufferViews[" + std::to_string(viewIndex) + "] (" +
                               std::to_string(view.byteLength) + " bytes)");
    return bufferBytes(view) + byteOffset;
}

const tinygltf::BufferView& AccessorReader::viewOf(int index, const Use& use, int viewIndex, const char* what) const {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model_.bufferViews.size())
        failAt(index, use, std::string(what) + " index " + std::to_string(viewIndex) + " out of range (" +
                               std::to_string(model_.bufferViews.size()) + " buffer views)");
    return model_.bufferViews[static_cast<std::size_t>(viewIndex)];
}

const unsigned char* AccessorReader::bufferBytes(const tinygltf::BufferView& view) const {
    return model_.buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
}

}  // namespace ml::gltf
