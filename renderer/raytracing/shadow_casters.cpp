#include "renderer/raytracing/shadow_casters.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "renderer/raytracing/shadow_bvh_layout.h"

namespace ml {

namespace {

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

std::vector<ShadowCaster> shadowCasters(const Scene& scene) {
    std::size_t count = 0;
    for (const DrawRange& d : scene.draws)
        if (!scene.materials.at(d.material).drawnAsGlass()) count += d.indexCount / 3;
    std::vector<ShadowCaster> casters;
    casters.reserve(count);
    for (const DrawRange& d : scene.draws) {
        const Material& material = scene.materials.at(d.material);
        if (material.drawnAsGlass()) continue;  // glass casts no shadow: BLEND, or light passes through it
        const std::uint32_t word = material.alphaTested() ? d.material : kShadowOpaque;
        for (std::uint32_t i = d.firstIndex; i + 2 < d.firstIndex + d.indexCount; i += 3) {
            ShadowCaster c;
            for (int k = 0; k < 3; ++k) {
                c.corners[k] = scene.vertices.at(scene.indices.at(i + k)).position;
                if (!finite(c.corners[k]))
                    throw std::runtime_error("scene " + scene.name + ": triangle " + std::to_string(i / 3) +
                                             " has a corner that is not finite; shadow rays need finite positions");
            }
            c.material = word;
            c.sceneTriangle = i / 3;
            casters.push_back(c);
        }
    }
    return casters;
}

}  // namespace ml
