#include "renderer/lights/surface_placement.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "renderer/hash.h"
#include "renderer/lights/spatial_order.h"
#include "renderer/scene/surface_samples.h"

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
    const SurfaceSamples surface(scene);
    if (!(surface.totalArea() > 0.0)) return;

    // A stream of its own, apart from generateLights' (key + 0..7): the colours stay as they were.
    const std::uint32_t stream = pcgHash(seed ^ 0x51A7CE5u);
    for (std::size_t i = 0; i < lights.size(); ++i) {
        Light& light = lights[i];
        if (light.type == LightType::Directional) continue;
        const std::uint32_t key = pcgHash(static_cast<std::uint32_t>(i) ^ stream);
        const SurfaceSamples::Point p = surface.at(hashToUnitFloat(key), hashToUnitFloat(key + 1u), hashToUnitFloat(key + 2u));
        const Vertex& va = scene.vertices[p.corners[0]];
        const Vertex& vb = scene.vertices[p.corners[1]];
        const Vertex& vc = scene.vertices[p.corners[2]];
        const glm::vec3 point = p.position(scene);
        glm::vec3 normal = p.u * va.normal + p.v * vb.normal + p.w * vc.normal;
        if (!(glm::dot(normal, normal) > 1e-12f)) normal = glm::cross(vb.position - va.position, vc.position - va.position);
        normal = glm::dot(normal, normal) > 1e-24f ? glm::normalize(normal) : glm::vec3(0.0f, 1.0f, 0.0f);
        light.position = point + normal * (kSurfaceOffsetShare * light.radius);
    }
}

std::vector<Light> generateLights(const Scene& scene, const LightGeneration& generation, LightPlacement placement) {
    const Bounds volume = lightVolume(scene.bounds);
    std::vector<Light> lights = generateLights(volume, generation);
    if (placement == LightPlacement::Surfaces) placeOnSurfaces(lights, scene, generation.seed);
    sortLightsSpatially(lights, volume);
    return lights;
}

}  // namespace ml
