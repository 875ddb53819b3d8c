// The glTF loader's materials: what a file's material says reaches the scene model, once and in
// the right colour space, and every bad value is refused in one line that names it.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

// One triangle drawn with `material`, with a 1x1 white PNG as texture 0 (sampler 0 when given).
Gltf withMaterial(const json& material, const json& sampler = json()) {
    Gltf g;
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, {255, 255, 255, 255}))}});
    json texture = {{"source", 0}};
    if (!sampler.is_null()) texture["sampler"] = g.add("samplers", sampler);
    g.add("textures", texture);
    g.add("materials", material);
    json p = trianglePrimitive(g, true, 0);
    p["attributes"]["TEXCOORD_0"] = g.vec2({{0, 0}, {1, 0}, {0, 1}});
    g.scene({g.node({{"mesh", g.mesh({p})}})});
    return g;
}

TEST(GltfMaterials, EveryFactorAndTextureReachesTheSceneModel) {
    const json material = {
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}},
          {"metallicFactor", 0.3},
          {"roughnessFactor", 0.6},
          {"baseColorTexture", {{"index", 0}}},
          {"metallicRoughnessTexture",
           {{"index", 0},
            {"extensions", {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.5}, {"scale", {2.0, 3.0}}}}}}}}}},
        {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
        {"occlusionTexture", {{"index", 0}, {"strength", 0.25}}},
        {"emissiveFactor", {1.0, 0.5, 0.0}},
        {"emissiveTexture", {{"index", 0}}},
        {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
        {"alphaMode", "MASK"},
        {"alphaCutoff", 0.3},
        {"doubleSided", true}};
    Gltf g = withMaterial(material, {{"magFilter", 9728}, {"minFilter", 9984}, {"wrapS", 33071}, {"wrapT", 33648}});
    g.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength"};
    std::vector<std::string> warnings;
    const Scene s = load(g.writeGltf(testDir(), "material"), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_FLOAT_EQ(m.metallic, 0.3f);
    EXPECT_FLOAT_EQ(m.roughness, 0.6f);
    EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
    expectNear(m.emissive, {4.0f, 2.0f, 0.0f});
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_EQ(m.metallicRoughnessTexture.transform.offset, glm::vec2(0.5f, 0.25f));
    EXPECT_EQ(m.metallicRoughnessTexture.transform.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_FLOAT_EQ(m.metallicRoughnessTexture.transform.rotation, 0.5f);
    EXPECT_TRUE(m.baseColorTexture.transform.isIdentity());
    // One image, read as colour (base colour, emissive) and as data (the rest): held once per colour space.
    ASSERT_EQ(s.images.size(), 2u);
    EXPECT_EQ(m.baseColorTexture.image, m.emissiveTexture.image);
    EXPECT_TRUE(s.images[static_cast<std::size_t>(m.baseColorTexture.image)].srgb);
    EXPECT_EQ(m.normalTexture.image, m.metallicRoughnessTexture.image);
    EXPECT_EQ(m.normalTexture.image, m.occlusionTexture.image);
    EXPECT_FALSE(s.images[static_cast<std::size_t>(m.normalTexture.image)].srgb);
    ASSERT_EQ(s.samplers.size(), 1u);
    EXPECT_EQ(s.samplers[0].magFilter, 9728);
    EXPECT_EQ(s.samplers[0].minFilter, 9984);
    EXPECT_EQ(s.samplers[0].wrapS, 33071);
    EXPECT_EQ(s.samplers[0].wrapT, 33648);
    EXPECT_EQ(m.baseColorTexture.sampler, 0);
    // A normal map asks for tangents: generated here, one per vertex.
    EXPECT_EQ(s.tangents.size(), s.vertices.size());
}

TEST(GltfMaterials, GltfDefaultsAreMetallicAndRough) {
    const Scene s = load(withMaterial(json::object()).writeGltf(testDir(), "defaults"));
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.metallic, 1.0f);  // glTF's defaults, not the procedural scenes'
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
    EXPECT_TRUE(s.tangents.empty()) << "no normal map, no tangent stream";
    EXPECT_TRUE(s.images.empty()) << "no texture read, no image decoded";
}

TEST(GltfMaterials, BlendIsLoadedAsBlendedWithoutWarning) {
    std::vector<std::string> warnings;
    const fs::path file = withMaterial({{"alphaMode", "BLEND"}}).writeGltf(testDir(), "blend");
    const Scene s = load(file, warnings);
    EXPECT_EQ(s.materials.at(0).alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(s.materials.at(0).blended());
    EXPECT_FALSE(s.materials.at(0).alphaTested()) << "BLEND ignores alphaCutoff";
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);
}

// KHR_materials_ior, KHR_materials_specular and KHR_materials_unlit load into the material and
// warn about nothing; unlit ignores the other two, as the extension asks.
TEST(GltfMaterials, IorSpecularAndUnlitAreRead) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}},
                                           {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {2.0, 1.0, 0.5}},
                                                                       {"specularColorTexture", {{"index", 0}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "specular"), warnings);
    EXPECT_FLOAT_EQ(s.materials.at(0).ior, 1.33f);
    EXPECT_FLOAT_EQ(s.materials.at(0).specularFactor, 0.5f);
    EXPECT_EQ(s.materials.at(0).specularColorFactor, glm::vec3(2.0f, 1.0f, 0.5f));
    EXPECT_TRUE(s.materials.at(0).specularColorTexture.present());
    EXPECT_FALSE(s.materials.at(0).specularTexture.present());
    EXPECT_TRUE(s.materials.at(0).specularModelled());
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);

    Gltf u = withMaterial({{"extensions", {{"KHR_materials_unlit", json::object()}, {"KHR_materials_ior", {{"ior", 2.0}}}}}});
    u.doc["extensionsUsed"] = {"KHR_materials_unlit", "KHR_materials_ior"};
    warnings.clear();
    s = load(u.writeGltf(dir, "unlit"), warnings);
    EXPECT_TRUE(s.materials.at(0).unlit);
    EXPECT_FALSE(s.materials.at(0).specularModelled());
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);
}

// KHR_materials_clearcoat loads its factors, maps and the normal map's scale, warns about nothing,
// and a factor of 0 is no coat whatever else the extension holds.
TEST(GltfMaterials, ClearcoatIsRead) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.25},
                                                                        {"clearcoatTexture", {{"index", 0}}},
                                                                        {"clearcoatNormalTexture", {{"index", 0}, {"scale", 0.5}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "clearcoat"), warnings);
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.clearcoatFactor, 0.75f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughnessFactor, 0.25f);
    EXPECT_TRUE(m.clearcoatTexture.present());
    EXPECT_FALSE(m.clearcoatRoughnessTexture.present());
    EXPECT_TRUE(m.clearcoatNormalTexture.present());
    EXPECT_FLOAT_EQ(m.clearcoatNormalScale, 0.5f);
    EXPECT_TRUE(m.clearcoatModelled());
    EXPECT_FALSE(s.tangents.empty()) << "the coat's normal map needs tangents as the material's own does";
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);

    Gltf off = withMaterial({{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatRoughnessFactor", 0.5}}}}}});
    warnings.clear();
    s = load(off.writeGltf(dir, "no_coat"), warnings);
    EXPECT_FALSE(s.materials.at(0).clearcoatModelled()) << "glTF's default clearcoatFactor is 0";
}

// KHR_materials_pbrSpecularGlossiness: the diffuse is the base colour, metallic 0, the specular
// colour the dielectric's F0 (ior 0, weight 1), and glossiness in the map's alpha becomes the
// roughness of a metallic-roughness map baked at load: G = 1 - glossinessFactor x A, B = 0.
TEST(GltfMaterials, SpecularGlossinessBecomesMetallicRoughnessAndSpecular) {
    const fs::path dir = testDir();
    Gltf g;
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(2, 1, {200, 100, 50, 255, 10, 20, 30, 51}))}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.1, 0.1, 1.0}}, {"metallicFactor", 1.0}}},
                        {"extensions",
                         {{"KHR_materials_pbrSpecularGlossiness",
                           {{"diffuseFactor", {0.5, 0.25, 1.0, 0.75}},
                            {"specularFactor", {0.9, 0.6, 0.3}},
                            {"glossinessFactor", 0.8},
                            {"diffuseTexture", {{"index", 0}}},
                            {"specularGlossinessTexture", {{"index", 0}}}}}}}});
    g.add("materials", {{"extensions", {{"KHR_materials_pbrSpecularGlossiness", {{"glossinessFactor", 0.3}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    json textured = trianglePrimitive(g, true, 0);
    textured["attributes"]["TEXCOORD_0"] = g.vec2({{0, 0}, {1, 0}, {0, 1}});
    json factors = primitive({{"POSITION", g.vec3({{5, 0, 0}, {6, 0, 0}, {5, 1, 0}})}}, g.indices({0, 1, 2}), 1);
    g.scene({g.node({{"mesh", g.mesh({textured, factors})}})});
    std::vector<std::string> warnings;
    const Scene s = load(g.writeGltf(dir, "specgloss"), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);
    ASSERT_EQ(s.materials.size(), 2u);

    const Material& m = s.materials[0];
    EXPECT_EQ(m.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f)) << "the diffuse, not the fallback block";
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.roughness, 1.0f) << "the baked map holds the roughness";
    EXPECT_EQ(m.ior, 0.0f);
    EXPECT_EQ(m.specularFactor, 1.0f);
    EXPECT_EQ(m.specularColorFactor, glm::vec3(0.9f, 0.6f, 0.3f));
    EXPECT_TRUE(m.specularModelled());
    ASSERT_TRUE(m.baseColorTexture.present() && m.specularColorTexture.present() && m.metallicRoughnessTexture.present());
    EXPECT_EQ(m.baseColorTexture.image, m.specularColorTexture.image) << "one sRGB copy for diffuse and specular";
    EXPECT_TRUE(s.images.at(static_cast<std::size_t>(m.specularColorTexture.image)).srgb);
    const Image& baked = s.images.at(static_cast<std::size_t>(m.metallicRoughnessTexture.image));
    EXPECT_FALSE(baked.srgb);
    ASSERT_EQ(baked.rgba8.size(), 8u);
    EXPECT_EQ(baked.rgba8[1], std::lround(255.0 * (1.0 - 0.8)));               // A 255: roughness 0.2
    EXPECT_EQ(baked.rgba8[5], std::lround(255.0 * (1.0 - 0.8 * 51.0 / 255.0)));  // A 51: roughness 0.84
    EXPECT_EQ(baked.rgba8[2], 0);
    EXPECT_EQ(baked.rgba8[6], 0);
    EXPECT_EQ(s.images.size(), 2u) << "the sRGB map and its baked roughness, nothing else";

    const Material& plain = s.materials[1];
    EXPECT_EQ(plain.baseColorFactor, glm::vec4(1.0f));
    EXPECT_FLOAT_EQ(plain.roughness, 0.7f);
    EXPECT_EQ(plain.specularColorFactor, glm::vec3(1.0f));
    EXPECT_FALSE(plain.metallicRoughnessTexture.present());
    EXPECT_EQ(plain.ior, 0.0f);
}

// KHR_materials_sheen loads its factors and maps (the colour's as sRGB), warns about nothing, and
// a colour of 0 is no sheen whatever else the extension holds.
TEST(GltfMaterials, SheenIsRead) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 0.25, 1.0}}, {"sheenRoughnessFactor", 0.75},
                                                                    {"sheenColorTexture", {{"index", 0}}},
                                                                    {"sheenRoughnessTexture", {{"index", 0}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_sheen"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "sheen"), warnings);
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.sheenColorFactor, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_FLOAT_EQ(m.sheenRoughnessFactor, 0.75f);
    EXPECT_TRUE(m.sheenColorTexture.present());
    EXPECT_TRUE(m.sheenRoughnessTexture.present());
    EXPECT_NE(m.sheenColorTexture.image, m.sheenRoughnessTexture.image) << "one image as sRGB colour and as linear roughness";
    EXPECT_TRUE(m.sheenModelled());
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);

    Gltf off = withMaterial({{"extensions", {{"KHR_materials_sheen", {{"sheenRoughnessFactor", 0.5}, {"sheenColorTexture", {{"index", 0}}}}}}}});
    warnings.clear();
    s = load(off.writeGltf(dir, "no_sheen"), warnings);
    EXPECT_FALSE(s.materials.at(0).sheenModelled()) << "glTF's default sheenColorFactor is 0";
}

// KHR_materials_anisotropy loads its strength, rotation and map, warns about nothing, and gets the
// tangents a file without TANGENT leaves out (generated, as for a normal map); a strength of 0 is
// the isotropic lobe whatever else the extension holds, and asks for no tangents.
TEST(GltfMaterials, AnisotropyIsReadAndGetsTangents) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyRotation", -7.5},
                                                                         {"anisotropyTexture", {{"index", 0}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "anisotropy"), warnings);
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.anisotropyStrength, 0.6f);
    EXPECT_FLOAT_EQ(m.anisotropyRotation, -7.5f) << "any finite angle";
    EXPECT_TRUE(m.anisotropyTexture.present());
    EXPECT_FALSE(s.images.at(static_cast<std::size_t>(m.anisotropyTexture.image)).srgb) << "a direction: linear";
    EXPECT_TRUE(m.anisotropyModelled());
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);
    ASSERT_EQ(s.tangents.size(), s.vertices.size()) << "no TANGENT in the file: generated";
    for (const glm::vec4& t : s.tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
        EXPECT_EQ(std::abs(t.w), 1.0f);
    }

    Gltf off = withMaterial({{"extensions", {{"KHR_materials_anisotropy", {{"anisotropyRotation", 0.5}, {"anisotropyTexture", {{"index", 0}}}}}}}});
    warnings.clear();
    s = load(off.writeGltf(dir, "no_anisotropy"), warnings);
    EXPECT_FALSE(s.materials.at(0).anisotropyModelled()) << "glTF's default anisotropyStrength is 0";
    EXPECT_TRUE(s.tangents.empty()) << "an isotropic lobe needs no tangents";
}

// KHR_materials_iridescence loads its factors and maps with glTF's defaults (ior 1.3, 100 to 400 nm),
// warns about nothing, and a factor of 0 is no film whatever else the extension holds.
TEST(GltfMaterials, IridescenceIsRead) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.75}, {"iridescenceIor", 1.8},
                                                                          {"iridescenceThicknessMinimum", 200.0},
                                                                          {"iridescenceThicknessMaximum", 600.0},
                                                                          {"iridescenceTexture", {{"index", 0}}},
                                                                          {"iridescenceThicknessTexture", {{"index", 0}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_iridescence"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "iridescence"), warnings);
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.iridescenceFactor, 0.75f);
    EXPECT_FLOAT_EQ(m.iridescenceIor, 1.8f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMinimum, 200.0f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMaximum, 600.0f);
    EXPECT_TRUE(m.iridescenceTexture.present());
    EXPECT_TRUE(m.iridescenceThicknessTexture.present());
    EXPECT_EQ(m.iridescenceTexture.image, m.iridescenceThicknessTexture.image) << "both linear: one image";
    EXPECT_TRUE(m.iridescenceModelled());
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);

    Gltf defaults = withMaterial({{"extensions", {{"KHR_materials_iridescence", {{"iridescenceFactor", 1.0}}}}}});
    warnings.clear();
    s = load(defaults.writeGltf(dir, "iridescence_defaults"), warnings);
    EXPECT_FLOAT_EQ(s.materials.at(0).iridescenceIor, 1.3f);
    EXPECT_FLOAT_EQ(s.materials.at(0).iridescenceThicknessMinimum, 100.0f);
    EXPECT_FLOAT_EQ(s.materials.at(0).iridescenceThicknessMaximum, 400.0f);

    Gltf off = withMaterial({{"extensions", {{"KHR_materials_iridescence", {{"iridescenceTexture", {{"index", 0}}}}}}}});
    warnings.clear();
    s = load(off.writeGltf(dir, "no_iridescence"), warnings);
    EXPECT_FALSE(s.materials.at(0).iridescenceModelled()) << "glTF's default iridescenceFactor is 0";
}

// KHR_materials_transmission and KHR_materials_volume load their factors and maps with glTF's
// defaults (thin-walled, no tint); a transmissive material is drawn as glass, and a factor of 0 is
// opaque whatever its map.
TEST(GltfMaterials, TransmissionAndVolumeReachTheSceneModel) {
    const fs::path dir = testDir();
    Gltf g = withMaterial({{"extensions",
                            {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}, {"transmissionTexture", {{"index", 0}}}}},
                             {"KHR_materials_volume", {{"thicknessFactor", 0.3},
                                                       {"thicknessTexture", {{"index", 0}}},
                                                       {"attenuationDistance", 2.5},
                                                       {"attenuationColor", {0.2, 0.5, 0.9}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume"};
    std::vector<std::string> warnings;
    Scene s = load(g.writeGltf(dir, "transmission"), warnings);
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.transmissionFactor, 0.75f);
    EXPECT_TRUE(m.transmissionTexture.present());
    EXPECT_FLOAT_EQ(m.thicknessFactor, 0.3f);
    EXPECT_TRUE(m.thicknessTexture.present());
    EXPECT_FLOAT_EQ(m.attenuationDistance, 2.5f);
    EXPECT_EQ(m.attenuationColor, glm::vec3(0.2f, 0.5f, 0.9f));
    EXPECT_TRUE(m.transmissionModelled());
    EXPECT_TRUE(m.drawnAsGlass()) << "light passes through: drawn by the transparent pass";
    EXPECT_FALSE(m.blended());
    for (const std::string& w : warnings) EXPECT_EQ(w.find("not modelled"), std::string::npos) << w;

    Gltf defaults = withMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                                  {"KHR_materials_volume", json::object()}}}});
    s = load(defaults.writeGltf(dir, "transmission_defaults"), warnings);
    EXPECT_FLOAT_EQ(s.materials.at(0).thicknessFactor, 0.0f) << "thin-walled";
    EXPECT_FLOAT_EQ(s.materials.at(0).attenuationDistance, 0.0f) << "infinite: no tint";
    EXPECT_EQ(s.materials.at(0).attenuationColor, glm::vec3(1.0f));

    // The thickness is in the mesh's units: a node drawn at scale 2 draws a copy twice as thick.
    Gltf scaled;
    scaled.add("materials", {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                            {"KHR_materials_volume", {{"thicknessFactor", 0.3}}}}}});
    const int mesh = scaled.mesh({trianglePrimitive(scaled, true, 0)});
    scaled.scene({scaled.node({{"mesh", mesh}}), scaled.node({{"mesh", mesh}, {"scale", {2.0, 2.0, 2.0}}})});
    s = load(scaled.writeGltf(dir, "volume_scaled"), warnings);
    std::vector<float> thicknesses;
    for (const DrawRange& d : s.draws) thicknesses.push_back(s.materials.at(d.material).thicknessFactor);
    std::sort(thicknesses.begin(), thicknesses.end());
    ASSERT_EQ(thicknesses.size(), 2u);
    EXPECT_FLOAT_EQ(thicknesses[0], 0.3f);
    EXPECT_FLOAT_EQ(thicknesses[1], 0.6f);

    Gltf off = withMaterial({{"extensions", {{"KHR_materials_transmission", {{"transmissionTexture", {{"index", 0}}}}}}}});
    s = load(off.writeGltf(dir, "no_transmission"), warnings);
    EXPECT_FALSE(s.materials.at(0).transmissionModelled()) << "glTF's default transmissionFactor is 0";
    EXPECT_FALSE(s.materials.at(0).drawnAsGlass());
}

TEST(GltfMaterials, BadValuesAreNamedInOneLine) {
    const fs::path dir = testDir();
    const auto refused = [&](const char* name, const json& material, std::initializer_list<const char*> keywords,
                             const json& sampler = json()) {
        SCOPED_TRACE(name);
        expectFault(withMaterial(material, sampler).writeGltf(dir, name), keywords);
    };
    refused("cutoff_negative", {{"alphaMode", "MASK"}, {"alphaCutoff", -0.5}}, {"materials[0]", "alphaCutoff"});
    refused("alpha_mode", {{"alphaMode", "GLASS"}}, {"materials[0]", "alphaMode", "GLASS"});
    refused("normal_texture", {{"normalTexture", {{"index", 7}}}}, {"materials[0]", "normalTexture", "index 7"});
    refused("occlusion_strength", {{"occlusionTexture", {{"index", 0}, {"strength", 3.0}}}}, {"occlusionTexture.strength", "3"});
    refused("texture_index", {{"emissiveTexture", {{"index", 7}}}}, {"materials[0]", "emissiveTexture", "index 7", "1 textures"});
    refused("texcoord_set", {{"normalTexture", {{"index", 0}, {"texCoord", 3}}}}, {"normalTexture", "texCoord 3"});
    refused("transform", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {1.0}}}}}}}}}}},
            {"baseColorTexture", "KHR_texture_transform scale"});
    refused("emissive_strength", {{"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", -1.0}}}}}},
            {"materials[0]", "emissiveStrength"});
    refused("ior_below_one", {{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}, {"materials[0]", "KHR_materials_ior", "ior 0.5"});
    refused("ior_negative", {{"extensions", {{"KHR_materials_ior", {{"ior", -2.0}}}}}}, {"materials[0]", "ior -2"});
    refused("specular_factor", {{"extensions", {{"KHR_materials_specular", {{"specularFactor", -0.1}}}}}},
            {"materials[0]", "specularFactor -0.1"});
    refused("specular_colour", {{"extensions", {{"KHR_materials_specular", {{"specularColorFactor", {1.0, -1.0, 1.0}}}}}}},
            {"materials[0]", "specularColorFactor"});
    refused("specular_texture", {{"extensions", {{"KHR_materials_specular", {{"specularColorTexture", {{"index", 9}}}}}}}},
            {"materials[0]", "specularColorTexture", "index 9"});
    refused("clearcoat_factor", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.5}}}}}},
            {"materials[0]", "KHR_materials_clearcoat", "clearcoatFactor 1.5"});
    refused("clearcoat_roughness", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatRoughnessFactor", "rough"}}}}}},
            {"materials[0]", "clearcoatRoughnessFactor", "not a finite number"});
    refused("clearcoat_texture", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatNormalTexture", {{"index", 9}}}}}}}},
            {"materials[0]", "clearcoatNormalTexture", "index 9"});
    refused("clearcoat_texture_info", {{"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatTexture", 3}}}}}},
            {"materials[0]", "clearcoatTexture", "not a textureInfo"});
    const auto sg = [](const json& fields) { return json{{"extensions", {{"KHR_materials_pbrSpecularGlossiness", fields}}}}; };
    refused("glossiness", sg({{"glossinessFactor", 1.5}}), {"materials[0]", "KHR_materials_pbrSpecularGlossiness glossinessFactor"});
    refused("diffuse_count", sg({{"diffuseFactor", {1.0, 1.0, 1.0}}}), {"materials[0]", "diffuseFactor", "4 numbers"});
    refused("specular_negative", sg({{"specularFactor", {1.0, -0.5, 1.0}}}), {"materials[0]", "specularFactor", "[0, 1]"});
    refused("diffuse_texture", sg({{"diffuseTexture", {{"index", 4}}}}), {"materials[0]", "diffuseTexture", "index 4"});
    refused("specgloss_texture", sg({{"specularGlossinessTexture", {{"texCoord", 0}}}}),
            {"materials[0]", "specularGlossinessTexture", "not a textureInfo"});
    refused("sheen_color", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 1.5, 0.5}}}}}}},
            {"materials[0]", "KHR_materials_sheen", "sheenColorFactor"});
    refused("sheen_color_count", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 0.5}}}}}}},
            {"materials[0]", "sheenColorFactor", "3 numbers"});
    refused("sheen_roughness", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {1, 1, 1}}, {"sheenRoughnessFactor", -0.25}}}}}},
            {"materials[0]", "sheenRoughnessFactor -0.25", "outside [0, 1]"});
    refused("sheen_texture", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorFactor", {1, 1, 1}}, {"sheenRoughnessTexture", {{"index", 9}}}}}}}},
            {"materials[0]", "sheenRoughnessTexture", "index 9"});
    refused("sheen_texture_info", {{"extensions", {{"KHR_materials_sheen", {{"sheenColorTexture", {{"texCoord", 0}}}}}}}},
            {"materials[0]", "sheenColorTexture", "not a textureInfo"});
    const auto aniso = [](const json& fields) { return json{{"extensions", {{"KHR_materials_anisotropy", fields}}}}; };
    refused("anisotropy_negative", aniso({{"anisotropyStrength", -0.2}}),
            {"materials[0]", "KHR_materials_anisotropy", "anisotropyStrength -0.2", "outside [0, 1]"});
    refused("anisotropy_above_one", aniso({{"anisotropyStrength", 1.5}}), {"materials[0]", "anisotropyStrength 1.5", "outside [0, 1]"});
    refused("anisotropy_rotation", aniso({{"anisotropyStrength", 0.5}, {"anisotropyRotation", "left"}}),
            {"materials[0]", "anisotropyRotation", "not a finite number"});
    refused("anisotropy_texture", aniso({{"anisotropyStrength", 0.5}, {"anisotropyTexture", {{"index", 9}}}}),
            {"materials[0]", "anisotropyTexture", "index 9"});
    refused("anisotropy_texture_info", aniso({{"anisotropyStrength", 0.5}, {"anisotropyTexture", 2}}),
            {"materials[0]", "anisotropyTexture", "not a textureInfo"});
    const auto film = [](const json& fields) { return json{{"extensions", {{"KHR_materials_iridescence", fields}}}}; };
    refused("iridescence_factor", film({{"iridescenceFactor", 1.5}}), {"materials[0]", "iridescenceFactor 1.5", "outside [0, 1]"});
    refused("iridescence_negative", film({{"iridescenceFactor", -0.5}}), {"materials[0]", "iridescenceFactor -0.5"});
    refused("iridescence_ior", film({{"iridescenceFactor", 1}, {"iridescenceIor", 0.8}}), {"materials[0]", "iridescenceIor 0.8", "below 1"});
    refused("iridescence_thickness_order", film({{"iridescenceFactor", 1}, {"iridescenceThicknessMinimum", 500}, {"iridescenceThicknessMaximum", 300}}),
            {"materials[0]", "iridescenceThicknessMinimum 500", "above iridescenceThicknessMaximum 300"});
    refused("iridescence_thickness_negative", film({{"iridescenceFactor", 1}, {"iridescenceThicknessMinimum", -10}}),
            {"materials[0]", "thickness -10", "negative"});
    refused("iridescence_thickness_max_negative", film({{"iridescenceFactor", 1}, {"iridescenceThicknessMaximum", -1}}),
            {"materials[0]", "thickness -1", "negative"});
    const auto transmission = [](const json& fields) { return json{{"extensions", {{"KHR_materials_transmission", fields}}}}; };
    refused("transmission_factor", transmission({{"transmissionFactor", 1.5}}), {"materials[0]", "transmissionFactor 1.5", "outside [0, 1]"});
    refused("transmission_texture", transmission({{"transmissionFactor", 1}, {"transmissionTexture", {{"index", 9}}}}),
            {"materials[0]", "transmissionTexture", "index 9"});
    const auto volume = [](const json& fields) {
        return json{{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1}}}, {"KHR_materials_volume", fields}}}};
    };
    refused("volume_thickness", volume({{"thicknessFactor", -0.5}}), {"materials[0]", "thicknessFactor -0.5", "negative"});
    refused("volume_distance", volume({{"attenuationDistance", 0}}), {"materials[0]", "attenuationDistance 0", "not above 0"});
    refused("volume_colour", volume({{"attenuationColor", {0.5, 1.5, 0.5}}}), {"materials[0]", "attenuationColor", "[0, 1]"});
    refused("volume_colour_length", volume({{"attenuationColor", {0.5, 0.5}}}), {"materials[0]", "attenuationColor"});
    refused("iridescence_texture", film({{"iridescenceFactor", 1}, {"iridescenceThicknessTexture", {{"index", 9}}}}),
            {"materials[0]", "iridescenceThicknessTexture", "index 9"});
    {
        // Its two maps share one texture unit: two textures (here one image, two samplers) are refused.
        Gltf g = withMaterial(film({{"iridescenceFactor", 1}, {"iridescenceTexture", {{"index", 0}}}, {"iridescenceThicknessTexture", {{"index", 1}}}}));
        g.add("textures", {{"source", 0}, {"sampler", g.add("samplers", {{"magFilter", 9728}})}});
        SCOPED_TRACE("iridescence_two_textures");
        expectFault(g.writeGltf(dir, "iridescence_two_textures"), {"materials[0]", "iridescenceTexture and iridescenceThicknessTexture", "one image"});
    }
    refused("min_filter", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}, {"samplers[0]", "minFilter 1234"},
            {{"minFilter", 1234}});
    refused("wrap", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}, {"samplers[0]", "wrapT 5"}, {{"wrapT", 5}});
}

}  // namespace
}  // namespace ml
