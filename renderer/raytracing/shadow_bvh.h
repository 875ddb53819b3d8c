// The shadow rays' BVH, built on the CPU: Embree's SAH builder (rtcBuildBVH, libembree-dev)
// makes a tree of 2, 4 or 8 children a node (--shadow-bvh-width; Embree's maxBranchingFactor)
// over the scene's shadow casters (shadow_casters.h: every triangle that is not BLEND) into our
// own nodes, which are then laid out depth-first in the GPU's layout (shadow_bvh_layout.h) for
// glsl/include/shadow_rays.glsl. shadow_bvh_traversal.h walks the same arrays on the CPU.
//
//   - Binned SAH (RTC_BUILD_QUALITY_MEDIUM), no spatial splits: each triangle sits in exactly one
//     leaf. (Embree's HIGH quality differs only by spatial splits, which need a split callback
//     and reference a triangle from several leaves; without the callback it is this same build.)
//   - Leaves of 1..kShadowBvhMaxLeafSize triangles (the layout allows 8).
//   - Depth-first: a node's first child's subtree follows it, then its second's, and so on; the
//     triangles are reordered into leaf order, first child to last.
//   - Depth: the most nodes on a path from the root to a leaf (the root alone: 1).
//   - The stack: the traversal pushes the children of the node it pops in slot order, so the
//     most references it can hold at once is, at worst (every box met), need(root), where a
//     leaf needs 0 and a node of k children max(k, max over j of j + need(child j)). The build
//     refuses a tree that needs more than ML_SHADOW_STACK.
//   - A scene whose tree is one leaf (1..kShadowBvhMaxLeafSize triangles) still gets node 0 with
//     the leaf in its first slot. In the binary layout, which has no empty slot, its second child
//     is the same leaf behind an empty box (min +inf, max -inf): the slab test
//     (shadow_bvh_traversal.h: min and max of the two planes' t) takes that box as met, so the
//     leaf is tested twice, and the answer is the same, for a scene of 4 triangles.
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
inline constexpr std::uint32_t kShadowBvhMaxDepth = ML_SHADOW_STACK - 1;  // Embree's maxDepth
static_assert(kShadowBvhMaxLeafSize >= 1 && kShadowBvhMaxLeafSize <= kShadowLeafCountLimit);

struct ShadowBvh {
    std::uint32_t width = kDefaultShadowBvhWidth;  // children per node
    std::vector<glm::vec4> nodes;           // shadowNodeVec4s(width) each, the root first; empty where nothing casts a shadow
    std::vector<GpuBvhTriangle> triangles;  // in leaf order
    Bounds bounds;                          // of the casting triangles (empty where there are none)
    std::size_t leaves = 0;
    std::size_t maskTriangles = 0;          // of `triangles`, the alpha-tested ones
    std::uint32_t depth = 0;                // nodes on the longest root-to-leaf path; 0 without nodes
    std::uint32_t stackNeed = 0;            // the most references the traversal's stack can hold (see above)
    double buildSeconds = 0.0;              // Embree's build and the flattening (std::chrono, wall clock)

    std::size_t nodeCount() const { return nodes.size() / shadowNodeVec4s(width); }
    const glm::vec4* node(std::uint32_t index) const { return nodes.data() + std::size_t{index} * shadowNodeVec4s(width); }
    std::size_t bytes() const { return nodes.size() * sizeof(glm::vec4) + triangles.size() * sizeof(GpuBvhTriangle); }
};

// Throws std::invalid_argument for a width other than 2, 4 or 8 ("--shadow-bvh-width 3: ..."),
// and std::runtime_error, one line naming the scene, where Embree fails, where the scene has
// more than 2^28 casting triangles ("scene X: N triangles, more than the shadow structure's
// 2^28"), where a corner is not finite, or where the tree's traversal could need more than
// ML_SHADOW_STACK stack entries.
ShadowBvh buildShadowBvh(const Scene& scene, std::uint32_t width = kDefaultShadowBvhWidth);

}  // namespace ml
