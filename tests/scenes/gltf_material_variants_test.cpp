// KHR_materials_variants in the loader: the root's names, each primitive's mappings as material
// sets beside the draw ranges, applyMaterialVariant switching them, and every bad index named in
// one line with the file and the primitive.
#include <string>
#include <vector>

#include "scenes/material_variants.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

const glm::vec4 kRed{1, 0, 0, 1}, kGreen{0, 1, 0, 1}, kBlue{0, 0, 1, 1};

// Materials red (0), green (1), blue (2); variants "Green" (0) and "Blue" (1). Primitive 0 of the
// mesh, at x in [0, 1], maps to green and blue; primitive 1, at x in [5, 6], has no mappings.
struct VariantsFile {
    Gltf g;
    json mapped, plain;
};

VariantsFile variantsFile() {
    VariantsFile f;
    Gltf& g = f.g;
    for (const glm::vec4& c : {kRed, kGreen, kBlue}) colourMaterial(g, c, "OPAQUE");
    g.doc["extensionsUsed"] = {"KHR_materials_variants"};
    g.doc["extensions"]["KHR_materials_variants"]["variants"] = json::array({{{"name", "Green"}}, {{"name", "Blue"}}});
    f.mapped = primitive({{"POSITION", g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}, g.indices({0, 1, 2}), 0);
    f.mapped["extensions"]["KHR_materials_variants"]["mappings"] =
        json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}});
    f.plain = primitive({{"POSITION", g.vec3({{5, 0, 0}, {6, 0, 0}, {5, 1, 0}})}}, g.indices({0, 1, 2}), 0);
    return f;
}

fs::path write(VariantsFile& f, const fs::path& dir, const std::string& name) {
    f.g.scene({f.g.node({{"mesh", f.g.mesh({f.mapped, f.plain})}})});
    return f.g.writeGltf(dir, name);
}

// The base colour the triangle whose first corner lies at x draws with.
glm::vec4 colourAt(const Scene& s, float x) {
    for (const DrawRange& d : s.draws)
        for (std::uint32_t i = d.firstIndex; i < d.firstIndex + d.indexCount; i += 3)
            if (s.vertices[s.indices[i]].position.x >= x && s.vertices[s.indices[i]].position.x <= x + 1.0f)
                return s.materials.at(d.material).baseColorFactor;
    ADD_FAILURE() << "no triangle at x " << x;
    return glm::vec4(-1.0f);
}

TEST(GltfMaterialVariants, MappingsSwitchOnlyTheMappedPrimitives) {
    VariantsFile f = variantsFile();
    std::vector<std::string> warnings;
    Scene s = load(write(f, testDir(), "variants"), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.at(0);  // modelled: no "skipped" line
    ASSERT_EQ(s.materialVariants.names, (std::vector<std::string>{"Green", "Blue"}));
    EXPECT_EQ(s.materials.size(), 3u) << "every material a variant may take is converted at load";
    ASSERT_EQ(s.materialVariants.defaults.size(), s.draws.size());
    ASSERT_EQ(s.materialVariants.materials.size(), 2u);
    EXPECT_EQ(colourAt(s, 0.0f), kRed);
    EXPECT_EQ(colourAt(s, 5.0f), kRed);

    applyMaterialVariant(s, 0);
    EXPECT_EQ(colourAt(s, 0.0f), kGreen);
    EXPECT_EQ(colourAt(s, 5.0f), kRed) << "a primitive without mappings keeps its material";
    applyMaterialVariant(s, 1);
    EXPECT_EQ(colourAt(s, 0.0f), kBlue);
    EXPECT_EQ(colourAt(s, 5.0f), kRed);
    applyMaterialVariant(s, std::nullopt);
    EXPECT_EQ(colourAt(s, 0.0f), kRed);
}

// A variant not every mapping lists falls back to the primitive's own material; one mapping may
// list several variants; a file without the extension has no variants and one range per material.
TEST(GltfMaterialVariants, UnlistedVariantsKeepTheDefaultAndPlainFilesHaveNone) {
    VariantsFile f = variantsFile();
    f.mapped["extensions"]["KHR_materials_variants"]["mappings"] = json::array({{{"material", 2}, {"variants", {1, 0}}}});
    Scene s = load(write(f, testDir(), "both"));
    applyMaterialVariant(s, 0);
    EXPECT_EQ(colourAt(s, 0.0f), kBlue);

    VariantsFile one = variantsFile();
    one.mapped["extensions"]["KHR_materials_variants"]["mappings"] = json::array({{{"material", 1}, {"variants", {1}}}});
    s = load(write(one, testDir(), "one"));
    applyMaterialVariant(s, 0);
    EXPECT_EQ(colourAt(s, 0.0f), kRed);
    applyMaterialVariant(s, 1);
    EXPECT_EQ(colourAt(s, 0.0f), kGreen);

    const Scene plain = load(oneTriangle().writeGltf(testDir(), "plain"));
    EXPECT_TRUE(plain.materialVariants.empty());
    EXPECT_TRUE(plain.materialVariants.materials.empty());
    EXPECT_EQ(plain.draws.size(), 1u);
}

// A variant's material with a normal map gets its primitive tangents, though the default has none:
// the streams follow every material a primitive may be drawn with.
TEST(GltfMaterialVariants, StreamsFollowTheVariantsMaterials) {
    VariantsFile f = variantsFile();
    Gltf& g = f.g;
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, {128, 128, 255, 255}))}});
    g.add("textures", {{"source", 0}});
    g.doc["materials"][2]["normalTexture"] = {{"index", 0}};
    f.mapped["attributes"]["NORMAL"] = g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    f.mapped["attributes"]["TEXCOORD_0"] = g.vec2({{0, 0}, {1, 0}, {0, 1}});
    const Scene s = load(write(f, testDir(), "tangents"));
    EXPECT_EQ(s.tangents.size(), s.vertices.size());

    // A variant's texture on UV set 1 asks the primitive for TEXCOORD_1, named as for its default.
    VariantsFile uv = variantsFile();
    uv.g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, {255, 255, 255, 255}))}});
    uv.g.add("textures", {{"source", 0}});
    uv.g.doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}, {"texCoord", 1}};
    expectFault(write(uv, testDir(), "uv1"), {"materials[1]", "TEXCOORD_1", "meshes[0] primitive 0"});
}

TEST(GltfMaterialVariants, BadMappingsAreNamedInOneLine) {
    const fs::path dir = testDir();
    const auto refused = [&](const char* name, const json& mappings, std::initializer_list<const char*> keywords) {
        SCOPED_TRACE(name);
        VariantsFile f = variantsFile();
        f.mapped["extensions"]["KHR_materials_variants"]["mappings"] = mappings;
        expectFault(write(f, dir, name), keywords);
    };
    refused("material_range", json::array({{{"material", 7}, {"variants", {0}}}}),
            {"meshes[0] primitive 0", "KHR_materials_variants", "mappings[0]", "material 7 out of range (3 materials)"});
    refused("material_negative", json::array({{{"material", -1}, {"variants", {0}}}}), {"meshes[0] primitive 0", "material -1"});
    refused("variant_range", json::array({{{"material", 1}, {"variants", {0, 2}}}}),
            {"meshes[0] primitive 0", "mappings[0]", "variant 2 out of range (2 variants)"});
    refused("variant_twice", json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {0}}}}),
            {"meshes[0] primitive 0", "mappings[1]", "variant 0 is listed by two mappings"});
    refused("not_an_array", json::object(), {"meshes[0] primitive 0", "mappings is not an array"});
    refused("no_variants", json::array({{{"material", 1}}}), {"meshes[0] primitive 0", "mappings[0]", "variants array"});

    VariantsFile unnamed = variantsFile();
    unnamed.g.doc["extensions"]["KHR_materials_variants"]["variants"][1] = {{"title", "Blue"}};
    expectFault(write(unnamed, dir, "unnamed"), {"KHR_materials_variants variants[1] has no name"});
    VariantsFile rootless = variantsFile();
    rootless.g.doc["extensions"]["KHR_materials_variants"] = {{"variants", 3}};
    expectFault(write(rootless, dir, "rootless"), {"KHR_materials_variants variants is not an array"});
    // Mappings in a file that names no variants list a variant out of range.
    VariantsFile none = variantsFile();
    none.g.doc.erase("extensions");
    expectFault(write(none, dir, "none"), {"meshes[0] primitive 0", "variant 0 out of range (0 variants)"});
}

}  // namespace
}  // namespace ml
