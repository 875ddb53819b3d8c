// The shadow rays' BVH, built on the CPU: Embree's SAH builder (rtcBuildBVH, libembree-dev)
// makes a binary tree over the scene's shadow casters (shadow_casters.h: every triangle that is
// not BLEND) into our own nodes, which are then laid out depth-first in the GPU's layout
// (shadow_bvh_layout.h) for glsl/include/shadow_rays.glsl. shadow_bvh_traversal.h walks the same
// arrays on the CPU.
//
//   - Binned SAH (RTC_BUILD_QUALITY_MEDIUM), no spatial splits: each triangle sits in exactly one
//     leaf. (Embree's HIGH quality differs only by spatial splits, which need a split callback
//     and reference a triangle from several leaves; without the callback it is this same build.)
//   - Leaves of 1..kShadowBvhMaxLeafSize triangles (the layout allows 8).
//   - Depth-first: a node's left subtree follows it, then its right subtree; the triangles are
//     reordered into leaf order, left to right.
//   - Depth: the most nodes on a path from the root to a leaf (the root alone: 1). The traversal
//     pushes both children of the node it pops, so its stack holds at most depth + 1 references:
//     the build refuses a tree deeper than ML_SHADOW_STACK - 1.
//   - A scene whose tree is one leaf (1..kShadowBvhMaxLeafSize triangles) still gets node 0: its
//     left child is the leaf, its right child the same leaf behind an empty box (min +inf, max
//     -inf). The slab test (shadow_bvh_traversal.h: min and max of the two planes' t) takes that
//     box as met, so the leaf is tested twice: the answer is the same, for a scene of 4 triangles.
//   - No caster (an empty scene, or one all BLEND): no node, no triangle; the GPU traces nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/raytracing/shadow_bvh_layout.h"
#include "scenes/scene.h"

namespace ml {

// The SAH's settings, to be tuned by measurement on the GPU (the issue asks for it).
inline constexpr std::uint32_t kShadowBvhMaxLeafSize = 4;
inline constexpr float kShadowBvhTraversalCost = 1.0f;    // of one node (two boxes), against...
inline constexpr float kShadowBvhIntersectionCost = 1.0f; // ...one triangle
inline constexpr std::uint32_t kShadowBvhMaxDepth = ML_SHADOW_STACK - 1;
static_assert(kShadowBvhMaxLeafSize >= 1 && kShadowBvhMaxLeafSize <= kShadowLeafCountLimit);

struct ShadowBvh {
    std::vector<GpuBvhNode> nodes;          // nodes[0] is the root; empty where nothing casts a shadow
    std::vector<GpuBvhTriangle> triangles;  // in leaf order
    Bounds bounds;                          // of the casting triangles (empty where there are none)
    std::size_t leaves = 0;
    std::size_t maskTriangles = 0;          // of `triangles`, the alpha-tested ones
    std::uint32_t depth = 0;                // nodes on the longest root-to-leaf path; 0 without nodes
    double buildSeconds = 0.0;              // Embree's build and the flattening (std::chrono, wall clock)

    std::size_t bytes() const { return nodes.size() * sizeof(GpuBvhNode) + triangles.size() * sizeof(GpuBvhTriangle); }
};

// Throws std::runtime_error, one line naming the scene, where Embree fails, where the scene has
// more than 2^28 casting triangles ("scene X: N triangles, more than the shadow structure's
// 2^28"), where a corner is not finite, or where the tree is deeper than kShadowBvhMaxDepth.
ShadowBvh buildShadowBvh(const Scene& scene);

}  // namespace ml
