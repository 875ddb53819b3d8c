#include "renderer/lights/surface_placement.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "renderer/hash.h"

namespace ml {

const char* lightPlacementName(LightPlacement placement) {
    return placement == LightPlacement::Surfaces ? "surfaces" : "volume";
}

LightPlacement parseLightPlacement(const std::string& text) {
    if (text == "volume") return LightPlacement::Volume;
    if (text == "surfaces") return LightPlacement::Surfaces;
    throw std::invalid_argument("--light-placement '" + text +
                                "': expected volume (uniform in the bounds) or surfaces (near the scene's surfaces)");
}

void placeOnSurfaces(std::vector<Light>& lights, const Scene& scene, std::uint32_t seed) {
    const std::size_t triangles = scene.triangleCount();
    // Running sum of areas (double: a million small triangles still add up exactly enough).
    std::vector<double> cumulative(triangles);
    double total = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3 a = scene.vertices[scene.indices[3 * t]].position;
        const glm::vec3 b = scene.vertices[scene.indices[3 * t + 1]].position;
        const glm::vec3 c = scene.vertices[scene.indices[3 * t + 2]].position;
        total += 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
        cumulative[t] = total;
    }
    if (!(total > 0.0)) return;

    // A stream of its own, apart from generateLights' (key + 0..7): the colours stay as they were.
    const std::uint32_t stream = pcgHash(seed ^ 0x51A7CE5u);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        Light& light = lights[i];
        if (light.type == LightType::Directional) continue;
        const std::uint32_t key = pcgHash(static_cast<std::uint32_t>(i) ^ stream);
        const double pick = static_cast<double>(hashToUnitFloat(key)) * total;
        const std::size_t t = std::min<std::size_t>(
            static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
            triangles - 1);
        const Vertex& va = scene.vertices[scene.indices[3 * t]];
        const Vertex& vb = scene.vertices[scene.indices[3 * t + 1]];
        const Vertex& vc = scene.vertices[scene.indices[3 * t + 2]];
        // Uniform on the triangle: u = 1 - sqrt(r1), v = sqrt(r1) (1 - r2), w = sqrt(r1) r2.
        const float r1 = std::sqrt(hashToUnitFloat(key + 1u)), r2 = hashToUnitFloat(key + 2u);
        const float u = 1.0f - r1, v = r1 * (1.0f - r2), w = r1 * r2;
        const glm::vec3 point = u * va.position + v * vb.position + w * vc.position;
        glm::vec3 normal = u * va.normal + v * vb.normal + w * vc.normal;
        if (!(glm::dot(normal, normal) > 1e-12f)) normal = glm::cross(vb.position - va.position, vc.position - va.position);
        normal = glm::dot(normal, normal) > 1e-24f ? glm::normalize(normal) : glm::vec3(0.0f, 1.0f, 0.0f);
        light.position = point + normal * (kSurfaceOffsetShare * light.radius);
    }
}

std::vector<Light> generateLights(const Scene& scene, const LightGeneration& generation, LightPlacement placement) {
    std::vector<Light> lights = generateLights(lightVolume(scene.bounds), generation);
    if (placement == LightPlacement::Surfaces) placeOnSurfaces(lights, scene, generation.seed);
    return lights;
}

}  // namespace ml
