// Accessors: the formats glTF allows for each vertex attribute and for indices, and a reader
// that checks every index and byte range of an accessor before reading it. Internal to
// scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

// What an accessor is read for, so that a message can say which mesh (or instanced node) it
// belongs to.
struct Use {
    const char* attribute;  // "POSITION", "NORMAL", "TEXCOORD_0", "indices", "TRANSLATION"
    int mesh;
    int primitive;
    int instancedNode = -1;  // EXT_mesh_gpu_instancing's attributes belong to a node, not a primitive
    // Animation data belongs to neither: "animations[0] 'Walk' samplers[2]", "skins[1] 'Armature'".
    const std::string* owner = nullptr;
};


// Bytes of one component (0 for what glTF 2.0 does not define) and components of one element.
std::size_t componentBytes(int componentType);
std::size_t componentCount(int type);

// "accessors[4] (NORMAL of meshes[0] 'Body' primitive 2)",
// "accessors[7] (ROTATION of nodes[3] 'Trees' EXT_mesh_gpu_instancing)",
// "accessors[9] (output of animations[0] 'Walk' samplers[2])".
std::string describe(const tinygltf::Model& model, int accessor, const Use& use);

// The formats glTF 2.0 allows for each use; KHR_mesh_quantization widens those of vertex data.
struct Format {
    int type;
    const char* expected;  // for messages
    bool (*allows)(const tinygltf::Accessor&, bool quantized);
    int otherType = -1;    // a second accepted type (COLOR_0 is VEC3 or VEC4)
};

extern const Format kPositionFormat;
extern const Format kNormalFormat;
extern const Format kTexcoordFormat;
extern const Format kTangentFormat;
extern const Format kColorFormat;
extern const Format kIndexFormat;

// Reads accessors for one file: every index and byte range is checked before it is used.
class AccessorReader {
public:
    AccessorReader(const std::string& path, const tinygltf::Model& model, bool quantized)
        : path_(path), model_(model), quantized_(quantized) {}

    // count * components floats, after integer normalisation and sparse substitution.
    // maxCount bounds the allocation for accessors whose elements are not in the file.
    std::vector<float> floats(int index, const Use& use, const Format& format, std::size_t maxCount) const;

    std::vector<std::uint32_t> indices(int index, const Use& use, std::size_t maxCount) const;

    std::size_t count(int index) const { return model_.accessors[static_cast<std::size_t>(index)].count; }

private:
    [[noreturn]] void failAt(int index, const Use& use, const std::string& fault) const;
    const tinygltf::Accessor& checked(int index, const Use& use, const Format& format, std::size_t maxCount) const;
    // Calls fn(i, bytes of element i) for every element in the buffer view, then for every sparse
    // substitute. Elements of an accessor without a buffer view are zeros and are not visited.
    template <class Fn>
    void forEachElement(int index, const tinygltf::Accessor& a, const Use& use, Fn fn) const;
    void locate(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize,
                const unsigned char*& base, std::size_t& stride) const;
    template <class Fn>
    void forEachSparse(int index, const tinygltf::Accessor& a, const Use& use, std::size_t elementSize, Fn fn) const;
    // Sparse indices and values are tightly packed (the spec forbids a stride on their views).
    const unsigned char* sparseBytes(int index, const Use& use, int viewIndex, int byteOffset, std::size_t count,
                                     std::size_t elementSize, const char* what) const;
    const tinygltf::BufferView& viewOf(int index, const Use& use, int viewIndex, const char* what) const;
    // Views were checked against their buffers by the container checks.
    const unsigned char* bufferBytes(const tinygltf::BufferView& view) const;

    const std::string& path_;
    const tinygltf::Model& model_;
    bool quantized_;
};

}  // namespace ml::gltf
