// KHR_draco_mesh_compression: a file whose primitive is a Draco stream (written here with
// libdraco's encoder) loads into the same triangles as its uncompressed twin, required or
// optional as the file says, and a stream that cannot be decoded is one line naming the mesh,
// the primitive and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

// A bent grid of 4 x 3 quads, every stream the loader reads varying per vertex.
struct Grid {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> tangents, colours;
    std::vector<std::uint16_t> indices;
};

Grid bentGrid() {
    Grid g;
    const int nx = 4, ny = 3;
    for (int y = 0; y <= ny; ++y) {
        for (int x = 0; x <= nx; ++x) {
            const float u = float(x) / nx, v = float(y) / ny, angle = 0.6f * u;
            g.positions.emplace_back(std::sin(angle) * 2.0f, v * 1.5f, 0.3f * std::cos(angle) + 0.1f * v);
            g.normals.push_back(glm::normalize(glm::vec3(-std::sin(angle), 0.1f * v, std::cos(angle))));
            g.uvs.emplace_back(u, 1.0f - v);
            g.tangents.emplace_back(glm::normalize(glm::vec3(std::cos(angle), 0.0f, std::sin(angle))), x % 2 ? 1.0f : -1.0f);
            g.colours.emplace_back(u, v, 0.5f, 1.0f - 0.5f * u);
        }
    }
    for (int y = 0; y < ny; ++y) {
        for (int x = 0; x < nx; ++x) {
            const auto i = static_cast<std::uint16_t>(y * (nx + 1) + x);
            const auto right = static_cast<std::uint16_t>(i + 1), up = static_cast<std::uint16_t>(i + nx + 1);
            g.indices.insert(g.indices.end(), {i, right, static_cast<std::uint16_t>(up + 1), i, static_cast<std::uint16_t>(up + 1), up});
        }
    }
    return g;
}

// A normal-mapped material, so that the tangent stream is kept.
int normalMappedMaterial(Gltf& g) {
    const std::vector<std::uint8_t> flat = {128, 128, 255, 255};
    g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(1, 1, flat))}});
    g.add("textures", {{"source", 0}});
    return g.add("materials", {{"normalTexture", {{"index", 0}}}});
}

int vec4(Gltf& g, const std::vector<glm::vec4>& v) { return g.accessor(g.view(v.data(), v.size() * 16), kFloat, v.size(), "VEC4"); }

json plainAttributes(Gltf& g, const Grid& grid) {
    return {{"POSITION", g.vec3(grid.positions)}, {"NORMAL", g.vec3(grid.normals)}, {"TEXCOORD_0", g.vec2(grid.uvs)},
            {"TANGENT", vec4(g, grid.tangents)}, {"COLOR_0", vec4(g, grid.colours)}};
}

Gltf uncompressedGrid(const Grid& grid) {
    Gltf g;
    const int material = normalMappedMaterial(g);
    g.scene({g.node({{"mesh", g.mesh({primitive(plainAttributes(g, grid), g.indices(grid.indices), material)})}})});
    return g;
}

struct DracoStream {
    std::vector<std::uint8_t> bytes;
    std::size_t points = 0, faces = 0;
    json attributes;  // glTF name -> Draco unique id
};

// The grid as a Draco mesh; positions quantized to `positionBits` (0: stored exactly).
DracoStream encodeDraco(const Grid& grid, int positionBits) {
    const int faces = static_cast<int>(grid.indices.size() / 3);
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(faces);
    DracoStream out;
    const auto add = [&](draco::GeometryAttribute::Type type, int components, const float* values) {
        const int id = builder.AddAttribute(type, static_cast<std::int8_t>(components), draco::DT_FLOAT32);
        for (int f = 0; f < faces; ++f) {
            const auto corner = [&](int k) { return values + components * grid.indices[3 * f + k]; };
            builder.SetAttributeValuesForFace(id, draco::FaceIndex(f), corner(0), corner(1), corner(2));
        }
        return id;
    };
    const int position = add(draco::GeometryAttribute::POSITION, 3, &grid.positions[0].x);
    const int normal = add(draco::GeometryAttribute::NORMAL, 3, &grid.normals[0].x);
    const int uv = add(draco::GeometryAttribute::TEX_COORD, 2, &grid.uvs[0].x);
    const int tangent = add(draco::GeometryAttribute::GENERIC, 4, &grid.tangents[0].x);
    const int colour = add(draco::GeometryAttribute::COLOR, 4, &grid.colours[0].x);
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    EXPECT_TRUE(mesh);
    const auto uniqueId = [&](int id) { return mesh->attribute(id)->unique_id(); };
    out.attributes = {{"POSITION", uniqueId(position)}, {"NORMAL", uniqueId(normal)}, {"TEXCOORD_0", uniqueId(uv)},
                      {"TANGENT", uniqueId(tangent)}, {"COLOR_0", uniqueId(colour)}};
    draco::Encoder encoder;
    if (positionBits > 0) encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, positionBits);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(*mesh, &buffer);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
    out.points = mesh->num_points();
    out.faces = mesh->num_faces();
    return out;
}

enum class Fallback { None, Uncompressed };

// The grid with its primitive compressed; with a fallback, the primitive's accessors also hold
// `fallbackGrid`'s data, as an exporter writes an optional extension.
Gltf dracoGrid(const DracoStream& draco, bool required, const Grid* fallbackGrid = nullptr) {
    Gltf g;
    const int material = normalMappedMaterial(g);
    const int view = g.view(draco.bytes.data(), draco.bytes.size());
    json attributes, indices;
    if (fallbackGrid) {
        attributes = plainAttributes(g, *fallbackGrid);
        indices = g.indices(fallbackGrid->indices);
    } else {
        const auto declared = [&](const char* type) { return g.accessor(-1, kFloat, draco.points, type); };
        attributes = {{"POSITION", declared("VEC3")}, {"NORMAL", declared("VEC3")}, {"TEXCOORD_0", declared("VEC2")},
                      {"TANGENT", declared("VEC4")}, {"COLOR_0", declared("VEC4")}};
        indices = g.accessor(-1, kUShort, 3 * draco.faces, "SCALAR");
    }
    json prim = primitive(attributes, indices.get<int>(), material);
    prim["extensions"] = {{"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", draco.attributes}}}};
    g.scene({g.node({{"mesh", g.mesh({prim})}})});
    g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    if (required) g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return g;
}

CornerTolerance exact() { return {0.0f, 1e-6f, 1e-6f, 1e-6f, 1e-6f}; }

TEST(GltfDraco, RequiredDecodesToTheTrianglesOfTheUncompressedFile) {
    const Grid grid = bentGrid();
    const fs::path dir = testDir();
    const Scene plain = load(uncompressedGrid(grid).writeGltf(dir, "plain"));
    const DracoStream draco = encodeDraco(grid, 0);
    // .gltf and .glb: the indices set aside for tinygltf come back through either container.
    for (const fs::path& file : {dracoGrid(draco, true).writeGltf(dir, "draco"), dracoGrid(draco, true).writeGlb(dir, "draco")}) {
        std::vector<std::string> warnings;
        const Scene decoded = load(file, warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        EXPECT_EQ(decoded.triangleCount(), grid.indices.size() / 3);
        ASSERT_EQ(decoded.tangents.size(), decoded.vertices.size()) << "tangents decoded";
        ASSERT_EQ(decoded.colors.size(), decoded.vertices.size()) << "colours decoded";
        expectSameTriangles(decoded, plain, exact());
    }
}

TEST(GltfDraco, QuantizedPositionsStayWithinTheQuantizationStep) {
    const Grid grid = bentGrid();
    const fs::path dir = testDir();
    const Scene plain = load(uncompressedGrid(grid).writeGltf(dir, "plain"));
    const Scene decoded = load(dracoGrid(encodeDraco(grid, 11), true).writeGlb(dir, "quantized"));
    // 11 bits over the largest extent (1.5 along y): half a step of 1.5 / 2047 at most.
    CornerTolerance tol = exact();
    tol.position = 0.5f * 1.5f / 2047.0f + 1e-6f;
    expectSameTriangles(decoded, plain, tol);
}

TEST(GltfDraco, OptionalPrefersTheDecodedStreamOverTheFallback) {
    const Grid grid = bentGrid();
    Grid moved = grid;  // the fallback differs, so the test sees which one was read
    for (glm::vec3& p : moved.positions) p.y += 10.0f;
    const fs::path dir = testDir();
    const Scene plain = load(uncompressedGrid(grid).writeGltf(dir, "plain"));
    std::vector<std::string> warnings;
    const Scene decoded = load(dracoGrid(encodeDraco(grid, 0), false, &moved).writeGltf(dir, "optional"), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    expectSameTriangles(decoded, plain, exact());
}

TEST(GltfDraco, OptionalFallsBackWithOneWarningWhenTheStreamIsBroken) {
    const Grid grid = bentGrid();
    DracoStream draco = encodeDraco(grid, 0);
    draco.bytes.resize(draco.bytes.size() / 2);
    const fs::path dir = testDir();
    const Scene plain = load(uncompressedGrid(grid).writeGltf(dir, "plain"));
    const Scene fallback = loadWithOneWarning(dracoGrid(draco, false, &grid).writeGltf(dir, "broken_optional"),
                                              {"meshes[0] primitive 0: KHR_draco_mesh_compression", "uncompressed accessors are used instead"});
    expectSameTriangles(fallback, plain, exact());
}

TEST(GltfDraco, TruncatedStreamIsOneLineNamingTheMeshAndPrimitive) {
    DracoStream draco = encodeDraco(bentGrid(), 0);
    draco.bytes.resize(draco.bytes.size() / 2);
    expectFault(dracoGrid(draco, true).writeGltf(testDir(), "truncated"),
                {"meshes[0] primitive 0", "KHR_draco_mesh_compression", "cannot decode bufferViews[0]"});
}

TEST(GltfDraco, NotADracoStreamIsOneLine) {
    DracoStream draco = encodeDraco(bentGrid(), 0);
    for (std::size_t i = 0; i < 5; ++i) draco.bytes[i] = 'X';  // "DRACO" is the stream's magic
    expectFault(dracoGrid(draco, true).writeGlb(testDir(), "not_draco"), {"meshes[0] primitive 0", "cannot decode"});
}

TEST(GltfDraco, UnknownAttributeIdIsOneLine) {
    DracoStream draco = encodeDraco(bentGrid(), 0);
    draco.attributes["NORMAL"] = 42;
    expectFault(dracoGrid(draco, true).writeGltf(testDir(), "unknown_id"), {"meshes[0] primitive 0", "NORMAL", "no attribute with id 42"});
}

TEST(GltfDraco, AttributeOfATypeGltfDoesNotHaveIsOneLine) {
    // Found by the fuzzer: a stream whose attribute holds bools (here mapped to TEXCOORD_0); Draco's
    // own conversion would load bytes that are not 0 or 1 as bools.
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(1);
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int flags = builder.AddAttribute(draco::GeometryAttribute::GENERIC, 2, draco::DT_BOOL);
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const bool flag[2] = {true, false};
    builder.SetAttributeValuesForFace(position, draco::FaceIndex(0), corners, corners + 3, corners + 6);
    builder.SetAttributeValuesForFace(flags, draco::FaceIndex(0), flag, flag, flag);
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    ASSERT_TRUE(mesh);
    draco::Encoder encoder;
    draco::EncoderBuffer buffer;
    ASSERT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
    DracoStream draco;
    draco.bytes.assign(buffer.data(), buffer.data() + buffer.size());
    draco.points = mesh->num_points();
    draco.faces = 1;
    draco.attributes = {{"POSITION", mesh->attribute(position)->unique_id()}, {"TEXCOORD_0", mesh->attribute(flags)->unique_id()}};
    Gltf g;
    const int view = g.view(draco.bytes.data(), draco.bytes.size());
    json prim = primitive({{"POSITION", g.accessor(-1, kFloat, draco.points, "VEC3")},
                           {"TEXCOORD_0", g.accessor(-1, kFloat, draco.points, "VEC2")}},
                          g.accessor(-1, kUShort, 3, "SCALAR"));
    prim["extensions"] = {{"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", draco.attributes}}}};
    g.scene({g.node({{"mesh", g.mesh({prim})}})});
    g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectFault(g.writeGlb(testDir(), "bool_attribute"), {"meshes[0] primitive 0", "TEXCOORD_0", "not a glTF component type"});
}

TEST(GltfDraco, BufferViewOutOfRangeIsOneLine) {
    Gltf g = dracoGrid(encodeDraco(bentGrid(), 0), true);
    g.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 9;
    expectFault(g.writeGltf(testDir(), "view_range"), {"meshes[0] primitive 0", "bufferView 9 out of range"});
}

}  // namespace
}  // namespace ml
