// CPU mirror of glsl/include/shading.glsl, for tests that check the GPU against the formula.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/light_set.h"

namespace ml {

float lightFalloff(float distance, float radius);

struct SurfaceSample {
    glm::vec3 position;
    glm::vec3 normal;  // unit length
    glm::vec3 albedo;  // linear
    float specularStrength = 0.25f;
    float shininess = 32.0f;
};

// The linear radiance the shaders compute for a surface point seen from `eye`; without
// `specular` the Blinn-Phong term is left out (--specular off).
glm::vec3 shadeReference(const SurfaceSample& s, const glm::vec3& eye, const std::vector<PointLight>& lights, float ambient,
                         bool specular = true);

}  // namespace ml
