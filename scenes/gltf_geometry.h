// glTF meshes into triangles: which accessors each primitive reads (planMesh), and how each mesh
// instance's vertices and indices land in the scene in world space (SceneBuilder). Internal to
// scenes/gltf_*.cpp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_common.h"
#include "scenes/gltf_materials.h"
#include "scenes/gltf_nodes.h"
#include "scenes/scene.h"

namespace ml::gltf {

// Counts of what was skipped or repaired, each reported once as a warning.
struct Skipped {
    std::map<int, std::size_t> primitiveModes;  // POINTS, LINES, LINE_LOOP, LINE_STRIP (or unknown) -> primitives
    std::size_t withoutPosition = 0;
    std::size_t emptyPrimitives = 0;
    std::size_t regeneratedNormals = 0;   // primitives whose NORMAL held NaN or infinity
    std::size_t regeneratedTangents = 0;  // primitives whose TANGENT held NaN or infinity
    std::size_t repairedTexcoords = 0;    // TEXCOORD_0 or TEXCOORD_1 with NaN or infinity
    std::size_t repairedColours = 0;
    std::size_t orthographicCameras = 0;
};

// Primitives that share their vertex attributes (one big vertex buffer drawn in several material
// runs) share one block of vertices per instance rather than each copying all of it.
struct VertexGroup {
    // Accessors; -1 where absent.
    int position = -1, normal = -1, texcoord = -1, texcoord1 = -1, color = -1, tangent = -1;
    int firstPrimitive = 0;  // names the group in messages
    // What the group's primitives' materials ask for: a stream is read only when one does.
    bool readsTexcoord1 = false;
    bool needsTangents = false;
};

struct PrimitivePlan {
    int primitive;
    std::size_t group;
    int indices;   // accessor, or -1
    int material;  // glTF material, or -1
    int mode;      // TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN
    bool readsTexcoord1 = false;
    bool normalMapped = false;
    int normalTexCoord = 0;  // the UV set tangents are generated from
    // KHR_materials_variants: the glTF material under each of the file's variants (its own where
    // no mapping lists one); empty where the primitive has no mappings.
    std::vector<int> variantMaterials;
};

// How one glTF mesh becomes triangles, worked out once however many nodes instance it, so that a
// mesh with a million empty primitives costs one pass, not one per instance.
struct MeshPlan {
    std::vector<VertexGroup> groups;
    std::vector<PrimitivePlan> primitives;
};
// `variantCount`: the file's KHR_materials_variants (readVariantNames), whose mappings each
// primitive is checked against.
MeshPlan planMesh(const std::string& path, const tinygltf::Model& model, std::size_t meshIndex, std::size_t variantCount,
                  Skipped& skipped);

// Builds the scene from mesh instances: vertices in world space, materials through the converter.
class SceneBuilder {
public:
    SceneBuilder(const std::string& path, const tinygltf::Model& model, Scene& scene, Skipped& skipped,
                 MaterialConverter& materials)
        : path_(path),
          model_(model),
          scene_(scene),
          skipped_(skipped),
          materials_(materials),
          reader_(path, model, lists(model.extensionsUsed, "KHR_mesh_quantization")) {}

    // Appends the instance's vertices (one block per vertex group, in plan order, one after
    // another) and triangles; returns where each group's block starts.
    std::vector<std::uint32_t> addInstance(const MeshInstance& instance, const MeshPlan& plan);

    // One draw range per material (instances append in node order, so a material recurs), or per
    // set of materials a primitive takes under the file's variants (scene.materialVariants, whose
    // names the loader set), and the optional streams dropped where no drawn primitive asked for them.
    void finish();

private:
    struct Block {
        std::uint32_t base = 0;
        std::uint32_t count = 0;
        bool generateNormals = false;
        bool generateTangents = false;
    };
    using Ranges = std::vector<std::pair<std::size_t, std::size_t>>;

    Block appendVertices(const MeshInstance& instance, const VertexGroup& group, const glm::dmat3& normalMatrix,
                         bool mirrored);
    std::vector<float> readRepaired(const VertexGroup& group, const MeshInstance& instance, int accessor,
                                    const char* attribute, const Format& format, std::size_t count, float replacement,
                                    std::size_t& repairs) const;
    void appendTriangles(const MeshInstance& instance, const PrimitivePlan& prim, const Block& block, bool mirrored);
    // The index into materialSets_ of the primitive's materials: its default, then one a variant;
    // volumes' thicknesses scaled by `meshScale` (MaterialConverter::materialFor).
    std::uint32_t materialSetOf(const PrimitivePlan& prim, double meshScale);
    void generateNormals(const Block& block, const Ranges& ranges);

    // Optional streams (Scene::colors, uv1, tangents): once a stream exists, every vertex appended
    // gets an element, its own or the default.
    template <class T>
    void appendToStream(std::vector<T>& stream, const std::vector<T>& values, std::size_t base, std::size_t count,
                        const T& defaultValue);

    const std::string& path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    Skipped& skipped_;
    MaterialConverter& materials_;
    AccessorReader reader_;
    std::vector<DrawRange> runs_;  // per primitive instance, before grouping; material: a materialSets_ index
    std::vector<std::vector<std::uint32_t>> materialSets_;  // Scene::materials indices: default, then per variant
    std::map<std::vector<std::uint32_t>, std::uint32_t> materialSetIndex_;
    // Whether a drawn primitive asked for each optional stream.
    bool colorsDrawn_ = false, uv1Drawn_ = false, tangentsDrawn_ = false;
};

}  // namespace ml::gltf
