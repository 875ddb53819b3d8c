// Which lights can light anything: a point or spot light whose sphere (its radius, where its
// falloff reaches zero) touches no triangle of the scene adds nothing to any pixel, yet is still
// culled, assigned and counted. `render --stats` reports the share that reaches a surface.
//
// Exact (sphere against each triangle's closest point), over a uniform grid of the triangles'
// bounding boxes, so a light looks only at the triangles near it.
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/lights/light_set.h"
#include "scenes/scene.h"

namespace ml {

struct SurfaceReach {
    std::size_t lights = 0;    // point and spot lights looked at
    std::size_t reaching = 0;  // of them, those whose sphere touches a triangle
    double share() const { return lights ? static_cast<double>(reaching) / static_cast<double>(lights) : 0.0; }
};

SurfaceReach measureSurfaceReach(const Scene& scene, const std::vector<Light>& lights);

}  // namespace ml
