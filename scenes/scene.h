// The scene model: only what shading needs (design.md, "Modelling no more than a scene needs").
//
// Geometry is flattened to world space at load time: one vertex array, one index array, and a
// list of draw ranges that each name a material. Skins, morphs, animation, cameras and lights
// of a glTF file are not modelled; the loader skips them with one warning each.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ml {

// Mirrors the vertex layout of glsl/scene.vert (locations 0, 1, 2).
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};
static_assert(sizeof(Vertex) == 32, "Vertex is uploaded as-is; keep it tightly packed");

// An 8-bit RGBA image whose colour channels are sRGB-encoded (glTF baseColorTexture).
struct Image {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // width * height * 4 bytes, rows top to bottom
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    int baseColorTexture = -1;        // index into Scene::images, or -1
    float specularStrength = 0.25f;   // Blinn-Phong specular weight
    float shininess = 32.0f;          // Blinn-Phong exponent
    // glTF's doubleSided: false (the default) lets raster passes cull back faces, true draws
    // both sides (lit with the normal as given, as glTF asks for no flipping here).
    bool doubleSided = false;
};

// A contiguous run of triangles (3 indices each) drawn with one material.
struct DrawRange {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    std::uint32_t material = 0;
};

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 size() const { return max - min; }
};

// A camera placement a scene suggests for its default view.
struct CameraPose {
    glm::vec3 eye{0.0f, 1.0f, 5.0f};
    glm::vec3 target{0.0f};
    float fovyDegrees = 60.0f;
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<DrawRange> draws;
    std::vector<Material> materials;
    std::vector<Image> images;
    Bounds bounds;                           // of all vertex positions
    std::optional<CameraPose> suggestedView; // procedural scenes set one; glTF derives from bounds

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Thrown for input the loader cannot use. what() is one line: "<file>: <fault>".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Recomputes bounds from the vertices.
void computeBounds(Scene& scene);

// A camera pose that frames the bounds from a raised three-quarter view.
CameraPose framingView(const Bounds& bounds);

}  // namespace ml
