// Rewrites a glTF file into variants that must render the same image (issue 61, the layout
// invariance test, tests/gpu/layout_invariance_test.cpp): the same triangles stored another way
// (buffer views interleaved or separate, byte offsets and strides, 8/16/32-bit indices, no
// indices, sparse accessors, one accessor shared by several primitives), vertices no index uses,
// unrelated geometry far away, the node hierarchy baked into the vertices, and the triangles,
// vertices and corners in another order.
//
// It works on tinygltf's model: every primitive's vertex streams are read into tightly packed
// elements of their own component type (no value is converted, so a layout change keeps every bit),
// changed, and written back into a buffer of their own, the file's other buffers, images,
// animations, skins and extensions as they were. Test code: it trusts its input (a file the
// project's loader reads), and refuses what it does not handle with a reason instead of guessing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace ml::test::layout {

// One vertex attribute's elements, as the file stores them (component type, normalisation),
// tightly packed: element i is bytes[i * elementSize, (i + 1) * elementSize).
struct Stream {
    int componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    int type = TINYGLTF_TYPE_VEC3;
    bool normalized = false;
    std::size_t elementSize = 12;
    std::vector<std::uint8_t> bytes;
    std::size_t count() const { return elementSize == 0 ? 0 : bytes.size() / elementSize; }
};

// The vertex streams one or more primitives index into: attributes and morph targets.
struct VertexSet {
    std::map<std::string, Stream> attributes;
    std::vector<std::map<std::string, Stream>> targets;
    std::size_t count() const;
};

struct Primitive {
    std::size_t set = 0;  // into Mesh::sets
    bool indexed = true;
    std::vector<std::uint32_t> indices;
    int indexType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;  // as the file stored it
    int mode = TINYGLTF_MODE_TRIANGLES;
    int material = -1;
    tinygltf::Value extras;
    tinygltf::ExtensionMap extensions;
};

struct Mesh {
    tinygltf::Mesh header;  // name, weights, extras; its primitives are rebuilt from the fields below
    std::vector<VertexSet> sets;
    std::vector<Primitive> primitives;
};

// How the rewritten streams are laid out in the new buffer.
enum class IndexWidth { AsStored, Narrowest, U16, U32 };
enum class Sparse { None, ZeroBase, OverBase };
struct Layout {
    bool interleaved = false;     // a vertex set's attributes in one view with a byteStride
    std::size_t viewPadding = 0;  // bytes of junk before every view in the buffer (a multiple of 4)
    std::size_t accessorOffset = 0;  // separate views: bytes of junk before the elements (accessor byteOffset)
    std::size_t extraStride = 0;  // bytes of junk after every element (separate) or record (interleaved)
    IndexWidth indexWidth = IndexWidth::AsStored;
    // ZeroBase: POSITION without a buffer view (zeros), its non-zero elements substituted by a
    // sparse accessor. OverBase: POSITION and NORMAL over a view of junk, every element substituted.
    Sparse sparse = Sparse::None;
};

// A glTF file read for rewriting, and written back with rewrite's changes.
class Rewriter {
public:
    // Reads the file with tinygltf (images are kept as their files, not decoded).
    explicit Rewriter(const std::filesystem::path& file);

    tinygltf::Model model;     // meshes are rebuilt from `meshes` when written
    std::vector<Mesh> meshes;  // every mesh of the model, its primitives' streams read
    Layout layout;

    // Writes dir/name.gltf with its buffers beside it (name_N.bin) and copies of the image files
    // it refers to. Returns the path.
    std::filesystem::path write(const std::filesystem::path& dir, const std::string& name);

    // --- The changes. Each returns false, with the reason in `why`, where it does not apply. ---

    // `count` vertices before and `count` after every triangle primitive's own (a floor far below
    // and wide of what the primitive draws), which no index uses; the indices shifted past them.
    bool addUnusedVertices(std::size_t count, std::string& why);
    // A new mesh (a square of half-size `halfSize` facing +y at `centre`, in world space) on a
    // new root node of the default scene, with a material of its own.
    bool addFarQuad(const glm::vec3& centre, float halfSize, std::string& why);
    // The triangle primitives of a mesh with the same attribute formats share one set of
    // accessors, each primitive's indices offset by where its vertices start; a mesh with one
    // such primitive has it split in two halves that share its accessors.
    bool shareAccessors(std::string& why);
    // Every triangle primitive drawn without indices (its vertices gathered in index order).
    // Refused where the loader would generate normals or tangents from the index topology.
    bool deindex(std::string& why);
    // Every node's world transform applied to its mesh's vertices (each node instance its own
    // mesh), every node moved to the root of the default scene. Refused for skinned, morphed or
    // animated files and for positions that are not floats.
    bool bakeHierarchy(std::string& why);
    // Triangles of each triangle primitive in a seeded random order.
    bool shuffleTriangles(std::uint32_t seed, std::string& why);
    // Vertices of each vertex set in a seeded random order, the indices remapped.
    bool shuffleVertices(std::uint32_t seed, std::string& why);
    // Each triangle (a, b, c) as (b, c, a): the same winding.
    bool rotateCorners(std::string& why);
    // Whether `layout` changes anything for this file (8-bit indices need a primitive that fits).
    bool layoutApplies(std::string& why) const;

private:
    std::filesystem::path sourceDir_;
    int defaultScene() const;
    // Whether every primitive that uses set `s` of `mesh` draws triangles.
    bool onlyTriangles(const Mesh& mesh, std::size_t s) const;
};

}  // namespace ml::test::layout
