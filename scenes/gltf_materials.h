// glTF materials and their textures into the scene model's Material and Image
// (docs/lights-and-shading.md). Internal to scenes/gltf_*.cpp; kept apart from geometry so that the
// material mapping can change without touching the rest of the loader.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_common.h"
#include "scenes/scene.h"

namespace ml::gltf {

inline constexpr const char* kSpecularGlossiness = "KHR_materials_pbrSpecularGlossiness";

// Converts materials on first use and appends them (and the images they read) to the scene.
class MaterialConverter {
public:
    MaterialConverter(const std::string& path, const tinygltf::Model& model, Scene& scene)
        : path_(path),
          model_(model),
          scene_(scene),
          materialSlots_(model.materials.size(), -1),
          imageSlots_{std::vector<int>(model.images.size(), -1), std::vector<int>(model.images.size(), -1)},
          samplerSlots_(model.samplers.size(), -1) {}

    // The Scene::materials index for a glTF material; -1 (no material) is glTF's default, white.
    // The index was checked by the caller. `meshScale`: the drawing node's scale (the mean of its
    // world matrix's column lengths); a volume's thickness is in the mesh's units, so a material
    // with one is copied once per scale it is drawn at, its thickness scaled into world units.
    std::uint32_t materialFor(int gltfMaterial, double meshScale = 1.0);

    // One line per kind of material feature the scene model does not hold, or that was repaired.
    std::vector<std::string> warnings() const;

private:
    Material convertMaterial(std::size_t index);
    // A textureInfo's texture as the scene holds it; `what` names it in messages
    // ("materials[2] 'Leaves' normalTexture"). `srgb`: a colour texture (base colour, emissive).
    TextureRef textureRef(const std::string& what, int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions,
                          bool srgb);
    // A textureInfo given inside a material extension (a JSON object: index, texCoord, extensions).
    TextureRef extensionTextureRef(const std::string& what, const tinygltf::Value& info, bool srgb);
    // KHR_materials_unlit, KHR_materials_ior and KHR_materials_specular into m.
    void convertMaterialExtensions(const tinygltf::Material& source, const std::string& what, Material& m);
    // KHR_materials_pbrSpecularGlossiness (the extension's object) into m's base colour,
    // roughness and KHR_materials_specular F0, in place of the metallic-roughness block
    // (docs/gltf.md says what it keeps and what it changes).
    void convertSpecularGlossiness(const tinygltf::Value& specularGlossiness, const std::string& what, Material& m);
    int imageFor(std::size_t index, bool srgb);
    int samplerFor(std::size_t index);

    const std::string& path_;
    const tinygltf::Model& model_;
    Scene& scene_;
    std::vector<int> materialSlots_;  // glTF material -> Scene::materials index
    std::map<std::pair<int, double>, std::uint32_t> scaledVolumes_;  // (glTF material, mesh scale) -> its copy
    std::vector<int> imageSlots_[2];  // glTF image -> Scene::images index, [0] linear, [1] sRGB
    std::vector<int> samplerSlots_;   // glTF sampler -> Scene::samplers index
    std::optional<std::uint32_t> defaultMaterial_;
    // Roughness maps baked from specular-glossiness maps: (sRGB Scene::images index, glossinessFactor) -> Scene::images index.
    std::map<std::pair<int, float>, int> bakedRoughness_;
    std::uint64_t texelBudget_ = kMaxImageTexels;
    // Counts of what was skipped or approximated, each reported once as a warning.
    std::size_t texturesWithoutSource_ = 0;
    std::vector<std::string> failedImages_;
};

// --- What a material asks of the geometry --------------------------------------------------------
// The vertex streams a primitive needs follow from its material: TEXCOORD_1 where a texture reads
// UV set 1, tangents where there is a normal texture or an anisotropic lobe.

// A texture a material reads, and the UV set it reads it through.
struct MaterialTexture {
    const char* slot;  // "baseColorTexture", "normalTexture", ...
    double texCoord;   // the textureInfo's texCoord, or KHR_texture_transform's override
};

// The textureInfos of a material that name a texture (index >= 0).
std::vector<MaterialTexture> texturesOf(const tinygltf::Material& material);

// Does the material read the tangent stream: a normal texture (its own or its coat's), or an
// anisotropic lobe (KHR_materials_anisotropy)?
bool needsTangents(const tinygltf::Material& material);
// The UV set generated tangents follow: the normal texture's, else the coat's normal texture's, else
// the anisotropy texture's (0 where the material needs no tangents or its maps read TEXCOORD_0).
int tangentTexCoord(const tinygltf::Material& material);
bool usesTexCoord1(const tinygltf::Material& material);

// Throws "<path>: materials[i] 'name': normalTexture reads texCoord 2 ..." for a texture that
// reads a UV set other than 0 or 1 (the scene model holds two).
void checkTexCoords(const std::string& path, const tinygltf::Model& model, std::size_t material);

}  // namespace ml::gltf
