// The glTF loader: good files land in world space with the right materials, unmodelled features
// are skipped with one warning per kind, and bad files end in one SceneError line naming the
// file and the fault. Every test writes its own small glTF/GLB into a temporary directory.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "scenes/gltf_loader.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

// --- Good files ------------------------------------------------------------------------------------

TEST(GltfLoader, IndexedMeshIsFlattenedToWorldSpace) {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    const double s = std::sqrt(0.5);
    // Parent translation, child rotation (90 degrees about +Y) and scale: world = T * R * S.
    const int child = g.node({{"mesh", mesh}, {"rotation", {0.0, s, 0.0, s}}, {"scale", {2.0, 2.0, 2.0}}});
    const int parent = g.node({{"translation", {10.0, 0.0, 0.0}}, {"children", {child}}});
    // The same mesh instanced again through a column-major matrix (a translation by (0, 5, 0)).
    const int second = g.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}}});
    g.scene({parent, second});
    const fs::path file = g.writeGltf(testDir(), "transforms");

    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(scene.name, "transforms");
    EXPECT_FALSE(scene.suggestedView.has_value());
    ASSERT_EQ(scene.vertices.size(), 6u);
    EXPECT_EQ(scene.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));

    // Rotating +90 degrees about Y takes +X to -Z and +Z to +X.
    expectNear(scene.vertices[0].position, {10, 0, 0});
    expectNear(scene.vertices[1].position, {10, 0, -2});
    expectNear(scene.vertices[2].position, {10, 2, 0});
    for (int i = 0; i < 3; ++i) expectNear(scene.vertices[i].normal, {1, 0, 0});
    expectNear(scene.vertices[3].position, {0, 5, 0});
    expectNear(scene.vertices[4].position, {1, 5, 0});
    expectNear(scene.vertices[5].position, {0, 6, 0});
    for (int i = 3; i < 6; ++i) expectNear(scene.vertices[i].normal, {0, 0, 1});

    // No material index: one draw with a default white material.
    ASSERT_EQ(scene.draws.size(), 1u);
    EXPECT_EQ(scene.draws[0].firstIndex, 0u);
    EXPECT_EQ(scene.draws[0].indexCount, 6u);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(scene.materials[0].baseColorTexture.image, -1);
    expectNear(scene.bounds.min, {0, 0, -2});
    expectNear(scene.bounds.max, {10, 6, 0});
}

TEST(GltfLoader, NormalsUseTheInverseTranspose) {
    Gltf g;
    // A triangle in the plane y + z = 0, stretched by 2 along Y: a plain matrix multiply would tilt
    // the normal the wrong way.
    const glm::vec3 n = glm::normalize(glm::vec3(0, 1, 1));
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, -1}});
    const int nrm = g.vec3({n, n, n});
    const int mesh = g.mesh({primitive({{"POSITION", pos}, {"NORMAL", nrm}})});
    g.scene({g.node({{"mesh", mesh}, {"scale", {1.0, 2.0, 1.0}}})});
    const Scene scene = load(g.writeGltf(testDir(), "stretched"));
    const glm::vec3 expected = glm::normalize(glm::vec3(0, 0.5f, 1));
    for (const Vertex& v : scene.vertices) expectNear(v.normal, expected);
    expectNear(faceNormal(scene, 0), expected);  // the surface's own normal agrees
}

TEST(GltfLoader, NonIndexedTrianglesGetSequentialIndices) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    const int mesh = g.mesh({primitive({{"POSITION", pos}})});
    g.scene({g.node({{"mesh", mesh}})});
    const Scene scene = load(g.writeEmbedded(testDir(), "soup"));
    EXPECT_EQ(scene.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(scene.triangleCount(), 2u);
    expectNear(scene.vertices[5].position, {0, 1, 1});
}

TEST(GltfLoader, MissingNormalsAreGeneratedAreaWeighted) {
    Gltf g;
    // Vertex 0 is shared by a big triangle facing +Z (area 2) and a small one facing +Y (area 0.5).
    const int pos = g.vec3({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1}, {1, 0, 0}});
    const int idx = g.indices({0, 1, 2, 0, 3, 4});
    const int mesh = g.mesh({primitive({{"POSITION", pos}}, idx)});
    g.scene({g.node({{"mesh", mesh}})});
    const Scene scene = load(g.writeGltf(testDir(), "generated"));
    ASSERT_EQ(scene.vertices.size(), 5u);
    expectNear(scene.vertices[0].normal, glm::normalize(glm::vec3(0, 1, 4)));  // 4:1 by area
    expectNear(scene.vertices[1].normal, {0, 0, 1});
    expectNear(scene.vertices[2].normal, {0, 0, 1});
    expectNear(scene.vertices[3].normal, {0, 1, 0});
    expectNear(scene.vertices[4].normal, {0, 1, 0});
}

TEST(GltfLoader, MirroringTransformKeepsFrontFacesAndNormals) {
    Gltf g;
    const int withNormals = g.mesh({trianglePrimitive(g, true)});
    const int without = g.mesh({trianglePrimitive(g, false)});
    g.scene({g.node({{"mesh", withNormals}, {"scale", {-1.0, 1.0, 1.0}}}),
             g.node({{"mesh", without}, {"scale", {-1.0, 1.0, 1.0}}})});
    const Scene scene = load(g.writeGltf(testDir(), "mirrored"));
    ASSERT_EQ(scene.triangleCount(), 2u);
    // Mirrored in X, the triangle still faces +Z: winding is flipped back, normals follow.
    for (std::size_t t = 0; t < 2; ++t) expectNear(faceNormal(scene, t), {0, 0, 1});
    for (const Vertex& v : scene.vertices) expectNear(v.normal, {0, 0, 1});
}

TEST(GltfLoader, Uv0AndBaseColorFactorAndOneDrawPerMaterial) {
    Gltf g;
    g.add("materials", {{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.0, 0.0, 1.0}}}}});
    g.add("materials", {{"name", "blue"}, {"doubleSided", true}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.0, 0.25, 1.0, 0.5}}}}});
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int uv = g.vec2({{0, 0}, {1, 0}, {0.5f, 1}});
    // The same UVs as normalized UNSIGNED_SHORT, as glTF allows.
    const std::vector<std::uint16_t> packed = {0, 0, 65535, 0, 32768, 65535};
    const int uvShort = g.accessor(g.view(packed.data(), packed.size() * 2), kUShort, 3, "VEC2", {{"normalized", true}});
    const int idx = g.indices({0, 1, 2});
    // Materials alternate red, blue, red: the loader gathers them into one draw each.
    const int mesh = g.mesh({primitive({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, 0),
                             primitive({{"POSITION", pos}, {"TEXCOORD_0", uvShort}}, idx, 1),
                             primitive({{"POSITION", pos}, {"TEXCOORD_0", uv}}, idx, 0)});
    g.scene({g.node({{"mesh", mesh}})});
    std::vector<std::string> warnings;
    const fs::path file = g.writeGltf(testDir(), "materials");
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty());

    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].name, "red");
    EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(scene.materials[1].baseColorFactor, glm::vec4(0, 0.25f, 1, 0.5f));
    EXPECT_FALSE(scene.materials[0].doubleSided);  // glTF's default: back faces may be culled
    EXPECT_TRUE(scene.materials[1].doubleSided);
    ASSERT_EQ(scene.draws.size(), 2u);
    EXPECT_EQ(scene.draws[0].material, 0u);
    EXPECT_EQ(scene.draws[0].indexCount, 6u);
    EXPECT_EQ(scene.draws[1].material, 1u);
    EXPECT_EQ(scene.draws[1].firstIndex, 6u);
    EXPECT_EQ(scene.draws[1].indexCount, 3u);
    // Primitives sharing attributes share vertices; the UNSIGNED_SHORT ones are their own block.
    ASSERT_EQ(scene.vertices.size(), 6u);
    EXPECT_EQ(scene.vertices[2].uv, glm::vec2(0.5f, 1));
    EXPECT_EQ(scene.vertices[4].uv, glm::vec2(1, 0));
    EXPECT_NEAR(scene.vertices[5].uv.x, 0.5f, 1e-4f);
    EXPECT_EQ(scene.vertices[5].uv.y, 1.0f);
}

TEST(GltfLoader, BaseColorTextureFromPngDataUri) {
    // 2x2: red, green on the top row; blue, half-transparent white below.
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
    Gltf g;
    g.add("images", {{"name", "checker"}, {"uri", "data:image/png;base64," + base64(encodePng(2, 2, pixels))}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const int mesh = g.mesh({trianglePrimitive(g, true, 0)});
    g.scene({g.node({{"mesh", mesh}})});
    std::vector<std::string> warnings;
    const Scene scene = load(g.writeGltf(testDir(), "textured"), warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].name, "checker");
    EXPECT_EQ(scene.images[0].width, 2);
    EXPECT_EQ(scene.images[0].height, 2);
    EXPECT_EQ(scene.images[0].rgba8, pixels);  // sRGB bytes as stored, top row first
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorTexture.image, 0);
}

TEST(GltfLoader, GlbWithBinChunkAndImageInBufferView) {
    const std::vector<std::uint8_t> pixels = {10, 20, 30, 255};
    const std::vector<std::uint8_t> png = encodePng(1, 1, pixels);
    Gltf g;
    g.add("images", {{"bufferView", g.view(png.data(), png.size())}, {"mimeType", "image/png"}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const int mesh = g.mesh({trianglePrimitive(g, true, 0)});
    g.scene({g.node({{"mesh", mesh}, {"translation", {0.0, 0.0, 3.0}}})});
    const Scene scene = load(g.writeGlb(testDir(), "binary"));
    EXPECT_EQ(scene.name, "binary");
    ASSERT_EQ(scene.vertices.size(), 3u);
    expectNear(scene.vertices[1].position, {1, 0, 3});
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].rgba8, pixels);
}

TEST(GltfLoader, SparseAccessorReplacesValues) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<std::uint16_t> which = {2};
    const std::vector<glm::vec3> values = {{0, 3, 0}};
    const int sparseIndices = g.view(which.data(), 2);
    const int sparseValues = g.view(values.data(), 12);
    g.doc["accessors"][pos]["sparse"] = {{"count", 1},
                                         {"indices", {{"bufferView", sparseIndices}, {"componentType", kUShort}}},
                                         {"values", {{"bufferView", sparseValues}}}};
    const int mesh = g.mesh({primitive({{"POSITION", pos}})});
    g.scene({g.node({{"mesh", mesh}})});
    const Scene scene = load(g.writeGltf(testDir(), "sparse"));
    expectNear(scene.vertices[1].position, {1, 0, 0});
    expectNear(scene.vertices[2].position, {0, 3, 0});
}

TEST(GltfLoader, QuantizedPositionsWithKhrMeshQuantization) {
    Gltf g;
    g.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    g.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    const std::vector<std::uint16_t> packed = {0, 0, 0, 0, 2, 4, 0, 0, 0, 0, 6, 0};  // VEC3, 8 bytes apart
    const int view = g.view(packed.data(), packed.size() * 2, 8);
    const int pos = g.accessor(view, kUShort, 3, "VEC3");
    const int mesh = g.mesh({primitive({{"POSITION", pos}})});
    g.scene({g.node({{"mesh", mesh}, {"scale", {0.5, 0.5, 0.5}}})});
    std::vector<std::string> warnings;
    const Scene scene = load(g.writeGltf(testDir(), "quantized"), warnings);
    EXPECT_TRUE(warnings.empty());
    expectNear(scene.vertices[1].position, {1, 2, 0});
    expectNear(scene.vertices[2].position, {0, 0, 3});
}

TEST(GltfLoader, HundredThousandDeepNodeChainLoads) {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    constexpr int kDepth = 100000;
    json nodes = json::array();
    for (int i = 0; i < kDepth; ++i) {
        json n = {{"translation", {0.001, 0.0, 0.0}}};
        if (i + 1 < kDepth) n["children"] = {i + 1};
        else n["mesh"] = mesh;
        nodes.push_back(std::move(n));
    }
    g.doc["nodes"] = std::move(nodes);
    g.scene({0});
    const Scene scene = load(g.writeGltf(testDir(), "chain"));
    ASSERT_EQ(scene.vertices.size(), 3u);
    expectNear(scene.vertices[0].position, {100, 0, 0}, 1e-3f);
}

// --- Warnings: skipped, never half-loaded -------------------------------------------------------

TEST(GltfLoaderWarnings, UnmodelledFeaturesWarnOncePerKind) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int colour = g.vec3({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    const std::vector<float> times = {0.0f, 1.0f};
    const int input = g.accessor(g.view(times.data(), 8), kFloat, 2, "SCALAR");
    const int output = g.vec3({{0, 0, 0}, {0, 1, 0}});
    const std::vector<std::uint8_t> pixel = {255, 255, 255, 255};
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, pixel))}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"normalTexture", {{"index", 0}}}, {"emissiveTexture", {{"index", 0}}}});
    g.add("materials", {{"normalTexture", {{"index", 0}}}});
    const int mesh = g.mesh({
        primitive({{"POSITION", pos}, {"COLOR_0", colour}}, -1, 0),
        [&] { json p = primitive({{"POSITION", pos}}, -1, 1); p["targets"] = {{{"POSITION", pos}}}; return p; }(),
        [&] { json p = primitive({{"POSITION", pos}}); p["mode"] = 0; return p; }(),
        [&] { json p = primitive({{"POSITION", pos}}); p["mode"] = 0; return p; }(),
        [&] { json p = primitive({{"POSITION", pos}}); p["mode"] = 1; return p; }(),
    });
    const int root = g.node({{"mesh", mesh}, {"camera", 0}});
    // tinygltf 2.7 insists on inverseBindMatrices, which glTF makes optional.
    const std::vector<float> identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const int bind = g.accessor(g.view(identity.data(), 64), kFloat, 1, "MAT4");
    json skin = {{"joints", {root}}, {"inverseBindMatrices", bind}};
    g.doc["skins"] = {skin, skin};
    json channel = {{"sampler", 0}, {"target", {{"node", root}, {"path", "translation"}}}};
    json animation = json::object();
    animation["samplers"] = json::array({json{{"input", input}, {"output", output}}});
    animation["channels"] = json::array({channel});
    g.doc["animations"] = json::array({animation});
    json camera = {{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}};
    g.doc["cameras"] = {camera, camera, camera};
    g.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
    g.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}, {{"type", "directional"}}}}}}};
    g.scene({root});
    const fs::path file = g.writeGltf(testDir(), "features");

    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(scene.triangleCount(), 2u);  // the two triangle primitives, nothing else
    expectOneLineWarnings(warnings, file);
    // Skins, animations and morph targets are modelled (tests/scenes/gltf_animation_test.cpp); a
    // camera on an animated node stays where the rest pose puts it.
    for (const char* kind : {"1 camera or light on animated nodes", "3 primitives skipped (points and lines are not drawn)"})
        EXPECT_EQ(countContaining(warnings, kind), 1u) << kind;
    // KHR_lights_punctual is modelled now (tests/scenes/gltf_lights_test.cpp): no warning.
    EXPECT_EQ(countContaining(warnings, "KHR_lights_punctual"), 0u);
    // Materials' textures and KHR_materials_emissive_strength are modelled now.
    EXPECT_EQ(countContaining(warnings, "textures other than baseColor"), 0u);
    EXPECT_EQ(countContaining(warnings, "extension KHR_materials_emissive_strength"), 0u);
    EXPECT_EQ(countContaining(warnings, "2 POINTS primitives, 1 LINES primitive"), 1u);
    // Cameras and vertex colours are modelled now: no warning for either (the camera's line is
    // the animated node's).
    EXPECT_EQ(countContaining(warnings, "camera"), 1u);
    EXPECT_EQ(countContaining(warnings, "COLOR_0"), 0u);
    EXPECT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(warnings.size(), 2u);  // the camera on an animated node, the primitives
}

TEST(GltfLoaderWarnings, UndecodableImageBecomesWhite) {
    Gltf g;
    const std::string garbage = "this is not a PNG";
    g.add("images", {{"name", "broken"}, {"uri", "data:image/png;base64," + base64({garbage.begin(), garbage.end()})}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const int mesh = g.mesh({trianglePrimitive(g, true, 0)});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGltf(testDir(), "badimage");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    expectOneLineWarnings(warnings, file);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("could not be decoded"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("images[0] 'broken'"), std::string::npos) << warnings[0];
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].width, 1);
    EXPECT_EQ(scene.images[0].height, 1);
    EXPECT_EQ(scene.images[0].rgba8, (std::vector<std::uint8_t>{255, 255, 255, 255}));
    EXPECT_EQ(scene.materials[0].baseColorTexture.image, 0);
    EXPECT_EQ(scene.triangleCount(), 1u);
}

TEST(GltfLoaderWarnings, MissingExternalImageBecomesWhite) {
    Gltf g;
    g.add("images", {{"uri", "nowhere.png"}});
    g.add("textures", {{"source", 0}});
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const int mesh = g.mesh({trianglePrimitive(g, true, 0)});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGltf(testDir(), "noimage");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    expectOneLineWarnings(warnings, file);
    EXPECT_EQ(countContaining(warnings, "nowhere.png"), warnings.size());
    EXPECT_EQ(countContaining(warnings, "could not be decoded"), 1u);
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].rgba8, (std::vector<std::uint8_t>{255, 255, 255, 255}));
}

TEST(GltfLoaderWarnings, NonFiniteNormalsAreRegenerated) {
    Gltf g;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int nrm = g.vec3({{0, 0, 1}, {nan, 0, 1}, {0, 0, 1}});
    const int mesh = g.mesh({primitive({{"POSITION", pos}, {"NORMAL", nrm}})});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGltf(testDir(), "nannormal");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(countContaining(warnings, "normals generated"), 1u);
    for (const Vertex& v : scene.vertices) expectNear(v.normal, {0, 0, 1});
}

TEST(GltfLoaderWarnings, MillionEmptyPrimitivesLoadInLinearTime) {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path dir = testDir();
    g.writeGltf(dir, "empties");
    // Splice a million primitives without attributes in front of the real one, as text: building
    // them as JSON objects here would take longer than loading them.
    std::ifstream in(dir / "empties.gltf");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string marker = "\"primitives\":[";
    const std::size_t at = text.find(marker);
    ASSERT_NE(at, std::string::npos);
    std::string empties;
    constexpr std::size_t kCount = 1000000;
    empties.reserve(kCount * 18);
    for (std::size_t i = 0; i < kCount; ++i) empties += "{\"attributes\":{}},";
    text.insert(at + marker.size(), empties);
    const fs::path file = dir / "empties.gltf";
    writeText(file, text);

    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // Timing is reported, not asserted (design.md: tests never assert a timing).
    RecordProperty("load_seconds", std::to_string(seconds));
    std::printf("    1,000,000 empty primitives loaded in %.2f s\n", seconds);
    EXPECT_EQ(scene.triangleCount(), 1u);
    expectOneLineWarnings(warnings, file);
    EXPECT_EQ(countContaining(warnings, "1000000 primitives without POSITION skipped"), 1u);
}

TEST(GltfLoaderWarnings, PrimitivesWithEmptyAccessorsAreSkipped) {
    Gltf g;
    const int empty = g.accessor(-1, kFloat, 0, "VEC3");
    std::vector<json> primitives(1000, primitive({{"POSITION", empty}}));
    primitives.push_back(trianglePrimitive(g));
    const int mesh = g.mesh(primitives);
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGltf(testDir(), "emptyaccessors");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(countContaining(warnings, "1000 empty primitives skipped"), 1u);
}

// --- Faults: one SceneError line each ----------------------------------------------------------

TEST(GltfLoaderFaults, MissingFile) { expectFault(testDir() / "absent.gltf", {"not found"}); }

TEST(GltfLoaderFaults, UnreadableFile) {
    const fs::path dir = testDir() / "folder.gltf";  // a directory cannot be read as a file
    fs::create_directories(dir);
    expectFault(dir, {"not a regular file"});
}

TEST(GltfLoaderFaults, MalformedJson) {
    const fs::path file = testDir() / "malformed.gltf";
    writeText(file, "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [\n{\"mesh\": 0,,}\n]}");
    expectFault(file, {"malformed JSON"});
}

TEST(GltfLoaderFaults, JsonThatIsNotAnObject) {
    const fs::path file = testDir() / "array.gltf";
    writeText(file, "[1, 2, 3]");
    expectFault(file, {"not an object"});
}

TEST(GltfLoaderFaults, EmptyFile) {
    const fs::path file = testDir() / "empty.gltf";
    writeText(file, "");
    expectFault(file, {"empty"});
}

TEST(GltfLoaderFaults, DeeplyNestedJson) {
    Gltf g = oneTriangle();
    const fs::path file = g.writeGltf(testDir(), "nested");
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    // 100,000 nested arrays in `extras`: valid JSON that a recursive converter would die on.
    text.insert(text.size() - 1, ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']'));
    writeText(file, text);
    expectFault(file, {"nested deeper"});
}

TEST(GltfLoaderFaults, UnsupportedGltfVersion) {
    Gltf g = oneTriangle();
    g.doc["asset"]["version"] = "1.0";
    expectFault(g.writeGltf(testDir(), "old"), {"version", "1.0"});
}

TEST(GltfLoaderFaults, WrongFileExtension) {
    const fs::path file = testDir() / "scene.obj";
    writeText(file, "{}");
    expectFault(file, {".gltf or .glb"});
}

TEST(GltfLoaderFaults, GlbBadMagic) {
    std::vector<std::uint8_t> bytes = oneTriangle().glb();
    bytes[0] = 'x';
    const fs::path file = testDir() / "magic.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"magic"});
}

TEST(GltfLoaderFaults, GlbBadVersion) {
    std::vector<std::uint8_t> bytes = oneTriangle().glb();
    bytes[4] = 1;
    const fs::path file = testDir() / "version.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"GLB version 1"});
}

TEST(GltfLoaderFaults, GlbTruncatedHeader) {
    const std::vector<std::uint8_t> bytes = {'g', 'l', 'T', 'F', 2, 0};
    const fs::path file = testDir() / "short.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"truncated"});
}

TEST(GltfLoaderFaults, GlbLengthPastEnd) {
    std::vector<std::uint8_t> bytes = oneTriangle().glb();
    bytes[10] = 0x10;  // total length + 1 MiB
    const fs::path file = testDir() / "length.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"length", "past the end"});
}

TEST(GltfLoaderFaults, GlbJsonChunkPastEnd) {
    std::vector<std::uint8_t> bytes = oneTriangle().glb();
    bytes[15] = 0x7f;  // JSON chunk length ~2 GiB
    const fs::path file = testDir() / "jsonchunk.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"JSON chunk", "past the end"});
}

TEST(GltfLoaderFaults, GlbBinChunkPastEnd) {
    std::vector<std::uint8_t> bytes = oneTriangle().glb();
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, &bytes[12], 4);
    bytes[20 + jsonLength + 3] = 0x01;  // BIN chunk length + 16 MiB
    const fs::path file = testDir() / "binchunk.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"BIN chunk", "past the end"});
}

TEST(GltfLoaderFaults, GlbBufferOfLengthZero) {
    // tinygltf 2.7 throws std::out_of_range on this one; it must still come out as a SceneError.
    Gltf g = oneTriangle();
    json doc = g.doc;
    doc["buffers"] = json::array({{{"byteLength", 0}}});
    const std::vector<std::uint8_t> bytes = glbBytes(doc, g.bin);
    const fs::path file = testDir() / "zerobuffer.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"glTF parse error"});
}

TEST(GltfLoaderFaults, MissingBinFile) {
    const fs::path dir = testDir();
    const fs::path file = oneTriangle().writeGltf(dir, "nobin");
    fs::remove(dir / "nobin.bin");
    expectFault(file, {"missing", "nobin.bin"});
}

TEST(GltfLoaderFaults, BufferViewOverrunsBuffer) {
    Gltf g = oneTriangle();
    g.doc["bufferViews"][0]["byteLength"] = 4096;
    expectFault(g.writeGltf(testDir(), "viewoverrun"), {"bufferViews[0]", "overruns"});
}

TEST(GltfLoaderFaults, ImageBufferViewOverrunsBuffer) {
    Gltf g = oneTriangle();
    const std::vector<std::uint8_t> png = encodePng(1, 1, {1, 2, 3, 4});
    g.add("images", {{"bufferView", g.view(png.data(), png.size())}, {"mimeType", "image/png"}});
    g.doc["bufferViews"].back()["byteLength"] = 1 << 20;
    const std::vector<std::uint8_t> bytes = g.glb();
    const fs::path file = testDir() / "imageview.glb";
    writeBytes(file, bytes.data(), bytes.size());
    expectFault(file, {"overruns"});
}

TEST(GltfLoaderFaults, AccessorOverrunsBufferView) {
    Gltf g = oneTriangle();
    g.doc["accessors"][0]["count"] = 4;  // 4 positions in a view that holds 3
    expectFault(g.writeGltf(testDir(), "accessoroverrun"), {"accessors[0]", "POSITION", "overruns"});
}

TEST(GltfLoaderFaults, AccessorOverrunsThroughItsStride) {
    Gltf g = oneTriangle();
    g.doc["bufferViews"][0]["byteStride"] = 16;  // 3 elements of 12 bytes, 16 apart, need 44 of 36
    expectFault(g.writeGltf(testDir(), "strideoverrun"), {"accessors[0]", "overruns"});
}

TEST(GltfLoaderFaults, AccessorWithAHugeCount) {
    Gltf g = oneTriangle();
    g.doc["accessors"][0]["count"] = std::uint64_t{1} << 61;  // offset arithmetic would overflow
    expectFault(g.writeGltf(testDir(), "hugecount"), {"accessors[0]", "overruns"});
}

TEST(GltfLoaderFaults, AccessorWithoutDataCannotAskForGigabytes) {
    Gltf g = oneTriangle();
    g.doc["accessors"][0].erase("bufferView");  // zeros, which cost nothing in the file
    g.doc["accessors"][0]["count"] = 4000000000u;
    expectFault(g.writeGltf(testDir(), "zeros"), {"accessors[0]", "limit"});
}

TEST(GltfLoaderFaults, PositionsWithWrongComponentType) {
    Gltf g = oneTriangle();
    g.doc["accessors"][0]["componentType"] = kUShort;
    expectFault(g.writeGltf(testDir(), "positiontype"), {"accessors[0]", "componentType UNSIGNED_SHORT", "POSITION"});
}

TEST(GltfLoaderFaults, PositionsWithWrongType) {
    Gltf g = oneTriangle();
    g.doc["accessors"][0]["type"] = "VEC2";
    expectFault(g.writeGltf(testDir(), "positionvec2"), {"accessors[0]", "type VEC2", "POSITION"});
}

TEST(GltfLoaderFaults, FloatIndices) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const std::vector<float> idx = {0, 1, 2};
    const int indices = g.accessor(g.view(idx.data(), 12), kFloat, 3, "SCALAR");
    g.scene({g.node({{"mesh", g.mesh({primitive({{"POSITION", pos}}, indices)})}})});
    expectFault(g.writeGltf(testDir(), "floatindices"), {"indices", "componentType FLOAT"});
}

TEST(GltfLoaderFaults, IndexOutOfRange) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int idx = g.indices({0, 1, 3});
    g.scene({g.node({{"mesh", g.mesh({primitive({{"POSITION", pos}}, idx)})}})});
    expectFault(g.writeGltf(testDir(), "badindex"), {"index 3", "out of range", "meshes[0]"});
}

TEST(GltfLoaderFaults, IndexCountNotAMultipleOfThree) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int idx = g.indices({0, 1, 2, 0});
    g.scene({g.node({{"mesh", g.mesh({primitive({{"POSITION", pos}}, idx)})}})});
    expectFault(g.writeGltf(testDir(), "fourindices"), {"multiple of 3"});
}

TEST(GltfLoaderFaults, NanPosition) {
    Gltf g;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int pos = g.vec3({{0, 0, 0}, {1, nan, 0}, {0, 1, 0}});
    g.scene({g.node({{"mesh", g.mesh({primitive({{"POSITION", pos}})})}})});
    expectFault(g.writeGltf(testDir(), "nan"), {"non-finite", "accessors[0]", "meshes[0]", "element 1"});
}

TEST(GltfLoaderFaults, InfinitePosition) {
    Gltf g;
    const float inf = std::numeric_limits<float>::infinity();
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, -inf}});
    g.add("meshes", {{"name", "Spike"}, {"primitives", {primitive({{"POSITION", pos}})}}});
    g.scene({g.node({{"mesh", 0}})});
    expectFault(g.writeGltf(testDir(), "inf"), {"non-finite", "accessors[0]", "meshes[0] 'Spike'"});
}

TEST(GltfLoaderFaults, TransformOverflowsToInfinity) {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    const int inner = g.node({{"mesh", mesh}, {"scale", {1e300, 1e300, 1e300}}});
    g.scene({g.node({{"scale", {1e300, 1e300, 1e300}}, {"children", {inner}}})});
    expectFault(g.writeGltf(testDir(), "overflow"), {"non-finite", "nodes[0]"});
}

TEST(GltfLoaderFaults, NoScene) {
    Gltf g;
    g.mesh({trianglePrimitive(g)});
    expectFault(g.writeGltf(testDir(), "noscene"), {"no scene"});
}

TEST(GltfLoaderFaults, EmptyScene) {
    Gltf g = oneTriangle();
    g.scene({});
    expectFault(g.writeGltf(testDir(), "emptyscene"), {"empty"});
}

TEST(GltfLoaderFaults, SceneWithoutTriangles) {
    Gltf g;
    const int pos = g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    json points = primitive({{"POSITION", pos}});
    points["mode"] = 0;
    g.scene({g.node({{"mesh", g.mesh({points})}})});
    expectFault(g.writeGltf(testDir(), "pointsonly"), {"no triangles"});
}

TEST(GltfLoaderFaults, NodeCycle) {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    g.node({{"children", {1}}});
    g.node({{"children", {2}}, {"mesh", mesh}});
    g.node({{"children", {0}}});
    g.scene({0});
    expectFault(g.writeGltf(testDir(), "cycle"), {"cycle", "nodes[0]"});
}

TEST(GltfLoaderFaults, NodeThatIsItsOwnChild) {
    Gltf g;
    g.node({{"children", {0}}, {"mesh", g.mesh({trianglePrimitive(g)})}});
    g.scene({0});
    expectFault(g.writeGltf(testDir(), "selfcycle"), {"cycle"});
}

TEST(GltfLoaderFaults, NodeWithTwoParents) {
    // Without the check, 40 levels of doubled children would be visited 2^40 times.
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    for (int i = 0; i < 40; ++i) g.node({{"children", {i + 1, i + 1}}});
    g.node({{"mesh", mesh}});
    g.scene({0});
    // The walk is depth first, so the deepest doubled child is the one caught.
    expectFault(g.writeGltf(testDir(), "shared"), {"reached twice", "nodes[40]"});
}

TEST(GltfLoaderFaults, ChildIndexOutOfRange) {
    Gltf g;
    g.node({{"children", {7}}, {"mesh", g.mesh({trianglePrimitive(g)})}});
    g.scene({0});
    expectFault(g.writeGltf(testDir(), "badchild"), {"node index 7", "out of range"});
}

TEST(GltfLoaderFaults, MeshIndexOutOfRange) {
    Gltf g = oneTriangle();
    g.doc["nodes"][0]["mesh"] = 5;
    expectFault(g.writeGltf(testDir(), "badmesh"), {"mesh index 5", "out of range"});
}

TEST(GltfLoaderFaults, MaterialIndexOutOfRange) {
    Gltf g = oneTriangle();
    g.doc["meshes"][0]["primitives"][0]["material"] = 2;
    expectFault(g.writeGltf(testDir(), "badmaterial"), {"material index 2", "out of range"});
}

TEST(GltfLoaderWarnings, BaseColorFactorOfWrongLengthIsReported) {
    // tinygltf drops a malformed factor with a message of its own, which becomes a warning.
    Gltf g = oneTriangle();
    g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5}}}}});
    g.doc["meshes"][0]["primitives"][0]["material"] = 0;
    const fs::path file = g.writeGltf(testDir(), "factor");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    expectOneLineWarnings(warnings, file);
    EXPECT_EQ(countContaining(warnings, "baseColorFactor"), 1u);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorFactor, glm::vec4(1.0f));
}

TEST(GltfLoaderFaults, SparseIndexOutOfRange) {
    Gltf g = oneTriangle();
    const std::vector<std::uint32_t> which = {3};
    const std::vector<glm::vec3> values = {{0, 3, 0}};
    const int sparseIndices = g.view(which.data(), 4);
    const int sparseValues = g.view(values.data(), 12);
    g.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", sparseIndices}, {"componentType", kUInt}}},
                                       {"values", {{"bufferView", sparseValues}}}};
    expectFault(g.writeGltf(testDir(), "sparseindex"), {"sparse index 3", "out of range"});
}

TEST(GltfLoaderFaults, SparseValuesOverrunTheirView) {
    Gltf g = oneTriangle();
    const std::vector<std::uint8_t> which = {0, 1};
    const std::vector<glm::vec3> values = {{0, 3, 0}};  // one value for two indices
    const int sparseIndices = g.view(which.data(), 2);
    const int sparseValues = g.view(values.data(), 12);
    g.doc["accessors"][0]["sparse"] = {{"count", 2},
                                       {"indices", {{"bufferView", sparseIndices}, {"componentType", kUByte}}},
                                       {"values", {{"bufferView", sparseValues}}}};
    expectFault(g.writeGltf(testDir(), "sparsevalues"), {"sparse values", "overrun"});
}

TEST(GltfLoaderFaults, BufferDataUriThatIsNotBase64) {
    const fs::path dir = testDir();
    const fs::path file = oneTriangle().writeEmbedded(dir, "notbase64");
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const std::size_t at = text.find(";base64,") + 8;
    text.replace(at + 8, 4, "*%!?");  // garbage in the middle: the decoded size no longer matches
    writeText(file, text);
    expectFault(file, {"buffers[0]", "base64"});
}

TEST(GltfLoaderFaults, BufferDataUriWithTrailingGarbage) {
    const fs::path dir = testDir();
    const fs::path file = oneTriangle().writeEmbedded(dir, "trailing");
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const std::size_t end = text.find('"', text.find(";base64,"));
    text.insert(end, "!!!!");  // tinygltf's decoder would stop here quietly, at the right size
    writeText(file, text);
    expectFault(file, {"buffers[0]", "base64"});
}

TEST(GltfLoaderFaults, ImageDataUriThatIsNotBase64) {
    Gltf g = oneTriangle();
    g.add("images", {{"uri", "data:image/png;base64,!!!!"}});
    expectFault(g.writeGltf(testDir(), "imagebase64"), {"image", "base64"});
}

}  // namespace
}  // namespace ml
