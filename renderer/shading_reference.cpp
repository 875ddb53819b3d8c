#include "renderer/shading_reference.h"

#include <algorithm>
#include <cmath>

namespace ml {

float lightFalloff(float d, float radius) {
    if (d >= radius) return 0.0f;
    const float x = d / radius;
    const float x2 = x * x;
    const float w = std::clamp(1.0f - x2 * x2, 0.0f, 1.0f);
    return (w * w) / (d * d + 1.0f);
}

glm::vec3 shadeReference(const SurfaceSample& s, const glm::vec3& eye, const std::vector<PointLight>& lights, float ambient,
                         bool specular) {
    glm::vec3 color = ambient * s.albedo;
    const glm::vec3 v = glm::normalize(eye - s.position);
    for (const PointLight& l : lights) {
        const glm::vec3 toLight = l.position - s.position;
        const float d = glm::length(toLight);
        const float falloff = lightFalloff(d, l.radius);
        if (falloff <= 0.0f) continue;
        const glm::vec3 dir = toLight / std::max(d, 1e-6f);
        const float nDotL = glm::dot(s.normal, dir);
        if (nDotL <= 0.0f) continue;
        if (!specular) {
            color += l.color * (falloff * nDotL) * s.albedo;
            continue;
        }
        const glm::vec3 h = glm::normalize(dir + v);
        const float spec = s.specularStrength * std::pow(std::max(glm::dot(s.normal, h), 0.0f), s.shininess);
        color += l.color * (falloff * nDotL) * (s.albedo + glm::vec3(spec));
    }
    return color;
}

}  // namespace ml
