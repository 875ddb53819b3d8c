// glTF 2.0 (.gltf and .glb) into the scene model, through tinygltf 2.7.
//
// The work, in order, each step in a file of its own:
//   gltf_container   read the file (and check a GLB container by hand), pre-check the JSON text,
//                    set aside what tinygltf 2.7 refuses in compressed files (gltf_compressed_json),
//                    let tinygltf parse it, decode EXT_meshopt_compression views (gltf_meshopt),
//                    check the buffers and views tinygltf does not;
//   gltf_draco       decode KHR_draco_mesh_compression primitives into plain accessors;
//   gltf_nodes       flatten the default scene's node trees with an explicit stack;
//   gltf_instancing  expand each EXT_mesh_gpu_instancing node into one mesh instance per TRS;
//   gltf_animation   for a file with animations, skins or morph targets only: the node hierarchy
//                    at rest, the clips and skins, and which instances they move;
//   gltf_geometry    plan each mesh's primitives once and append each instance's triangles in
//                    world space, reading through gltf_accessors (which checks every byte range);
//                    an instance that moves in the mesh's own space, its influences and morph
//                    deltas beside it (gltf_deformation), posed at rest once all are placed;
//   gltf_variants    read KHR_materials_variants' names, and each primitive's mappings as it is planned;
//   gltf_materials   convert materials and their images on first use (a variant's too);
//   gltf_cameras     place the perspective cameras the node trees hold;
//   gltf_lights      place the lights (KHR_lights_punctual) the node trees hold;
//   unreferenced_vertices  drop the vertices no index uses (they are not part of the scene);
// and here, the warnings for what the scene model does not hold. gltf_common holds the limits
// and the one-line messages all of them use.
#include "scenes/gltf_loader.h"

#include <filesystem>
#include <new>
#include <optional>
#include <utility>

#include "scenes/gltf_animation.h"
#include "scenes/gltf_cameras.h"
#include "scenes/gltf_lights.h"
#include "scenes/gltf_common.h"
#include "scenes/gltf_container.h"
#include "scenes/gltf_deformation.h"
#include "scenes/gltf_draco.h"
#include "scenes/gltf_geometry.h"
#include "scenes/gltf_instancing.h"
#include "scenes/gltf_materials.h"
#include "scenes/gltf_nodes.h"
#include "scenes/gltf_variants.h"
#include "scenes/unreferenced_vertices.h"

namespace ml {
namespace {

using namespace gltf;

// --- Warnings ------------------------------------------------------------------------------------

std::size_t skippedPrimitives(const Skipped& skipped) {
    std::size_t total = 0;
    for (const auto& entry : skipped.primitiveModes) total += entry.second;
    return total;
}

// "3 LINES primitives, 1 POINTS primitive".
std::string skippedModes(const Skipped& skipped) {
    static const char* const kModeNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    std::string modes;
    for (const auto& [mode, n] : skipped.primitiveModes) {
        const std::string name = mode >= 0 && mode < 4 ? kModeNames[mode] : "mode " + std::to_string(mode);
        modes += (modes.empty() ? "" : ", ") + std::to_string(n) + " " + name + (n == 1 ? " primitive" : " primitives");
    }
    return modes;
}


// One line per kind of thing the scene model does not hold (materials report their own).
std::vector<std::string> unmodelledFeatures(const tinygltf::Model& model, const Skipped& skipped) {
    std::vector<std::string> lines;
    const auto note = [&](std::size_t n, const std::string& text) {
        if (n > 0) lines.push_back(text);
    };
    note(skipped.orthographicCameras, counted(skipped.orthographicCameras, "orthographic camera", "orthographic cameras") +
                                          " skipped (only perspective cameras are modelled)");

    for (const std::string& ext : model.extensionsUsed)
        if (!isModelledGltfExtension(ext))
            lines.push_back("extension " + clip(ext, 80) + " skipped (not modelled)");

    if (!skipped.primitiveModes.empty())
        lines.push_back(counted(skippedPrimitives(skipped), "primitive", "primitives") +
                        " skipped (points and lines are not drawn): " + skippedModes(skipped));
    note(skipped.withoutPosition, counted(skipped.withoutPosition, "primitive", "primitives") + " without POSITION skipped");
    note(skipped.emptyPrimitives, counted(skipped.emptyPrimitives, "empty primitive", "empty primitives") + " skipped (no triangles)");
    note(skipped.regeneratedNormals, "NORMAL of " + counted(skipped.regeneratedNormals, "primitive", "primitives") +
                                         " held NaN or infinity; normals generated instead");
    note(skipped.regeneratedTangents, "TANGENT of " + counted(skipped.regeneratedTangents, "primitive", "primitives") +
                                          " held NaN or infinity; tangents generated instead");
    note(skipped.repairedTexcoords, "texture coordinates (TEXCOORD_0 or TEXCOORD_1) of " +
                                        counted(skipped.repairedTexcoords, "primitive", "primitives") +
                                        " held NaN or infinity; those set to 0");
    note(skipped.repairedColours, "COLOR_0 of " + counted(skipped.repairedColours, "primitive", "primitives") +
                                      " held NaN or infinity; those set to 1");
    return lines;
}

// Reverses the winding of the triangles from `first` on (a mirroring transform's, put back).
void flipWinding(std::vector<std::uint32_t>& indices, std::size_t first) {
    for (std::size_t t = first; t + 2 < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
}

// Cameras and lights stay where the rest pose puts them: only meshes are animated.
std::size_t movedCamerasAndLights(const FlatScene& flat, const AnimationReader& animation) {
    std::size_t n = 0;
    for (const CameraInstance& c : flat.cameras) n += animation.moves(c.node);
    for (const LightInstance& l : flat.lights) n += animation.moves(l.node);
    return n;
}

Scene loadChecked(const std::string& path, std::vector<std::string>& warnings) {
    ParsedGltf parsed = readGltfContainer(path);
    std::vector<std::string> decodeWarnings = std::move(parsed.warnings);
    for (std::string& line : decodeDracoPrimitives(path, parsed.model)) decodeWarnings.push_back(std::move(line));
    const tinygltf::Model& model = parsed.model;

    Scene scene;
    scene.name = std::filesystem::path(path).stem().string();
    Skipped skipped;
    MaterialConverter materials(path, model, scene);
    SceneBuilder builder(path, model, scene, skipped, materials);
    const AccessorReader instanceReader(path, model, lists(model.extensionsUsed, "KHR_mesh_quantization"));
    std::size_t instanceBudget = kMaxInstances;
    scene.materialVariants.names = readVariantNames(path, model);
    std::vector<std::optional<MeshPlan>> plans(model.meshes.size());
    const FlatScene flat = flattenNodes(path, model);
    // Only a file with something that moves pays for animation.
    std::optional<AnimationReader> animation;
    std::optional<DeformationBuilder> deformation;
    if (hasAnimation(model)) {
        animation.emplace(path, model, instanceReader);
        deformation.emplace(path, model, instanceReader, animation->animation());
    }
    for (const MeshInstance& instance : flat.meshes) {
        std::optional<MeshPlan>& plan = plans[instance.mesh];
        if (!plan) plan = planMesh(path, model, instance.mesh, scene.materialVariants.names.size(), skipped);
        for (const MeshInstance& placed : gpuInstances(path, model, instanceReader, instance, instanceBudget)) {
            if (!animation || !animation->deforms(placed)) {
                builder.addInstance(placed, *plan);
                continue;
            }
            // Placed in the mesh's own space; the pose puts it in the world.
            const auto firstVertex = static_cast<std::uint32_t>(scene.vertices.size());
            const std::size_t firstIndex = scene.indices.size();
            MeshInstance local = placed;
            local.world = glm::dmat4(1.0);
            const std::vector<std::uint32_t> bases = builder.addInstance(local, *plan);
            // A skinned mesh ignores its node's transform (glTF), so only a node-placed one mirrors.
            const bool mirrored = model.nodes[placed.node].skin < 0 && glm::determinant(glm::dmat3(placed.world)) < 0.0;
            if (mirrored) flipWinding(scene.indices, firstIndex);
            deformation->add(placed, *plan, bases, firstVertex, static_cast<std::uint32_t>(scene.vertices.size()) - firstVertex);
        }
    }
    if (scene.indices.empty())
        fail(path, "the scene has no triangles to draw " +
                       (skipped.primitiveModes.empty() ? std::string("(empty scene)") : "(skipped: " + skippedModes(skipped) + ")"));
    builder.finish();
    if (deformation) deformation->finish(scene, std::move(animation->animation()));
    scene.cameras = convertCameras(path, model, flat.cameras, skipped.orthographicCameras);
    scene.lights = convertLights(path, model, flat.lights);
    dropUnreferencedVertices(scene);
    computeBounds(scene);

    for (const std::string& line : unmodelledFeatures(model, skipped)) warnings.push_back(path + ": " + line);
    if (animation) {
        for (const std::string& line : animation->warnings()) warnings.push_back(path + ": " + line);
        for (const std::string& line : deformation->warnings()) warnings.push_back(path + ": " + line);
        if (const std::size_t n = movedCamerasAndLights(flat, *animation); n > 0)
            warnings.push_back(path + ": " + counted(n, "camera or light", "cameras and lights") +
                               " on animated nodes stay where the rest pose puts them (only meshes are animated)");
    }
    for (const std::string& line : materials.warnings()) warnings.push_back(path + ": " + line);
    for (const std::string& line : decodeWarnings) warnings.push_back(path + ": " + line);
    if (!parsed.tinygltfWarnings.empty()) warnings.push_back(path + ": glTF parser: " + parsed.tinygltfWarnings);
    scene.extensionsUsed = model.extensionsUsed;
    return scene;
}

}  // namespace

bool isModelledGltfExtension(const std::string& name) {
    // Lights (gltf_lights) and what the materials read (gltf_materials); quantized attributes
    // are read by the accessors; compressed geometry is decoded (gltf_draco, gltf_meshopt) and
    // GPU instances flattened (gltf_instancing).
    return name == "KHR_lights_punctual" || name == "KHR_mesh_quantization" || name == "KHR_texture_transform" ||
           name == "KHR_materials_emissive_strength" || name == "KHR_materials_unlit" || name == "KHR_materials_ior" ||
           name == "KHR_materials_specular" || name == "KHR_materials_clearcoat" || name == "KHR_materials_sheen" ||
           name == "KHR_materials_anisotropy" ||
           name == "KHR_materials_iridescence" || name == "KHR_materials_transmission" || name == "KHR_materials_volume" ||
           name == "KHR_materials_pbrSpecularGlossiness" || name == "KHR_materials_variants" ||
           name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression" || name == "EXT_mesh_gpu_instancing";
}

Scene loadGltf(const std::string& path, std::vector<std::string>& warnings) {
    try {
        return loadChecked(path, warnings);
    } catch (const std::bad_alloc&) {
        // The limits keep input from asking for more than a few GiB, which a machine may still lack.
        fail(path, "out of memory while loading");
    }
}

}  // namespace ml
