// The order of each draw range's triangles in the index buffer (--triangle-order), chosen at
// upload with meshoptimizer. Only the order within a range changes, so materials, draw ranges
// and submission stay as they are, and every method draws the same order (coplanar ties
// resolve alike, so the methods still agree with naive).
//
//   as-loaded     the scene's own order
//   vertex-cache  meshopt_optimizeVertexCache: neighbours together, so the GPU's post-transform
//                 cache reuses more vertices (atrium: 1.04 -> 0.70 vertex shader runs per triangle
//                 on its largest range)
//   overdraw      vertex-cache, then meshopt_optimizeOverdraw (threshold 1.05): clusters that
//                 face outward from the range's centre first, which occlude more from most views
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace ml {

enum class TriangleOrder { AsLoaded, VertexCache, Overdraw };
TriangleOrder parseTriangleOrder(const std::string& text);  // throws std::invalid_argument
const char* triangleOrderName(TriangleOrder order);

// The scene's indices with every draw range's triangles reordered; ranges keep their place.
std::vector<std::uint32_t> orderTriangles(const Scene& scene, TriangleOrder order);

}  // namespace ml
