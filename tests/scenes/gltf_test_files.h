// Writing small glTF and GLB files for tests, and the expectations the glTF tests share. The
// files land under $ML_TEST_TMP/gltf_loader/<suite>.<test>/, which the fuzzer takes as seeds.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "scenes/gltf_loader.h"

namespace ml::gltf_test {

namespace fs = std::filesystem;
using json = nlohmann::json;

inline constexpr int kUByte = 5121, kUShort = 5123, kUInt = 5125, kFloat = 5126;

// --- Files -----------------------------------------------------------------------------------------

inline fs::path testDir() {
    const char* env = std::getenv("ML_TEST_TMP");
    const fs::path root = (env != nullptr && *env != '\0') ? fs::path(env) : fs::temp_directory_path();
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = root / "gltf_loader" / (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

inline void writeBytes(const fs::path& file, const void* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    ASSERT_TRUE(out.good()) << file;
}

inline void writeText(const fs::path& file, const std::string& text) { writeBytes(file, text.data(), text.size()); }

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t b0 = bytes[i];
        const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const std::uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t triple = b0 << 16 | b1 << 8 | b2;
        out += kAlphabet[(triple >> 18) & 63];
        out += kAlphabet[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
    }
    return out;
}

inline std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> png;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<std::uint8_t>*>(context);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out->insert(out->end(), bytes, bytes + size);
    };
    EXPECT_NE(stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4), 0);
    return png;
}

inline void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

// A GLB container: header, JSON chunk, and a BIN chunk when there are bytes for one.
inline std::vector<std::uint8_t> glbBytes(const json& doc, std::vector<std::uint8_t> bin) {
    std::string text = doc.dump();
    while (text.size() % 4 != 0) text += ' ';
    while (bin.size() % 4 != 0) bin.push_back(0);
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    std::vector<std::uint8_t> out;
    putU32(out, 0x46546C67);
    putU32(out, 2);
    putU32(out, static_cast<std::uint32_t>(total));
    putU32(out, static_cast<std::uint32_t>(text.size()));
    putU32(out, 0x4E4F534A);
    out.insert(out.end(), text.begin(), text.end());
    if (!bin.empty()) {
        putU32(out, static_cast<std::uint32_t>(bin.size()));
        putU32(out, 0x004E4942);
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

// --- A small glTF builder --------------------------------------------------------------------------

// Builds a glTF document with one binary buffer; views and accessors are appended as data goes in.
class Gltf {
public:
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<std::uint8_t> bin;
    std::vector<json> moreBuffers;  // buffers 1.., written as they are after buffer 0

    int add(const char* array, json value) {
        json& list = doc[array];
        if (list.is_null()) list = json::array();
        list.push_back(std::move(value));
        return static_cast<int>(list.size()) - 1;
    }

    // Appends bytes (4-byte aligned) to buffer 0 as a new buffer view.
    int view(const void* data, std::size_t size, std::size_t stride = 0) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", size}};
        if (stride != 0) v["byteStride"] = stride;
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), bytes, bytes + size);
        return add("bufferViews", v);
    }

    int accessor(int bufferView, int componentType, std::size_t count, const char* type, const json& extra = json::object()) {
        json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (bufferView >= 0) a["bufferView"] = bufferView;
        a.update(extra);
        return add("accessors", a);
    }

    int vec3(const std::vector<glm::vec3>& v) { return accessor(view(v.data(), v.size() * 12), kFloat, v.size(), "VEC3"); }
    int vec2(const std::vector<glm::vec2>& v) { return accessor(view(v.data(), v.size() * 8), kFloat, v.size(), "VEC2"); }
    int indices(const std::vector<std::uint16_t>& v) {
        return accessor(view(v.data(), v.size() * 2), kUShort, v.size(), "SCALAR");
    }

    int mesh(const std::vector<json>& primitives) {
        json m = json::object();
        m["primitives"] = primitives;
        return add("meshes", m);
    }
    int node(const json& n) { return add("nodes", n); }
    void scene(const std::vector<int>& roots) {
        json s = json::object();
        s["nodes"] = roots;
        doc["scenes"] = json::array({s});
        doc["scene"] = 0;
    }

    // name.gltf, with buffer 0 in name.bin beside it.
    fs::path writeGltf(const fs::path& dir, const std::string& name) const {
        json d = doc;
        if (!bin.empty()) {
            writeBytes(dir / (name + ".bin"), bin.data(), bin.size());
            d["buffers"] = json::array({{{"byteLength", bin.size()}, {"uri", name + ".bin"}}});
        }
        for (const json& b : moreBuffers) d["buffers"].push_back(b);
        writeText(dir / (name + ".gltf"), d.dump());
        return dir / (name + ".gltf");
    }

    // name.gltf, with buffer 0 embedded as a base64 data URI.
    fs::path writeEmbedded(const fs::path& dir, const std::string& name) const {
        json d = doc;
        d["buffers"] = json::array(
            {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        for (const json& b : moreBuffers) d["buffers"].push_back(b);
        writeText(dir / (name + ".gltf"), d.dump());
        return dir / (name + ".gltf");
    }

    std::vector<std::uint8_t> glb() const {
        json d = doc;
        if (!bin.empty()) d["buffers"] = json::array({{{"byteLength", bin.size()}}});
        for (const json& b : moreBuffers) d["buffers"].push_back(b);
        return glbBytes(d, bin);
    }

    fs::path writeGlb(const fs::path& dir, const std::string& name) const {
        const std::vector<std::uint8_t> bytes = glb();
        writeBytes(dir / (name + ".glb"), bytes.data(), bytes.size());
        return dir / (name + ".glb");
    }
};

inline json primitive(const json& attributes, int indices = -1, int material = -1) {
    json p = json::object();
    p["attributes"] = attributes;
    if (indices >= 0) p["indices"] = indices;
    if (material >= 0) p["material"] = material;
    return p;
}

// One triangle in the XY plane, counter-clockwise seen from +Z, as an indexed primitive.
inline json trianglePrimitive(Gltf& g, bool withNormals = true, int material = -1) {
    json attributes = {{"POSITION", g.vec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}};
    if (withNormals) attributes["NORMAL"] = g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    return primitive(attributes, g.indices({0, 1, 2}), material);
}

// A file with a single node drawing a single triangle: the base that fault tests break.
inline Gltf oneTriangle() {
    Gltf g;
    const int mesh = g.mesh({trianglePrimitive(g)});
    g.scene({g.node({{"mesh", mesh}})});
    return g;
}

// --- Expectations ----------------------------------------------------------------------------------

inline Scene load(const fs::path& file, std::vector<std::string>& warnings) { return loadGltf(file.string(), warnings); }

inline Scene load(const fs::path& file) {
    std::vector<std::string> warnings;
    return load(file, warnings);
}

// The file must be refused with one SceneError line that names the file and holds each keyword.
inline void expectFault(const fs::path& file, std::initializer_list<const char*> keywords) {
    std::vector<std::string> warnings;
    try {
        loadGltf(file.string(), warnings);
        ADD_FAILURE() << file << " loaded; expected a SceneError";
    } catch (const SceneError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find_first_of("\r\n"), std::string::npos) << "not one line: " << message;
        EXPECT_NE(message.find(file.filename().string()), std::string::npos) << "no file name in: " << message;
        for (const char* keyword : keywords)
            EXPECT_NE(message.find(keyword), std::string::npos) << "no '" << keyword << "' in: " << message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << file << ": expected a SceneError, got: " << e.what();
    }
}

inline std::size_t countContaining(const std::vector<std::string>& lines, const std::string& part) {
    std::size_t n = 0;
    for (const std::string& line : lines) n += line.find(part) != std::string::npos;
    return n;
}

inline void expectOneLineWarnings(const std::vector<std::string>& warnings, const fs::path& file) {
    for (const std::string& w : warnings) {
        EXPECT_EQ(w.find_first_of("\r\n"), std::string::npos) << w;
        EXPECT_NE(w.find(file.filename().string()), std::string::npos) << w;
    }
}

// Loads the file, which must warn exactly once: one line naming the file and holding each keyword.
inline Scene loadWithOneWarning(const fs::path& file, std::initializer_list<const char*> keywords) {
    std::vector<std::string> warnings;
    Scene scene = load(file, warnings);
    EXPECT_EQ(warnings.size(), 1u);
    expectOneLineWarnings(warnings, file);
    for (const char* keyword : keywords)
        EXPECT_EQ(countContaining(warnings, keyword), 1u) << "no '" << keyword << "' in: " << (warnings.empty() ? "" : warnings[0]);
    return scene;
}

inline void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance) << "y " << actual.y << " z " << actual.z;
    EXPECT_NEAR(actual.y, expected.y, tolerance) << "x " << actual.x << " z " << actual.z;
    EXPECT_NEAR(actual.z, expected.z, tolerance) << "x " << actual.x << " y " << actual.y;
}

// The geometric normal of triangle t in index order (counter-clockwise front face).
inline glm::vec3 faceNormal(const Scene& s, std::size_t t) {
    const glm::vec3 a = s.vertices[s.indices[3 * t]].position;
    const glm::vec3 b = s.vertices[s.indices[3 * t + 1]].position;
    const glm::vec3 c = s.vertices[s.indices[3 * t + 2]].position;
    return glm::normalize(glm::cross(b - a, c - a));
}

// A scene's triangles as a reader sees them, whatever order the file stored them in: each
// triangle's corners rotated (winding kept) to start at the smallest position, the triangles
// sorted. Compressed files reorder both.
struct Corner {
    glm::vec3 position, normal;
    glm::vec2 uv;
    glm::vec4 tangent{0.0f}, colour{1.0f};
};
using CornerTriangle = std::array<Corner, 3>;

inline bool positionLess(const glm::vec3& a, const glm::vec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

inline std::vector<CornerTriangle> canonicalTriangles(const Scene& s) {
    std::vector<CornerTriangle> triangles;
    for (std::size_t t = 0; t < s.indices.size() / 3; ++t) {
        CornerTriangle tri;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = s.indices[3 * t + k];
            tri[k] = {s.vertices[i].position, s.vertices[i].normal, s.vertices[i].uv,
                      s.tangents.empty() ? glm::vec4(0.0f) : s.tangents[i], s.colors.empty() ? glm::vec4(1.0f) : s.colors[i]};
        }
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (positionLess(tri[k].position, tri[first].position)) first = k;
        std::rotate(tri.begin(), tri.begin() + first, tri.end());
        triangles.push_back(tri);
    }
    std::sort(triangles.begin(), triangles.end(), [](const CornerTriangle& a, const CornerTriangle& b) {
        for (int k = 0; k < 3; ++k)
            if (a[k].position != b[k].position) return positionLess(a[k].position, b[k].position);
        return false;
    });
    return triangles;
}

struct CornerTolerance {
    float position = 0.0f, normal = 1e-6f, uv = 1e-6f, tangent = 1e-6f, colour = 1e-6f;
};

// Both scenes hold the same triangles, corner by corner, within the tolerances.
inline void expectSameTriangles(const Scene& actual, const Scene& expected, const CornerTolerance& tol) {
    const std::vector<CornerTriangle> a = canonicalTriangles(actual), e = canonicalTriangles(expected);
    ASSERT_EQ(a.size(), e.size());
    const auto near = [](auto x, auto y, float t) { return glm::all(glm::lessThanEqual(glm::abs(x - y), decltype(x)(t))); };
    std::size_t mismatches = 0;
    for (std::size_t t = 0; t < a.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const Corner &x = a[t][k], &y = e[t][k];
            const bool same = near(x.position, y.position, tol.position) && near(x.normal, y.normal, tol.normal) &&
                              near(x.uv, y.uv, tol.uv) && near(x.tangent, y.tangent, tol.tangent) &&
                              near(x.colour, y.colour, tol.colour);
            if (!same && ++mismatches <= 3)
                ADD_FAILURE() << "triangle " << t << " corner " << k << ": position (" << x.position.x << ", " << x.position.y
                              << ", " << x.position.z << ") vs (" << y.position.x << ", " << y.position.y << ", "
                              << y.position.z << "), normal (" << x.normal.x << ", " << x.normal.y << ", " << x.normal.z
                              << ") vs (" << y.normal.x << ", " << y.normal.y << ", " << y.normal.z << "), uv (" << x.uv.x
                              << ", " << x.uv.y << ") vs (" << y.uv.x << ", " << y.uv.y << ")";
        }
    }
    EXPECT_EQ(mismatches, 0u);
}

// A metallic-roughness material of one colour, non-metallic; BLEND where alpha < 1 is asked for.
inline int colourMaterial(Gltf& g, glm::vec4 colour, const char* alphaMode, bool doubleSided = false, float roughness = 0.4f) {
    return g.add("materials", {{"pbrMetallicRoughness",
                                {{"baseColorFactor", {colour.r, colour.g, colour.b, colour.a}}, {"metallicFactor", 0.0}, {"roughnessFactor", roughness}}},
                               {"alphaMode", alphaMode},
                               {"doubleSided", doubleSided}});
}

// The camera the GPU tests of generated files look at their squares from (down -z at z = 4).
inline const CameraPose kFrontView{{0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f};

// A square in the plane z = `z` facing +z, half-size `half`, UVs (0, 0) at the top left to
// (1, 1) at the bottom right (glTF's v runs down the image), scaled by `uvScale`.
inline json square(Gltf& g, float z, float half, int material, const json& extraAttributes = json::object(), float uvScale = 1.0f) {
    json attributes = {{"POSITION", g.vec3({{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}})},
                       {"NORMAL", g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                       {"TEXCOORD_0", g.vec2({{0, uvScale}, {uvScale, uvScale}, {uvScale, 0}, {0, 0}})}};
    attributes.update(extraAttributes);
    return primitive(attributes, g.indices({0, 1, 2, 0, 2, 3}), material);
}

// Writes the file as GLB (self-contained, so the fuzzer can take it as a seed) into the test's
// directory and loads it.
inline Scene writeAndLoad(Gltf& g, const std::vector<json>& primitives, const std::string& name) {
    static std::string currentTest;
    static fs::path dir;
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    if (test != currentTest) {  // testDir() empties the directory: once per test
        currentTest = test;
        dir = testDir();
    }
    g.scene({g.node({{"mesh", g.mesh(primitives)}})});
    const fs::path file = g.writeGlb(dir, name);
    std::vector<std::string> warnings;
    Scene scene = loadGltf(file.string(), warnings);
    for (const std::string& w : warnings) std::printf("warning: %s\n", w.c_str());
    return scene;
}

}  // namespace ml::gltf_test
