// The scene model: only what shading needs (design.md, "Modelling no more than a scene needs").
//
// Geometry is flattened to world space at load time: one vertex array, one index array, and a
// list of draw ranges that each name a material. Optional vertex streams (tangents, a second UV
// set, vertex colours) exist only when a material or primitive asks for them, so a scene that
// uses none of them uploads and reads what it did before. A glTF file's animation, skins and
// morph targets come as Scene::animation (scenes/scene_animation.h), only where the file has them.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/material_variants.h"
#include "scenes/scene_animation.h"

namespace ml {

// Mirrors the vertex layout of glsl/scene.vert (locations 0, 1, 2).
struct Vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};
static_assert(sizeof(Vertex) == 32, "Vertex is uploaded as-is; keep it tightly packed");

// An 8-bit RGBA image. Colour images (base colour, emissive) are sRGB-encoded and sampled as
// linear through sRGB storage; data images (normal, metallic-roughness, occlusion) are linear.
// An image used both ways is held twice, once per colour space.
struct Image {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // width * height * 4 bytes, rows top to bottom
    bool srgb = true;
};

// glTF sampler: filters and wrap modes, with the GL enum values glTF itself uses.
struct Sampler {
    int magFilter = 0x2601;  // GL_LINEAR
    int minFilter = 0x2703;  // GL_LINEAR_MIPMAP_LINEAR
    int wrapS = 0x2901;      // GL_REPEAT
    int wrapT = 0x2901;
    bool operator==(const Sampler&) const = default;
};

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv.
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise in UV space as glTF defines it
    glm::vec2 scale{1.0f};
    bool isIdentity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
};

// One texture a material reads: which image, sampled how, through which UV set.
struct TextureRef {
    int image = -1;    // index into Scene::images, or -1: the material has no such texture
    int sampler = -1;  // index into Scene::samplers, or -1: glTF's default (linear, mipmapped, repeat)
    int texCoord = 0;  // 0: TEXCOORD_0 (Vertex::uv), 1: TEXCOORD_1 (Scene::uv1)
    TextureTransform transform;
    bool present() const { return image >= 0; }
};

// glTF's alphaMode: OPAQUE, MASK (cut out at alphaCutoff) or BLEND (drawn after the opaque
// frame, blended back to front; renderer/passes/transparent_pass.h).
enum class AlphaMode { Opaque, Mask, Blend };

// A glTF metallic-roughness material (docs/lights-and-shading.md says how it is shaded).
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    TextureRef baseColorTexture;      // sRGB; alpha is coverage
    // Defaults are a plain dielectric for procedural scenes; the glTF loader always sets both
    // from the file (whose own defaults are 1 and 1).
    float metallic = 0.0f;
    float roughness = 0.5f;
    TextureRef metallicRoughnessTexture;  // linear; B is metallic, G is roughness
    TextureRef normalTexture;             // linear, tangent space
    float normalScale = 1.0f;
    TextureRef occlusionTexture;          // linear; R is ambient occlusion
    float occlusionStrength = 1.0f;
    glm::vec3 emissive{0.0f};             // linear emissiveFactor times KHR_materials_emissive_strength
    TextureRef emissiveTexture;           // sRGB
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;             // MASK: drawn where alpha >= cutoff (BLEND ignores it, as glTF asks)
    // glTF's doubleSided: false (the default) lets raster passes cull back faces, true draws
    // both sides, lit with the normal as given (glTF asks for it reversed on the back face; not
    // modelled yet, alike in every method).
    bool doubleSided = false;
    // KHR_materials_unlit: shown as its base colour (factor x texture x COLOR_0), lit by nothing.
    bool unlit = false;
    // KHR_materials_ior and KHR_materials_specular (docs/lights-and-shading.md): the dielectric's
    // F0 is min(((ior - 1) / (ior + 1))^2 x specular colour, 1), its Fresnel weighted by the
    // specular factor. The defaults are glTF's plain dielectric (F0 0.04, weight 1).
    float ior = 1.5f;                          // 0 (F0 = 1) or at least 1
    float specularFactor = 1.0f;               // [0, 1]
    TextureRef specularTexture;                // linear; A is the factor
    glm::vec3 specularColorFactor{1.0f};       // linear, >= 0 (may exceed 1)
    TextureRef specularColorTexture;           // sRGB; RGB is the colour
    // KHR_materials_clearcoat: a GGX lobe of its own roughness and normal over the material,
    // weighted by clearcoat x its Fresnel (docs/lights-and-shading.md). Factor 0 (glTF's default)
    // is no coat.
    float clearcoatFactor = 0.0f;              // [0, 1]
    TextureRef clearcoatTexture;               // linear; R multiplies the factor
    float clearcoatRoughnessFactor = 0.0f;     // [0, 1]
    TextureRef clearcoatRoughnessTexture;      // linear; G multiplies the roughness
    TextureRef clearcoatNormalTexture;         // linear, tangent space; none: the surface's own normal
    float clearcoatNormalScale = 1.0f;
    // KHR_materials_sheen: a Charlie micro-fibre lobe under any coat, over the material, which it
    // dims by its albedo (docs/lights-and-shading.md). A colour of 0 (glTF's default) is no sheen.
    glm::vec3 sheenColorFactor{0.0f};          // linear, [0, 1]
    TextureRef sheenColorTexture;              // sRGB; RGB multiplies the colour
    float sheenRoughnessFactor = 0.0f;         // [0, 1]
    TextureRef sheenRoughnessTexture;          // linear; A multiplies the roughness
    // KHR_materials_anisotropy: the GGX lobe stretched along a direction in the tangent frame, its
    // alpha there mix(alpha, 1, strength^2) (docs/lights-and-shading.md). It needs the tangent
    // stream, which the loader makes where the file has none. A strength of 0 (glTF's default) is none.
    float anisotropyStrength = 0.0f;           // [0, 1]
    float anisotropyRotation = 0.0f;           // radians, counter-clockwise from the tangent
    TextureRef anisotropyTexture;              // linear; RG the direction in [-1, 1], B multiplies the strength
    // KHR_materials_iridescence: a thin film whose Fresnel (Belcour and Barla 2017) is mixed into
    // F by its strength (docs/lights-and-shading.md). A factor of 0 (glTF's default) is no film.
    float iridescenceFactor = 0.0f;            // [0, 1]
    TextureRef iridescenceTexture;             // linear; R multiplies the factor
    float iridescenceIor = 1.3f;               // >= 1
    float iridescenceThicknessMinimum = 100.0f;  // nm, >= 0, <= the maximum
    float iridescenceThicknessMaximum = 400.0f;  // nm, >= 0; the thickness where there is no map
    TextureRef iridescenceThicknessTexture;    // linear; G mixes minimum to maximum (the same image
                                               // as iridescenceTexture where both are set: bindings.h)
    // KHR_materials_transmission: light through the surface (the opaque scene behind it and the
    // lights on its far side), in place of the dielectric's diffuse by the factor; and
    // KHR_materials_volume: the medium under it, of a thickness (0: thin-walled) that refracts
    // the scene behind by the IOR and tints what passes by Beer's law (docs/lights-and-shading.md).
    // A transmissive material is drawn as glass (renderer/passes/transparent_pass.h). A factor of
    // 0 (glTF's default) is opaque.
    float transmissionFactor = 0.0f;           // [0, 1]
    TextureRef transmissionTexture;            // linear; R multiplies the factor
    float thicknessFactor = 0.0f;              // >= 0, in the mesh's units
    TextureRef thicknessTexture;               // linear; G multiplies the thickness
    glm::vec3 attenuationColor{1.0f};          // linear, [0, 1]
    float attenuationDistance = 0.0f;          // > 0; 0: infinite (glTF's default), no tint

    bool alphaTested() const { return alphaMode == AlphaMode::Mask; }
    // Does the material ask for anything but glTF's default dielectric Fresnel?
    bool specularModelled() const {
        return !unlit && (ior != 1.5f || specularFactor != 1.0f || specularColorFactor != glm::vec3(1.0f) ||
                          specularTexture.present() || specularColorTexture.present());
    }
    // Is there a coat? (glTF: a clearcoatFactor of 0 disables the layer, whatever its textures.)
    bool clearcoatModelled() const { return !unlit && clearcoatFactor > 0.0f; }
    // Is there a sheen? (glTF: a sheenColorFactor of 0 disables the layer, whatever its textures.)
    bool sheenModelled() const { return !unlit && sheenColorFactor != glm::vec3(0.0f); }
    // Is the lobe anisotropic? (A strength of 0 is the isotropic lobe, whatever the texture.)
    bool anisotropyModelled() const { return !unlit && anisotropyStrength > 0.0f; }
    // Is there a film? (glTF: an iridescenceFactor of 0 has no effect, whatever its textures.)
    bool iridescenceModelled() const { return !unlit && iridescenceFactor > 0.0f; }
    // Does light pass through it? (glTF: a transmissionFactor of 0 is opaque, whatever its texture.)
    bool transmissionModelled() const { return !unlit && transmissionFactor > 0.0f; }
    bool blended() const { return alphaMode == AlphaMode::Blend; }
    // Drawn by the transparent pass, after the opaque frame: BLEND, or light passes through it.
    bool drawnAsGlass() const { return blended() || transmissionModelled(); }
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

// A perspective camera a glTF file defines, placed by its node's world transform.
struct SceneCamera {
    std::string name;
    CameraPose pose;
    glm::vec3 up{0.0f, 1.0f, 0.0f};  // the node's +y: a rolled camera stays rolled
    float nearPlane = 0.0f;          // glTF znear
    float farPlane = 0.0f;           // glTF zfar, 0 where the file gives none (infinite)
};

// A light a glTF file places (KHR_lights_punctual) by its node's world transform, in the file's
// own terms; the renderer turns it into its light model (renderer/lights/light_set.h, lightsFromScene).
struct SceneLight {
    enum class Type { Point, Spot, Directional };
    std::string name;
    Type type = Type::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // the node's -z, unit (spot, directional)
    glm::vec3 color{1.0f};                    // linear
    float intensity = 1.0f;                   // candela (point, spot) or lux (directional)
    float range = 0.0f;                       // 0: none given (infinite in glTF)
    float innerConeAngle = 0.0f;              // radians (spot)
    float outerConeAngle = 0.7853981634f;     // radians (spot)
};

struct Scene {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<DrawRange> draws;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Sampler> samplers;
    // Optional vertex streams: each is empty, or holds one element per vertex.
    std::vector<glm::vec4> tangents;  // xyz world-space unit tangent, w the bitangent's sign (+-1)
    std::vector<glm::vec2> uv1;       // TEXCOORD_1
    std::vector<glm::vec4> colors;    // COLOR_0, linear RGBA (1 where a primitive has none)
    std::vector<SceneCamera> cameras;        // a glTF file's cameras, in the order its default scene's nodes are walked
    std::vector<SceneLight> lights;          // a glTF file's lights (KHR_lights_punctual), in the same order
    Bounds bounds;                           // of the vertex positions the triangles use
    std::optional<CameraPose> suggestedView; // procedural scenes set one; a file's default view: renderer/camera/default_camera.h
    std::vector<std::string> extensionsUsed; // a glTF file's extensionsUsed, as it lists them (`manylights info`)
    MaterialVariants materialVariants;       // KHR_materials_variants; empty for most scenes
    // A glTF file's clips, skins and morph targets, and the rest data of the vertices they move
    // (those vertices are held posed at rest above); null for a static scene.
    std::shared_ptr<const SceneAnimation> animation;

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// Thrown for input the loader cannot use. what() is one line: "<file>: <fault>".
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Recomputes bounds from the vertices the indices use.
void computeBounds(Scene& scene);

// A camera pose that frames the bounds from a raised three-quarter view.
CameraPose framingView(const Bounds& bounds);

}  // namespace ml
