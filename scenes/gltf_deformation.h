// The per-vertex data that skins and morph targets need, for each mesh instance an animation
// moves: JOINTS_0/WEIGHTS_0 (and _1), the morph targets' POSITION, NORMAL and TANGENT deltas,
// and the rest position, normal and tangent in the mesh's own space. Internal to scenes/gltf_*.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_geometry.h"
#include "scenes/gltf_nodes.h"
#include "scenes/scene.h"

namespace ml::gltf {

class DeformationBuilder {
public:
    DeformationBuilder(const std::string& path, const tinygltf::Model& model, const AccessorReader& reader,
                       SceneAnimation& animation)
        : path_(path), model_(model), reader_(reader), animation_(animation) {}

    // A mesh instance SceneBuilder has just placed in the mesh's own space (world = identity;
    // where its node mirrors, the loader has flipped the winding back as for a static instance):
    // its vertices are the scene's [firstVertex, firstVertex + vertexCount), group g's block
    // starting at groupBases[g]. Reads the influences (a skinned node) and the morph deltas of
    // each vertex group from its first primitive (primitives that share a group share POSITION,
    // and glTF has them share these too). Each fault is one line naming the accessor.
    void add(const MeshInstance& instance, const MeshPlan& plan, const std::vector<std::uint32_t>& groupBases,
             std::uint32_t firstVertex, std::uint32_t vertexCount);

    // After SceneBuilder::finish: takes every deformed vertex's rest data from the scene (where
    // it is still in the mesh's space), hands the animation to the scene, and poses the scene at
    // rest (world space, as the rest of the scene).
    void finish(Scene& scene, SceneAnimation&& animation);

    // Morph target attributes other than POSITION, NORMAL and TANGENT, left out (one line).
    std::vector<std::string> warnings() const;

private:
    void readInfluences(const MeshInstance& instance, const VertexGroup& group, std::size_t firstRest, std::size_t count,
                        const Skin& skin);
    void readMorphDeltas(const MeshInstance& instance, const VertexGroup& group, const DeformedMesh& mesh,
                         std::size_t local, std::size_t count);

    const std::string& path_;
    const tinygltf::Model& model_;
    const AccessorReader& reader_;
    SceneAnimation& animation_;
    std::size_t skippedMorphAttributes_ = 0;
    std::string skippedMorphAttribute_;
};

}  // namespace ml::gltf
