// EXT_meshopt_compression: buffer views compressed with meshoptimizer's encoders (vertex streams
// with each filter, triangle and sequence index streams) in a fallback buffer without a uri load
// into the triangles of the uncompressed twin, in a .gltf and a .glb; an optional extension falls
// back to the view's own bytes with one warning; a bad header or a truncated stream of a required
// one is one line naming the view and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <meshoptimizer.h>

#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

inline constexpr int kByte = 5120, kShort = 5122;

// Two primitives over one vertex block: the first indexed as a triangle list, the second as a
// plain index sequence.
struct Mesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> triangles, sequence;
};

Mesh smallMesh() {
    Mesh m;
    for (int i = 0; i < 6; ++i) {
        const float a = 0.9f * float(i);
        m.positions.emplace_back(std::cos(a) * 1.5f, std::sin(a), 0.25f * float(i) - 3.0f);
        m.normals.push_back(glm::normalize(glm::vec3(std::cos(a), std::sin(a), 0.5f)));
        m.uvs.emplace_back(0.125f * float(i), 1.0f - 0.0625f * float(i * i));
    }
    m.triangles = {0, 1, 2, 0, 2, 3};
    m.sequence = {3, 4, 5, 5, 4, 0};
    return m;
}

struct Stream {
    std::vector<std::uint8_t> bytes;
    std::size_t count, stride;
    const char* mode;
    const char* filter;
};

Stream vertexStream(const void* data, std::size_t count, std::size_t stride, const char* filter = "NONE") {
    std::vector<std::uint8_t> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
    return {out, count, stride, "ATTRIBUTES", filter};
}

Stream indexStream(const std::vector<std::uint32_t>& indices, std::size_t vertices, bool triangles) {
    std::vector<std::uint8_t> out(triangles ? meshopt_encodeIndexBufferBound(indices.size(), vertices)
                                            : meshopt_encodeIndexSequenceBound(indices.size(), vertices));
    out.resize(triangles ? meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), indices.size())
                         : meshopt_encodeIndexSequence(out.data(), out.size(), indices.data(), indices.size()));
    return {out, indices.size(), 4, triangles ? "TRIANGLES" : "INDICES", "NONE"};
}

// The file's compressed streams.
struct Streams {
    Stream positions, normals, uvs, triangles, sequence;
};

Streams encode(const Mesh& m) {
    Streams s;
    s.positions = vertexStream(m.positions.data(), m.positions.size(), 12);
    // Normals as 8-bit octahedral (4 bytes each, KHR_mesh_quantization's normalized BYTE).
    std::vector<glm::vec4> normals;
    for (const glm::vec3& n : m.normals) normals.emplace_back(n, 0.0f);
    std::vector<std::uint8_t> oct(4 * m.normals.size());
    meshopt_encodeFilterOct(oct.data(), m.normals.size(), 4, 8, &normals[0].x);
    s.normals = vertexStream(oct.data(), m.normals.size(), 4, "OCTAHEDRAL");
    // Texture coordinates with 16-bit mantissas (8 bytes each).
    std::vector<std::uint8_t> exp(8 * m.uvs.size());
    meshopt_encodeFilterExp(exp.data(), m.uvs.size(), 8, 16, &m.uvs[0].x);
    s.uvs = vertexStream(exp.data(), m.uvs.size(), 8, "EXPONENTIAL");
    s.triangles = indexStream(m.triangles, m.positions.size(), true);
    s.sequence = indexStream(m.sequence, m.positions.size(), false);
    return s;
}

struct FileOptions {
    bool required = true;
    bool fallbackBytes = false;  // buffer 1 holds the uncompressed bytes (else it is a fallback without a uri)
};

// The mesh with its views compressed into buffer 0 and decoded into buffer 1.
Gltf meshoptFile(const Mesh& m, const Streams& s, const FileOptions& options) {
    Gltf g;
    std::vector<std::uint8_t> plain;  // buffer 1's bytes, as decoded
    const auto compressed = [&](const Stream& stream, const void* decoded, bool vertex) {
        const std::size_t source = g.view(stream.bytes.data(), stream.bytes.size());
        const json sourceView = g.doc["bufferViews"][source];
        g.doc["bufferViews"].erase(source);  // only its bytes stay in buffer 0
        while (plain.size() % 4 != 0) plain.push_back(0);
        const std::size_t length = stream.count * stream.stride;
        json view = {{"buffer", 1}, {"byteOffset", plain.size()}, {"byteLength", length}};
        if (vertex) view["byteStride"] = stream.stride;
        const auto* bytes = static_cast<const std::uint8_t*>(decoded);
        plain.insert(plain.end(), bytes, bytes + length);
        json ext = {{"buffer", 0}, {"byteOffset", sourceView["byteOffset"]}, {"byteLength", stream.bytes.size()},
                    {"byteStride", stream.stride}, {"count", stream.count}, {"mode", stream.mode}};
        if (std::string(stream.filter) != "NONE") ext["filter"] = stream.filter;
        view["extensions"] = {{"EXT_meshopt_compression", ext}};
        return g.add("bufferViews", view);
    };
    // What the filtered streams decode to: a fallback holds the same values.
    const auto filteredBytes = [](const Stream& stream, void (*filter)(void*, std::size_t, std::size_t)) {
        std::vector<std::uint8_t> out(stream.count * stream.stride);
        if (meshopt_decodeVertexBuffer(out.data(), stream.count, stream.stride, stream.bytes.data(), stream.bytes.size()) == 0)
            filter(out.data(), stream.count, stream.stride);
        return out;
    };
    const std::vector<std::uint8_t> decodedNormals = filteredBytes(s.normals, meshopt_decodeFilterOct);
    const std::vector<std::uint8_t> decodedUvs = filteredBytes(s.uvs, meshopt_decodeFilterExp);

    const int positions = g.accessor(compressed(s.positions, m.positions.data(), true), kFloat, m.positions.size(), "VEC3");
    const int normals = g.accessor(compressed(s.normals, decodedNormals.data(), true), kByte, m.normals.size(), "VEC3",
                                   {{"normalized", true}});
    const int uv = g.accessor(compressed(s.uvs, decodedUvs.data(), true), kFloat, m.uvs.size(), "VEC2");
    const int triangles = g.accessor(compressed(s.triangles, m.triangles.data(), false), kUInt, m.triangles.size(), "SCALAR");
    const int sequence = g.accessor(compressed(s.sequence, m.sequence.data(), false), kUInt, m.sequence.size(), "SCALAR");
    const json attributes = {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uv}};
    g.scene({g.node({{"mesh", g.mesh({primitive(attributes, triangles), primitive(attributes, sequence)})}})});

    json buffer = {{"byteLength", plain.size()}};
    if (options.fallbackBytes) buffer["uri"] = "data:application/octet-stream;base64," + base64(plain);
    else buffer["extensions"] = {{"EXT_meshopt_compression", {{"fallback", true}}}};
    g.moreBuffers.push_back(buffer);
    g.doc["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    g.doc["extensionsRequired"] = options.required ? json{"EXT_meshopt_compression", "KHR_mesh_quantization"}
                                                   : json{"KHR_mesh_quantization"};
    return g;
}

// The same mesh stored plainly, floats throughout.
Gltf plainFile(const Mesh& m) {
    Gltf g;
    const json attributes = {{"POSITION", g.vec3(m.positions)}, {"NORMAL", g.vec3(m.normals)}, {"TEXCOORD_0", g.vec2(m.uvs)}};
    const auto indices = [&](const std::vector<std::uint32_t>& v) { return g.accessor(g.view(v.data(), 4 * v.size()), kUInt, v.size(), "SCALAR"); };
    g.scene({g.node({{"mesh", g.mesh({primitive(attributes, indices(m.triangles)), primitive(attributes, indices(m.sequence))})}})});
    return g;
}

// 8-bit octahedral normals are good to about 1/127 a component; 16-bit mantissas to 2^-15.
CornerTolerance filtered() { return {0.0f, 0.02f, 4e-5f, 1e-6f, 1e-6f}; }

TEST(GltfMeshopt, FallbackBufferWithoutUriDecodesToTheUncompressedTriangles) {
    const Mesh m = smallMesh();
    const Streams s = encode(m);
    const fs::path dir = testDir();
    const Scene plain = load(plainFile(m).writeGltf(dir, "plain"));
    for (const fs::path& file : {meshoptFile(m, s, {}).writeGltf(dir, "packed"), meshoptFile(m, s, {}).writeGlb(dir, "packed")}) {
        std::vector<std::string> warnings;
        const Scene decoded = load(file, warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        EXPECT_EQ(decoded.triangleCount(), 4u) << file;
        expectSameTriangles(decoded, plain, filtered());
    }
}

TEST(GltfMeshopt, QuaternionFilteredInstanceRotationsDecode) {
    // Instances rotated 90 degrees about +y and +z, their rotations as 12-bit quaternions.
    const float h = std::sqrt(0.5f);
    const std::vector<glm::vec4> rotations = {{0, h, 0, h}, {0, 0, h, h}};
    std::vector<std::uint8_t> quat(8 * rotations.size());
    meshopt_encodeFilterQuat(quat.data(), rotations.size(), 8, 12, &rotations[0].x);
    const Stream stream = vertexStream(quat.data(), rotations.size(), 8, "QUATERNION");

    Gltf g;
    g.view(stream.bytes.data(), stream.bytes.size());  // bufferViews[0]: the stream's bytes in buffer 0
    const int rotationView = g.add("bufferViews", {{"buffer", 1}, {"byteLength", 16}, {"byteStride", 8},
                                                    {"extensions", {{"EXT_meshopt_compression",
                                                                     {{"buffer", 0}, {"byteLength", stream.bytes.size()}, {"byteStride", 8},
                                                                      {"count", 2}, {"mode", "ATTRIBUTES"}, {"filter", "QUATERNION"}}}}}});
    const int rotation = g.accessor(rotationView, kShort, 2, "VEC4", {{"normalized", true}});
    const int mesh = g.mesh({trianglePrimitive(g)});
    g.scene({g.node({{"mesh", mesh}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"ROTATION", rotation}}}}}}}})});
    g.moreBuffers.push_back({{"byteLength", 16}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    g.doc["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization", "EXT_mesh_gpu_instancing"};
    g.doc["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    const Scene scene = load(g.writeGltf(testDir(), "rotations"));
    ASSERT_EQ(scene.vertices.size(), 6u);
    // The triangle (0,0,0) (1,0,0) (0,1,0): +x turns to -z about +y, and to +y about +z.
    expectNear(scene.vertices[1].position, {0, 0, -1}, 2e-3f);
    expectNear(scene.vertices[4].position, {0, 1, 0}, 2e-3f);
    expectNear(scene.vertices[5].position, {-1, 0, 0}, 2e-3f);
}

TEST(GltfMeshopt, OptionalFallsBackToTheViewsOwnBytesWithOneWarning) {
    const Mesh m = smallMesh();
    Streams s = encode(m);
    s.positions.bytes[0] = 0xFF;  // not a vertex stream header
    const fs::path dir = testDir();
    const Scene plain = load(plainFile(m).writeGltf(dir, "plain"));
    const Scene fallback = loadWithOneWarning(meshoptFile(m, s, {false, true}).writeGltf(dir, "optional"),
                                              {"bufferViews[0]: EXT_meshopt_compression", "bad header", "uncompressed bytes are used instead"});
    expectSameTriangles(fallback, plain, filtered());
}

TEST(GltfMeshopt, BadHeaderIsOneLineNamingTheView) {
    const Mesh m = smallMesh();
    Streams s = encode(m);
    s.normals.bytes[0] = 0x00;
    expectFault(meshoptFile(m, s, {}).writeGlb(testDir(), "bad_header"), {"bufferViews[1]", "EXT_meshopt_compression", "bad header"});
}

TEST(GltfMeshopt, TruncatedStreamIsOneLine) {
    const Mesh m = smallMesh();
    Streams s = encode(m);
    s.triangles.bytes.resize(s.triangles.bytes.size() / 2);
    expectFault(meshoptFile(m, s, {}).writeGltf(testDir(), "truncated"), {"bufferViews[3]", "EXT_meshopt_compression", "truncated"});
}

TEST(GltfMeshopt, SizesTheDecodersDoNotTakeAreOneLine) {
    const Mesh m = smallMesh();
    const Streams s = encode(m);
    const auto breakView = [&](const char* name, int view, const char* key, const json& value,
                               std::initializer_list<const char*> keywords) {
        Gltf g = meshoptFile(m, s, {});
        g.doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"][key] = value;
        expectFault(g.writeGltf(testDir(), name), keywords);
    };
    breakView("stride", 0, "byteStride", 6, {"bufferViews[0]", "byteStride 6"});
    breakView("mode", 0, "mode", "STRIPS", {"bufferViews[0]", "unknown mode 'STRIPS'"});
    breakView("filter", 3, "filter", "OCTAHEDRAL", {"bufferViews[3]", "filters apply to ATTRIBUTES"});
    breakView("count", 3, "count", 5, {"bufferViews[3]", "not a multiple of 3"});
    // A count no stream of that size can decode to is refused before anything is allocated.
    breakView("expansion", 0, "count", 100000000, {"bufferViews[0]", "more than", "compressed bytes can hold"});
    breakView("source", 0, "byteLength", 1 << 20, {"bufferViews[0]", "overruns buffers[0]"});
}

}  // namespace
}  // namespace ml
