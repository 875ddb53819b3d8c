#include "renderer/clustering/cluster_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "renderer/clustering/cluster_culling.h"

namespace ml {

Slicing parseSlicing(const std::string& text) {
    if (text == "linear") return Slicing::Linear;
    if (text == "log") return Slicing::Log;
    if (text == "fitted") return Slicing::Fitted;
    throw std::invalid_argument("--slicing '" + text + "': expected linear, log or fitted");
}

const char* slicingName(Slicing slicing) {
    switch (slicing) {
    case Slicing::Linear: return "linear";
    case Slicing::Log: return "log";
    case Slicing::Fitted: return "fitted";
    }
    return "?";
}

void validateGridConfig(const ClusterGridConfig& c) {
    if (c.tilesX == 0 || c.tilesX > 1024)
        throw std::invalid_argument("--tiles-x " + std::to_string(c.tilesX) + ": must be between 1 and 1024");
    if (c.slices == 0 || c.slices > 1024)
        throw std::invalid_argument("--slices " + std::to_string(c.slices) + ": must be between 1 and 1024");
    if (c.workgroup == 0 || c.workgroup > 1024 || (c.workgroup & (c.workgroup - 1)) != 0)
        throw std::invalid_argument("--workgroup " + std::to_string(c.workgroup) +
                                    ": must be a power of two between 1 and 1024");
}

ClusterGrid ClusterGrid::forViewport(const ClusterGridConfig& config, int width, int height) {
    // Square tiles, config.tilesX of them across the longer side (the width of a landscape frame).
    // Sized from the width alone, a portrait frame got 1-pixel tiles: 16 x 4096 clusters per slice
    // at 16x4096, a 144 MiB grid and a 15 s list sort on llvmpipe.
    ClusterGrid g;
    const int longSide = std::max({width, height, 1});
    const std::uint32_t across = std::max<std::uint32_t>(1, std::min<std::uint32_t>(config.tilesX, static_cast<std::uint32_t>(longSide)));
    g.tileSizePx = static_cast<float>(longSide) / static_cast<float>(across);
    const auto tilesFor = [&](int side) {
        return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::ceil(static_cast<float>(side) / g.tileSizePx - 1e-4f)));
    };
    g.tilesX = tilesFor(width);
    g.tilesY = tilesFor(height);
    g.slices = config.slices;
    return g;
}

DepthSlicing DepthSlicing::make(bool logarithmic, float zNear, float zFar, std::uint32_t slices) {
    DepthSlicing s;
    s.logarithmic = logarithmic;
    s.zNear = zNear;
    s.zFar = std::max(zFar, zNear * (1.0f + 1e-4f) + 1e-6f);
    const float n = static_cast<float>(slices);
    if (logarithmic) {
        s.scale = n / std::log(s.zFar / s.zNear);
        s.bias = -std::log(s.zNear) * s.scale;
    } else {
        s.scale = n / (s.zFar - s.zNear);
        s.bias = -s.zNear * s.scale;
    }
    return s;
}

std::uint32_t DepthSlicing::sliceFor(float z, std::uint32_t slices) const {
    const float f = logarithmic ? std::log(std::max(z, 1e-7f)) : z;
    const float s = std::floor(f * scale + bias);
    return static_cast<std::uint32_t>(std::clamp(s, 0.0f, static_cast<float>(slices - 1)));
}

float DepthSlicing::boundary(std::uint32_t k, std::uint32_t slices) const {
    const float t = static_cast<float>(k) / static_cast<float>(slices);
    return logarithmic ? zNear * std::pow(zFar / zNear, t) : zNear + (zFar - zNear) * t;
}

Aabb clusterBounds(const ClusterGrid& grid, const DepthSlicing& slicing, float cameraNear, float cameraFar,
                   const glm::mat4& projection, int width, int height, std::uint32_t x, std::uint32_t y,
                   std::uint32_t slice) {
    return boundsOf(clusterFrustum(grid, slicing, cameraNear, cameraFar, projection, width, height, x, y, slice));
}

float distanceSquared(const Aabb& box, const glm::vec3& p) {
    const glm::vec3 d = glm::max(glm::max(box.min - p, p - box.max), glm::vec3(0.0f));
    return glm::dot(d, d);
}

}  // namespace ml
