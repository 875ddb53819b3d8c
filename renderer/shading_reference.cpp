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

ShadingTerms shadingTerms(const glm::vec3& baseColor, float metallic, float roughness) {
    ShadingTerms t;
    const float m = std::clamp(metallic, 0.0f, 1.0f);
    const float alpha = std::clamp(roughness, 0.0f, 1.0f) * std::clamp(roughness, 0.0f, 1.0f);
    t.shininess = std::clamp(2.0f / std::max(alpha * alpha, 1e-6f) - 2.0f, 1.0f, 8192.0f);
    t.diffuse = baseColor * (1.0f - m);
    t.f0 = glm::mix(glm::vec3(0.04f), baseColor, m);
    t.specular = t.f0 * ((t.shininess + 8.0f) / 8.0f);
    return t;
}

glm::vec3 shadeReference(const SurfaceSample& s, const glm::vec3& eye, const std::vector<PointLight>& lights, float ambient,
                         bool specular) {
    const ShadingTerms t = shadingTerms(s.baseColor, s.metallic, s.roughness);
    glm::vec3 color = ambient * s.occlusion * (t.diffuse + t.f0) + s.emissive;
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
            color += l.color * (falloff * nDotL) * t.diffuse;
            continue;
        }
        const glm::vec3 h = glm::normalize(dir + v);
        const float spec = std::pow(std::max(glm::dot(s.normal, h), 0.0f), t.shininess);
        color += l.color * (falloff * nDotL) * (t.diffuse + t.specular * spec);
    }
    return color;
}

}  // namespace ml
