// What a scene's drawn materials use, as ML_FEATURE_* bits (glsl/include/bindings.h). Every
// shader that reads a material or a G-buffer is compiled with these as ML_MATERIAL_FEATURES, so
// a path (normal maps, emissive, alpha testing...) costs only the scenes that use it.
#pragma once

#include <cstdint>
#include <string>

#include "renderer/gl/shader_sources.h"
#include "scenes/scene.h"

namespace ml {

std::uint32_t materialFeatures(const Scene& scene);

// {"ML_MATERIAL_FEATURES", bits}.
shaders::Defines materialFeatureDefines(std::uint32_t features);

// "normal maps, emissive, alpha test", or "none": for --verbose and the panel.
std::string describeMaterialFeatures(std::uint32_t features);

// KHR_materials_ior's reflectance at normal incidence, ((ior - 1) / (ior + 1))^2 (outside the
// material: air), worked in double so that glTF's default 1.5 gives 0.04f to the bit, as the
// shaders' constant for materials without the extension. ior 0 gives 1.
float dielectricF0(float ior);

// The 2x3 affine UV transform of KHR_texture_transform (T * R * S): columns of the linear part,
// then the offset.
struct UvAffine {
    glm::vec2 column0{1.0f, 0.0f};
    glm::vec2 column1{0.0f, 1.0f};
    glm::vec2 offset{0.0f};
};
UvAffine uvAffine(const TextureTransform& transform);

}  // namespace ml
