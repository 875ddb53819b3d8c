// The glTF loader's geometry beyond triangle lists: strips and fans, skipped points and lines,
// the optional vertex streams (COLOR_0, TEXCOORD_1, TANGENT or generated tangents) and cameras.
// Each test writes its files under $ML_TEST_TMP, where the fuzzer finds them as seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "scenes/gltf_loader.h"
#include "scenes/tangent_frames.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

// A triangle by its corner positions, rotated so that the smallest corner comes first: two
// triangles compare equal when they have the same corners in the same winding.
using Corners = std::array<std::array<float, 3>, 3>;

std::multiset<Corners> trianglesOf(const Scene& scene) {
    std::multiset<Corners> out;
    for (std::size_t t = 0; t < scene.triangleCount(); ++t) {
        Corners c;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = scene.vertices[scene.indices[3 * t + k]].position;
            c[k] = {p.x, p.y, p.z};
        }
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.insert(c);
    }
    return out;
}

// Five points on a bent sheet, so that no two triangles lie in one plane.
const std::vector<glm::vec3> kFivePoints = {{0, 0, 0}, {1, 0, 0.2f}, {0, 1, 0.4f}, {1, 1, 0.1f}, {0, 2, 0.3f}};

json withMode(json p, int mode) {
    p["mode"] = mode;
    return p;
}

// One node (scaled by `scale`, so -1 mirrors) drawing one primitive over kFivePoints.
fs::path writeFivePoints(const std::string& name, int mode, const std::vector<std::uint16_t>& indices,
                         const glm::vec3& scale = glm::vec3(1.0f)) {
    Gltf g;
    const int position = g.vec3(kFivePoints);
    const int mesh = g.mesh({withMode(primitive({{"POSITION", position}}, indices.empty() ? -1 : g.indices(indices)), mode)});
    g.scene({g.node({{"mesh", mesh}, {"scale", {scale.x, scale.y, scale.z}}})});
    return g.writeGlb(testDir(), name);
}

constexpr int kPoints = 0, kLines = 1, kTriangles = 4, kStrip = 5, kFan = 6;

TEST(GltfGeometry, StripsAndFansGiveTheTrianglesOfTheirTriangleList) {
    for (const glm::vec3 scale : {glm::vec3(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)}) {
        const std::string suffix = scale.x < 0.0f ? "_mirrored" : "";
        // Strip: (0 1 2), (2 1 3) as (1 3 2), (2 3 4). Fan: (0 1 2), (0 2 3), (0 3 4).
        const auto stripList = trianglesOf(load(writeFivePoints("strip_list" + suffix, kTriangles, {0, 1, 2, 1, 3, 2, 2, 3, 4}, scale)));
        const auto fanList = trianglesOf(load(writeFivePoints("fan_list" + suffix, kTriangles, {0, 1, 2, 0, 2, 3, 0, 3, 4}, scale)));
        ASSERT_EQ(stripList.size(), 3u);
        EXPECT_EQ(trianglesOf(load(writeFivePoints("strip" + suffix, kStrip, {}, scale))), stripList);
        EXPECT_EQ(trianglesOf(load(writeFivePoints("strip_indexed" + suffix, kStrip, {0, 1, 2, 3, 4}, scale))), stripList);
        EXPECT_EQ(trianglesOf(load(writeFivePoints("fan" + suffix, kFan, {}, scale))), fanList);
        EXPECT_EQ(trianglesOf(load(writeFivePoints("fan_indexed" + suffix, kFan, {0, 1, 2, 3, 4}, scale))), fanList);
    }
    // Front faces stay front faces: the first strip triangle faces +z unmirrored.
    const Scene strip = load(writeFivePoints("strip_facing", kStrip, {}));
    const glm::vec3 a = strip.vertices[strip.indices[0]].position, b = strip.vertices[strip.indices[1]].position,
                    c = strip.vertices[strip.indices[2]].position;
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
}

TEST(GltfGeometry, StripsAndFansOfFewerThanThreeVerticesAreEmpty) {
    Gltf g;
    const int position = g.vec3(kFivePoints);
    const int mesh = g.mesh({withMode(primitive({{"POSITION", position}}, g.indices({0, 1})), kStrip),
                             withMode(primitive({{"POSITION", position}}, g.indices({3})), kFan),
                             withMode(primitive({{"POSITION", position}}, g.indices({0, 1, 2})), kFan)});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGlb(testDir(), "short_strips");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(countContaining(warnings, "2 empty primitives skipped"), 1u);
}

TEST(GltfGeometry, PointsAndLinesAreSkippedWithOneCountingWarning) {
    Gltf g;
    const int position = g.vec3(kFivePoints);
    const json points = withMode(primitive({{"POSITION", position}}), kPoints);
    const json lines = withMode(primitive({{"POSITION", position}}, g.indices({0, 1, 1, 2})), kLines);
    const int mesh = g.mesh({points, lines, lines, lines, withMode(primitive({{"POSITION", position}}), kStrip)});
    g.scene({g.node({{"mesh", mesh}})});
    const fs::path file = g.writeGlb(testDir(), "points_and_lines");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(scene.triangleCount(), 3u);
    expectOneLineWarnings(warnings, file);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("4 primitives skipped"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("1 POINTS primitive, 3 LINES primitives"), std::string::npos) << warnings[0];
}

TEST(GltfGeometry, AFileOfOnlyLinesNamesWhatWasSkipped) {
    Gltf g;
    const int position = g.vec3(kFivePoints);
    const int mesh = g.mesh({withMode(primitive({{"POSITION", position}}, g.indices({0, 1, 1, 2})), kLines),
                             withMode(primitive({{"POSITION", position}}), kLines),
                             withMode(primitive({{"POSITION", position}}), kPoints)});
    g.scene({g.node({{"mesh", mesh}})});
    expectFault(g.writeGlb(testDir(), "only_lines"),
                {"no triangles to draw", "skipped: 1 POINTS primitive, 2 LINES primitives"});
}

// --- COLOR_0 ---------------------------------------------------------------------------------------

// One triangle with the given COLOR_0 accessor, and a second primitive without colours.
Gltf colouredTriangle(const std::function<int(Gltf&)>& colorAccessor) {
    Gltf g;
    json coloured = trianglePrimitive(g);
    coloured["attributes"]["COLOR_0"] = colorAccessor(g);
    const int mesh = g.mesh({coloured, trianglePrimitive(g)});
    g.scene({g.node({{"mesh", mesh}})});
    return g;
}

TEST(GltfGeometry, VertexColoursInEveryFormat) {
    const glm::vec4 expected[3] = {{1, 0, 0, 1}, {0, 1, 0, 0.5f}, {0, 0, 1, 0}};
    struct Case {
        const char* name;
        std::function<int(Gltf&)> accessor;
        bool hasAlpha;
    };
    const std::vector<Case> cases = {
        {"float_vec4", [&](Gltf& g) { return g.accessor(g.view(expected, sizeof expected), kFloat, 3, "VEC4"); }, true},
        {"float_vec3",
         [](Gltf& g) {
             const std::vector<glm::vec3> rgb = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
             return g.vec3(rgb);
         },
         false},
        {"ubyte_vec4",
         [](Gltf& g) {
             const std::uint8_t rgba[12] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0};
             return g.accessor(g.view(rgba, 12), kUByte, 3, "VEC4", {{"normalized", true}});
         },
         true},
        {"ushort_vec3",
         [](Gltf& g) {
             const std::uint16_t rgb[10] = {65535, 0, 0, 0, 65535, 0, 0, 0, 65535, 0};
             return g.accessor(g.view(rgb, 18), kUShort, 3, "VEC3", {{"normalized", true}});
         },
         false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        std::vector<std::string> warnings;
        const Scene scene = load(colouredTriangle(c.accessor).writeGlb(testDir(), std::string("colour_") + c.name), warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        ASSERT_EQ(scene.colors.size(), scene.vertices.size());
        ASSERT_EQ(scene.vertices.size(), 6u);
        for (int i = 0; i < 3; ++i) {
            const glm::vec4 want = c.hasAlpha ? expected[i] : glm::vec4(glm::vec3(expected[i]), 1.0f);
            for (int k = 0; k < 4; ++k) EXPECT_NEAR(scene.colors[i][k], want[k], 0.003f) << "vertex " << i;
        }
        for (int i = 3; i < 6; ++i) EXPECT_EQ(scene.colors[i], glm::vec4(1.0f));  // no COLOR_0: white
    }
    // No COLOR_0 anywhere: no stream.
    EXPECT_TRUE(load(oneTriangle().writeGlb(testDir(), "no_colour")).colors.empty());
}

TEST(GltfGeometry, VertexColoursInAnUnnormalizedByteFormatAreRefused) {
    const Gltf g = colouredTriangle([](Gltf& file) {
        const std::uint8_t rgba[12] = {};
        return file.accessor(file.view(rgba, 12), kUByte, 3, "VEC4");
    });
    expectFault(g.writeGlb(testDir(), "colour_unnormalized"), {"accessors[", "COLOR_0", "normalized"});
}

// --- TEXCOORD_1 ------------------------------------------------------------------------------------

// A triangle with TEXCOORD_0 and TEXCOORD_1 drawn with `material` (a JSON material or null).
Gltf twoUvSets(const json& material) {
    Gltf g;
    const std::vector<std::uint8_t> white = {255, 255, 255, 255};
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, white))}});
    g.add("textures", {{"source", 0}});
    json p = trianglePrimitive(g);
    p["attributes"]["TEXCOORD_0"] = g.vec2({{0, 0}, {1, 0}, {0, 1}});
    p["attributes"]["TEXCOORD_1"] = g.vec2({{0.5f, 0.5f}, {0.25f, 0}, {0, 0.75f}});
    if (!material.is_null()) p["material"] = g.add("materials", material);
    g.scene({g.node({{"mesh", g.mesh({p})}})});
    return g;
}

TEST(GltfGeometry, TexCoord1IsLoadedOnlyWhenAMaterialReadsIt) {
    EXPECT_TRUE(load(twoUvSets(nullptr).writeGlb(testDir(), "uv1_unused")).uv1.empty());
    EXPECT_TRUE(load(twoUvSets({{"occlusionTexture", {{"index", 0}}}}).writeGlb(testDir(), "uv1_unused_by_uv0")).uv1.empty());

    const Scene occlusion = load(twoUvSets({{"occlusionTexture", {{"index", 0}, {"texCoord", 1}}}}).writeGlb(testDir(), "uv1_occlusion"));
    ASSERT_EQ(occlusion.uv1.size(), occlusion.vertices.size());
    EXPECT_EQ(occlusion.uv1[0], glm::vec2(0.5f, 0.5f));
    EXPECT_EQ(occlusion.uv1[2], glm::vec2(0.0f, 0.75f));

    // KHR_texture_transform's texCoord overrides the textureInfo's.
    const json transformed = {{"pbrMetallicRoughness",
                               {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}}}}};
    Gltf g = twoUvSets(transformed);
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    EXPECT_EQ(load(g.writeGlb(testDir(), "uv1_texture_transform")).uv1.size(), 3u);
}

TEST(GltfGeometry, TexCoordOutsideTheTwoSetsIsRefused) {
    expectFault(twoUvSets({{"name", "Rust"}, {"emissiveTexture", {{"index", 0}, {"texCoord", 2}}}}).writeGlb(testDir(), "texcoord2"),
                {"materials[0] 'Rust'", "emissiveTexture", "texCoord 2"});
}

TEST(GltfGeometry, TexCoord1OnAPrimitiveWithoutItIsRefused) {
    Gltf g;
    const int material = g.add("materials", {{"name", "Moss"}, {"normalTexture", {{"index", 0}, {"texCoord", 1}}}});
    g.add("textures", json::object());
    g.scene({g.node({{"mesh", g.mesh({trianglePrimitive(g, true, material)})}})});
    expectFault(g.writeGlb(testDir(), "texcoord1_missing"),
                {"materials[0] 'Moss'", "normalTexture", "TEXCOORD_1", "meshes[0] primitive 0"});
}

// --- Tangents --------------------------------------------------------------------------------------

// A unit quad in the XY plane facing +z, its UVs turned a quarter (u runs along +y, v along -x):
// the tangent (increasing u) is +y, the bitangent (increasing v) is -x = cross(+z, +y), so w = +1.
struct MappedQuad {
    std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    std::vector<glm::vec2> uvs = {{0, 1}, {0, 0}, {1, 0}, {1, 1}};
    glm::vec4 tangent{0, 1, 0, 1};
};

Gltf normalMappedQuad(bool withTangents, const glm::vec3& scale, bool normalMapped = true) {
    const MappedQuad quad;
    Gltf g;
    const std::vector<std::uint8_t> flat = {128, 128, 255, 255};
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, flat))}});
    g.add("textures", {{"source", 0}});
    const int material = normalMapped ? g.add("materials", {{"normalTexture", {{"index", 0}}}}) : g.add("materials", json::object());
    json attributes = {{"POSITION", g.vec3(quad.positions)},
                       {"NORMAL", g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                       {"TEXCOORD_0", g.vec2(quad.uvs)}};
    if (withTangents) {
        const std::vector<glm::vec4> tangents(4, quad.tangent);
        attributes["TANGENT"] = g.accessor(g.view(tangents.data(), 64), kFloat, 4, "VEC4");
    }
    const int mesh = g.mesh({primitive(attributes, g.indices({0, 1, 2, 0, 2, 3}), material)});
    g.scene({g.node({{"mesh", mesh}, {"scale", {scale.x, scale.y, scale.z}}})});
    return g;
}

void expectTangentsNear(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.tangents.size(), a.vertices.size());
    ASSERT_EQ(b.tangents.size(), a.tangents.size());
    for (std::size_t i = 0; i < a.tangents.size(); ++i) {
        expectNear(glm::vec3(a.tangents[i]), glm::vec3(b.tangents[i]), 1e-4f);
        EXPECT_EQ(a.tangents[i].w, b.tangents[i].w) << "vertex " << i;
    }
}

TEST(GltfGeometry, GeneratedTangentsAgreeWithGivenOnesAndMirrorsFlipW) {
    const Scene given = load(normalMappedQuad(true, glm::vec3(1)).writeGlb(testDir(), "tangents_given"));
    const Scene generated = load(normalMappedQuad(false, glm::vec3(1)).writeGlb(testDir(), "tangents_generated"));
    expectTangentsNear(given, generated);
    for (const glm::vec4& t : given.tangents) {
        expectNear(glm::vec3(t), {0, 1, 0});
        EXPECT_EQ(t.w, 1.0f);
    }

    // Mirrored in x (and scaled: the direction is renormalised): the tangent stays +y, w flips.
    const glm::vec3 mirror(-2.0f, 3.0f, 1.0f);
    const Scene givenMirrored = load(normalMappedQuad(true, mirror).writeGlb(testDir(), "tangents_given_mirrored"));
    const Scene generatedMirrored = load(normalMappedQuad(false, mirror).writeGlb(testDir(), "tangents_generated_mirrored"));
    expectTangentsNear(givenMirrored, generatedMirrored);
    for (const glm::vec4& t : givenMirrored.tangents) {
        expectNear(glm::vec3(t), {0, 1, 0});
        EXPECT_EQ(t.w, -1.0f);
    }
}

TEST(GltfGeometry, TangentsExistOnlyForNormalMappedPrimitives) {
    EXPECT_TRUE(load(normalMappedQuad(true, glm::vec3(1), false).writeGlb(testDir(), "tangents_unused")).tangents.empty());
}

TEST(GltfGeometry, TangentsWithNaNAreRegeneratedWithAWarning) {
    Gltf g = normalMappedQuad(true, glm::vec3(1));
    // Poison the first float of the TANGENT accessor.
    const int tangentAccessor = g.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"];
    const std::size_t offset = g.doc["bufferViews"][g.doc["accessors"][tangentAccessor]["bufferView"].get<int>()]["byteOffset"];
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&g.bin[offset], &nan, 4);
    const fs::path file = g.writeGlb(testDir(), "tangents_nan");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(countContaining(warnings, "TANGENT of 1 primitive held NaN"), 1u);
    ASSERT_EQ(scene.tangents.size(), 4u);
    for (const glm::vec4& t : scene.tangents) expectNear(glm::vec3(t), {0, 1, 0});
}

TEST(GltfGeometry, BadTangentAccessorsAreRefused) {
    {
        Gltf g = normalMappedQuad(false, glm::vec3(1));
        g.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = g.vec3({{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}});
        expectFault(g.writeGlb(testDir(), "tangents_vec3"), {"TANGENT", "VEC3", "expected VEC4 FLOAT"});
    }
    {
        Gltf g = normalMappedQuad(false, glm::vec3(1));
        const std::vector<glm::vec4> three(3, glm::vec4(1, 0, 0, 1));
        g.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = g.accessor(g.view(three.data(), 48), kFloat, 3, "VEC4");
        expectFault(g.writeGlb(testDir(), "tangents_count"), {"TANGENT", "count 3 differs from the POSITION count 4"});
    }
}

TEST(TangentFrames, DegenerateUvsGiveAUnitTangentOrthogonalToTheNormal) {
    Scene scene;
    for (const glm::vec3& p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}) {
        Vertex v;
        v.position = p;
        v.normal = {0, 0, 1};
        scene.vertices.push_back(v);  // all UVs (0, 0)
    }
    scene.indices = {0, 1, 2};
    generateTangents(scene, {{0, 3}}, 0);
    ASSERT_EQ(scene.tangents.size(), 3u);
    for (const glm::vec4& t : scene.tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(t), glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
        EXPECT_EQ(std::abs(t.w), 1.0f);
    }
}

// A file may store one vertex twice (equal position, normal and UV), and a re-export merges the
// copies: the generated frames must not tell the two apart (issue 61's twins). Two triangles with
// different UV directions share a corner; stored once or as two copies, it gets the same tangent.
TEST(GltfTangents, DuplicateVerticesGetTheFrameOfTheMergedVertex) {
    const auto vertex = [](glm::vec3 p, glm::vec2 uv) {
        Vertex v;
        v.position = p;
        v.normal = {0, 0, 1};
        v.uv = uv;
        return v;
    };
    Scene merged;
    merged.vertices = {vertex({0, 0, 0}, {0, 0}), vertex({1, 0, 0}, {1, 0}), vertex({0, 1, 0}, {0, 1}),
                       vertex({-1, 0, 0}, {1, 1})};
    merged.indices = {0, 1, 2, 0, 2, 3};
    Scene duplicated = merged;
    duplicated.vertices.push_back(merged.vertices[0]);  // vertex 4: a copy of the shared corner
    duplicated.indices = {0, 1, 2, 4, 2, 3};
    generateTangents(merged, {{0, 6}}, 0);
    generateTangents(duplicated, {{0, 6}}, 0);
    EXPECT_EQ(duplicated.tangents[0], merged.tangents[0]);
    EXPECT_EQ(duplicated.tangents[4], merged.tangents[0]);
    EXPECT_EQ(duplicated.tangents[2], merged.tangents[2]);
}

// --- Cameras ---------------------------------------------------------------------------------------

json perspective(double yfov, double znear, double zfar = 0.0) {
    json p = {{"yfov", yfov}, {"znear", znear}};
    if (zfar != 0.0) p["zfar"] = zfar;
    return {{"type", "perspective"}, {"perspective", p}};
}

TEST(GltfCameras, CamerasAtNestedRotatedScaledNodesLandWhereTheyShould) {
    Gltf g = oneTriangle();
    json named = perspective(0.8, 0.05, 200.0);
    named["name"] = "Overview";
    g.doc["cameras"] = {named, perspective(1.2, 0.1)};
    const double s = std::sqrt(0.5);
    // Parent: translate (1, 2, 3), scale 2. Child: translate (0, 0, 1), turn 90 degrees about +y,
    // so the camera looks down -x from (1, 2, 5).
    const int child = g.node({{"camera", 0}, {"translation", {0, 0, 1}}, {"rotation", {0.0, s, 0.0, s}}});
    const int parent = g.node({{"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}, {"children", {child}}});
    // Rolled 90 degrees about its view axis (z): its up is -x. Non-uniform scale changes nothing.
    const int rolled = g.node({{"camera", 1}, {"name", "RolledNode"}, {"rotation", {0.0, 0.0, s, s}}, {"scale", {3, 0.5, 7}}});
    json roots = g.doc["scenes"][0]["nodes"];
    roots.push_back(parent);
    roots.push_back(rolled);
    g.doc["scenes"][0]["nodes"] = roots;
    const fs::path file = g.writeGlb(testDir(), "cameras");

    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(scene.cameras.size(), 2u);
    const SceneCamera& overview = scene.cameras[0];
    EXPECT_EQ(overview.name, "Overview");
    expectNear(overview.pose.eye, {1, 2, 5});
    expectNear(overview.pose.target, {0, 2, 5});
    expectNear(overview.up, {0, 1, 0});
    EXPECT_NEAR(overview.pose.fovyDegrees, 0.8 * 180.0 / std::numbers::pi, 1e-4);
    EXPECT_FLOAT_EQ(overview.nearPlane, 0.05f);
    EXPECT_FLOAT_EQ(overview.farPlane, 200.0f);

    const SceneCamera& rolledCamera = scene.cameras[1];
    EXPECT_EQ(rolledCamera.name, "RolledNode");  // the node's name where the camera has none
    expectNear(rolledCamera.pose.eye, {0, 0, 0});
    expectNear(rolledCamera.pose.target, {0, 0, -1});
    expectNear(rolledCamera.up, {-1, 0, 0});
    EXPECT_EQ(rolledCamera.farPlane, 0.0f);  // none given: infinite
}

TEST(GltfCameras, OrthographicCamerasAreSkippedWithOneWarning) {
    Gltf g = oneTriangle();
    const json ortho = {{"type", "orthographic"}, {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}};
    g.doc["cameras"] = {ortho, perspective(1.0, 0.1)};
    g.doc["scenes"][0]["nodes"] = {0, g.node({{"camera", 0}}), g.node({{"camera", 0}}), g.node({{"camera", 1}})};
    std::vector<std::string> warnings;
    const Scene scene = load(g.writeGlb(testDir(), "orthographic"), warnings);
    EXPECT_EQ(scene.cameras.size(), 1u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("2 orthographic cameras skipped"), std::string::npos) << warnings[0];
}

TEST(GltfCameras, BadCamerasAreRefusedNamingThem) {
    struct Case {
        const char* name;
        json camera;
        std::vector<const char*> keywords;
    };
    const std::vector<Case> cases = {
        {"yfov_wide", perspective(3.2, 0.1), {"cameras[0]", "yfov"}},
        {"yfov_zero", perspective(0.0, 0.1), {"cameras[0]", "yfov"}},
        {"znear_zero", perspective(1.0, 0.0), {"cameras[0]", "znear"}},
        {"zfar_below_znear", perspective(1.0, 1.0, 0.5), {"cameras[0]", "zfar"}},
        {"znear_tiny", perspective(1.0, 1e-300), {"cameras[0]", "znear"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Gltf g = oneTriangle();
        g.doc["cameras"] = {c.camera};
        g.doc["scenes"][0]["nodes"] = {0, g.node({{"camera", 0}})};
        const fs::path file = g.writeGlb(testDir(), std::string("camera_") + c.name);
        std::vector<std::string> warnings;
        try {
            loadGltf(file.string(), warnings);
            ADD_FAILURE() << "loaded";
        } catch (const SceneError& e) {
            const std::string message = e.what();
            for (const char* keyword : c.keywords) EXPECT_NE(message.find(keyword), std::string::npos) << message;
        }
    }
    Gltf g = oneTriangle();
    g.doc["cameras"] = {perspective(1.0, 0.1)};
    g.doc["scenes"][0]["nodes"] = {0, g.node({{"camera", 3}})};
    expectFault(g.writeGlb(testDir(), "camera_index"), {"nodes[1]", "cameras[3] out of range (1 cameras)"});

    Gltf zeroScale = oneTriangle();
    zeroScale.doc["cameras"] = {perspective(1.0, 0.1)};
    zeroScale.doc["scenes"][0]["nodes"] = {0, zeroScale.node({{"camera", 0}, {"scale", {0, 0, 0}}})};
    expectFault(zeroScale.writeGlb(testDir(), "camera_zero_scale"), {"cameras[0]", "nodes[1]", "direction"});
}

TEST(GltfCameras, AFileWithoutCamerasHasNone) {
    EXPECT_TRUE(load(oneTriangle().writeGlb(testDir(), "no_cameras")).cameras.empty());
}

// Vertices no index uses (a 20x20 floor before the quad's corners, two strays after) are not
// part of the scene: dropped at load, so they widen neither the bounds nor anything fitted to
// them (issue 61's repro: its light landed under the quad once they counted). The colours that
// go with the kept vertices stay with them.
TEST(GltfGeometry, VerticesNoIndexUsesAreDropped) {
    Gltf g;
    const std::vector<glm::vec3> positions{{-10, 0, -10}, {10, 0, -10}, {10, 0, 10}, {-10, 0, 10},  // unused floor
                                           {-1, 2, -1},   {1, 2, -1},   {1, 2, 1},   {-1, 2, 1},    // the quad
                                           {500, 9, 0},   {0, -300, 0}};                              // unused strays
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0, 1, 0));
    std::vector<glm::vec4> colors;
    for (std::size_t i = 0; i < positions.size(); ++i) colors.emplace_back(float(i) / 16.0f, 0.5f, 0.25f, 1.0f);
    const int colorAccessor = g.accessor(g.view(colors.data(), colors.size() * 16), kFloat, colors.size(), "VEC4");
    const json attributes = {{"POSITION", g.vec3(positions)}, {"NORMAL", g.vec3(normals)}, {"COLOR_0", colorAccessor}};
    const int mesh = g.mesh({primitive(attributes, g.indices({4, 6, 5, 4, 7, 6}))});
    g.scene({g.node({{"mesh", mesh}})});
    std::vector<std::string> warnings;
    const Scene scene = load(g.writeGltf(testDir(), "unused_vertices"), warnings);
    ASSERT_EQ(scene.vertices.size(), 4u);
    EXPECT_EQ(scene.bounds.min, glm::vec3(-1, 2, -1));
    EXPECT_EQ(scene.bounds.max, glm::vec3(1, 2, 1));
    ASSERT_EQ(scene.colors.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(scene.vertices[i].position, positions[4 + i]);
        EXPECT_FLOAT_EQ(scene.colors[i].r, float(4 + i) / 16.0f);
    }
    EXPECT_EQ(scene.indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
}

}  // namespace
}  // namespace ml
