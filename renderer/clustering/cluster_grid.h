// The cluster grid: screen tiles times depth slices over the view frustum.
//
//   tiles: square, --tiles-x across the longer side (the width of a landscape frame), the other
//          count derived, whatever the resolution (seed 000: a grid sized in pixels changed
//          with the screen);
//   slices: --slices along view depth z (positive distance in front of the camera), spaced
//          linearly or logarithmically over [zNear, zFar]. "fitted" is log spacing over the
//          depth range actually visible this frame (a depth reduction on the GPU), not the far
//          plane: a far plane of 1000 in a 30-unit scene left 11 of 12 linear slices empty.
//
//   cluster index = x + tilesX * (y + tilesY * slice), tiles counted from the bottom-left
//   pixel as gl_FragCoord does.
//
// This file is the CPU mirror of glsl/include/cluster_grid.glsl; the tests check one against
// the other and the assignment against a CPU reference built from these functions.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace ml {

enum class Slicing { Linear, Log, Fitted };
Slicing parseSlicing(const std::string& text);  // throws std::invalid_argument
const char* slicingName(Slicing slicing);

struct ClusterGridConfig {
    // The defaults: 32 x 18 x 48 at 16:9, of six grids on an H200 the fastest at 65,536 lights
    // (with 32 x 64) and among the fastest at 1,048,576 once the list sort got cheaper
    // (docs/bench/nvidia-h200/grid-sweep-2/README.md).
    std::uint32_t tilesX = 32;
    std::uint32_t slices = 48;
    Slicing slicing = Slicing::Fitted;
    std::uint32_t workgroup = 64;  // light-assignment compute workgroup size
};

// Throws std::invalid_argument naming the flag (--tiles-x, --slices, --workgroup) when a value
// is zero or absurd; device limits are checked again when the GPU is known.
void validateGridConfig(const ClusterGridConfig& config);

struct ClusterGrid {
    std::uint32_t tilesX = 1, tilesY = 1, slices = 1;
    float tileSizePx = 1.0f;

    static ClusterGrid forViewport(const ClusterGridConfig& config, int width, int height);
    std::uint32_t clusterCount() const { return tilesX * tilesY * slices; }
    std::uint32_t index(std::uint32_t x, std::uint32_t y, std::uint32_t slice) const {
        return x + tilesX * (y + tilesY * slice);
    }
};

// How depth maps to slices: slice = floor(f(z) * scale + bias), f = identity (linear) or log.
struct DepthSlicing {
    bool logarithmic = true;
    float zNear = 0.1f, zFar = 100.0f;  // the range sliced
    float scale = 1.0f, bias = 0.0f;

    static DepthSlicing make(bool logarithmic, float zNear, float zFar, std::uint32_t slices);
    std::uint32_t sliceFor(float z, std::uint32_t slices) const;
    // Depth of the boundary below slice k (k = slices gives zFar).
    float boundary(std::uint32_t k, std::uint32_t slices) const;
};

// View-space bounds of a cluster, in the same way glsl/cluster_bounds.comp computes them.
// cameraNear/cameraFar widen the first and last slice so fragments clamped into them are covered.
struct Aabb {
    glm::vec3 min, max;
};
Aabb clusterBounds(const ClusterGrid& grid, const DepthSlicing& slicing, float cameraNear, float cameraFar,
                   const glm::mat4& projection, int width, int height, std::uint32_t x, std::uint32_t y,
                   std::uint32_t slice);

// Squared distance from a point to a box (0 inside).
float distanceSquared(const Aabb& box, const glm::vec3& p);

}  // namespace ml
