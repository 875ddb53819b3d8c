// Points spread over a scene's triangles in proportion to their area: a triangle is chosen from
// a cumulative table of areas (double: a million small triangles still add up exactly enough),
// searched by bisection, and the point is uniform on it (square-root-warped barycentrics). Where
// generated lights go (renderer/lights/surface_placement.h) and what the default camera frames
// (renderer/camera/default_camera.h).
//
// The points depend on the scene's surface, not on how a file stores it: the table runs over the
// triangles sorted by their corner positions, each triangle read from its lowest corner (winding
// kept), so the same model with its triangles or vertices in another order (a re-export, Draco,
// gltfpack) gets the same points to the bit. One sort to build, O(log T) a point.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace ml {

class SurfaceSamples {
public:
    explicit SurfaceSamples(const Scene& scene);

    double totalArea() const { return total_; }

    // The point at `pick` of the total area (in [0, 1)), placed on its triangle by r1, r2 in [0, 1).
    struct Point {
        std::size_t triangle;                   // the triangle, as the scene numbers it
        std::array<std::uint32_t, 3> corners;   // its vertices, from the lowest (winding kept)
        float u, v, w;                          // barycentrics of corners[0], [1] and [2]

        // u a + v b + w c of the corners' positions (or of anything else per vertex).
        glm::vec3 position(const Scene& scene) const {
            return u * scene.vertices[corners[0]].position + v * scene.vertices[corners[1]].position +
                   w * scene.vertices[corners[2]].position;
        }
    };
    Point at(float pick, float r1, float r2) const;

private:
    struct Entry {
        std::uint32_t triangle;
        std::array<std::uint32_t, 3> corners;
    };
    std::vector<Entry> entries_;       // in the order of their corner positions
    std::vector<double> cumulative_;
    double total_ = 0.0;
};

}  // namespace ml
