// Points spread over a scene's triangles in proportion to their area: a triangle is chosen from
// a cumulative table of areas (double: a million small triangles still add up exactly enough),
// searched by bisection, and the point is uniform on it (square-root-warped barycentrics). Where
// generated lights go (renderer/lights/surface_placement.h) and what the default camera frames
// (renderer/camera/default_camera.h). One pass over the triangles to build, O(log T) a point.
#pragma once

#include <cstddef>
#include <vector>

#include "scenes/scene.h"

namespace ml {

class SurfaceSamples {
public:
    explicit SurfaceSamples(const Scene& scene);

    double totalArea() const { return total_; }

    // The point at `pick` of the total area (in [0, 1)), placed on its triangle by r1, r2 in [0, 1).
    struct Point {
        std::size_t triangle;
        float u, v, w;  // barycentrics of the triangle's first, second and third corner
    };
    Point at(float pick, float r1, float r2) const;

private:
    std::vector<double> cumulative_;
    double total_ = 0.0;
};

}  // namespace ml
