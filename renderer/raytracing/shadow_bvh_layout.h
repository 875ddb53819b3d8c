// The shadow rays' BVH as the GPU reads it (glsl/include/shadow_rays.glsl, std430): a tree whose
// nodes hold their children's boxes, 2, 4 or 8 children a node (--shadow-bvh-width), and the
// triangles its leaves point at. Built on the CPU by renderer/raytracing/shadow_bvh.h; its
// constants (ML_SHADOW_*) live in glsl/include/bindings.h, the one source of truth for both
// languages.
//
//   The GPU buffer holds a 16-byte header first (the ray count of ML_COUNT_SHADOW_RAYS,
//   shadow_rays.h); the indices below count from the end of it.
//
//   Nodes are shadowNodeVec4s(width) vec4s each, nodes[0] the root. A node holds its children's
//   boxes, so a traversal tests the boxes of the node it pops and pushes the references of those
//   that the ray meets.
//
//   Width 2 (binary):
//     GpuBvhNode (64 B)    .x    .y    .z    .w
//       leftMin          left child's box min   left child reference   (uint bits)
//       leftMax          left child's box max   right child reference  (uint bits)
//       rightMin         right child's box min  0
//       rightMax         right child's box max  0
//
//   Width 4 or 8 (wide): width / 4 groups of four children, each a GpuBvhWideGroup (112 B), one
//   coordinate of all four boxes a vec4, so one vec4 operation tests four slabs:
//       loX hiX loY hiY loZ hiZ   the four boxes' min and max x, y, z (child k in component k)
//       references                the four child references (uint bits); 0 where the slot is empty
//   Children fill the slots in order; an empty slot (reference 0: the root is no child) has an
//   empty box (min +inf, max -inf) and is never pushed.
//
//   A child reference is a uint:
//     bit 31 clear: an inner node, its index in `nodes` (< 2^31; never 0, the root is no child)
//     bit 31 set:   a leaf, ML_SHADOW_LEAF_BIT | (count - 1) << 28 | first triangle
//                   count in 1..8, first triangle < 2^28; its triangles are consecutive
//
//     GpuBvhTriangle (48 B)   .xyz                  .w (uint bits)
//       v0                    corner 0 (world)      ML_SHADOW_OPAQUE, or the MASK material's index
//       v1                    corner 1              the triangle's index in the scene (its UVs)
//       v2                    corner 2              a MASK triangle's UV record (shadow_alpha.h), else 0
//
//   The corners are the scene triangle's, in its own order, so the barycentrics (u, v) of a hit
//   (the point (1 - u - v) v0 + u v1 + v v2) weigh the scene triangle's corners 1 and 2.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"

namespace ml {

struct alignas(16) GpuBvhNode {
    glm::vec4 leftMin;   // xyz: the left child's box min; w: the left child's reference (uint bits)
    glm::vec4 leftMax;   // xyz: the left child's box max; w: the right child's reference (uint bits)
    glm::vec4 rightMin;  // xyz: the right child's box min; w: 0
    glm::vec4 rightMax;  // xyz: the right child's box max; w: 0
};
static_assert(sizeof(GpuBvhNode) == 64);
static_assert(alignof(GpuBvhNode) == 16);

struct alignas(16) GpuBvhWideGroup {
    glm::vec4 loX, hiX, loY, hiY, loZ, hiZ;  // component k: child k's box
    glm::vec4 references;                    // component k: child k's reference (uint bits), 0 for none
};
static_assert(sizeof(GpuBvhWideGroup) == 16 * ML_SHADOW_WIDE_GROUP_VEC4S);

struct alignas(16) GpuBvhTriangle {
    glm::vec4 v0;  // xyz: corner 0; w: uint bits, ML_SHADOW_OPAQUE or the MASK material's index
    glm::vec4 v1;  // xyz: corner 1; w: uint bits, the triangle's index in the scene
    glm::vec4 v2;  // xyz: corner 2; w: uint bits, a MASK triangle's UV record (shadow_alpha.h), else 0
};
static_assert(sizeof(GpuBvhTriangle) == 48);
static_assert(alignof(GpuBvhTriangle) == 16);

// The layout's limits: a leaf holds at most 8 triangles (3 bits of count), its first triangle
// fits in 28 bits.
inline constexpr std::uint32_t kShadowLeafBit = ML_SHADOW_LEAF_BIT;
inline constexpr std::uint32_t kShadowOpaque = ML_SHADOW_OPAQUE;
inline constexpr std::uint32_t kShadowLeafCountLimit = 8;
inline constexpr std::uint32_t kShadowTriangleLimit = 1u << 28;
static_assert(kShadowLeafBit == 0x80000000u && kShadowOpaque == 0xFFFFFFFFu);

// --shadow-bvh-width's default: 4-wide, the fastest of the three on the H100 at every camera of
// the atrium and Sponza (2-11 % faster than binary, 8-wide 20-30 % slower; docs/lights-and-shading.md).
inline constexpr std::uint32_t kDefaultShadowBvhWidth = 4;
// The widths the layout has (--shadow-bvh-width), and a node's size in vec4s at each.
constexpr bool shadowBvhWidthSupported(std::uint32_t width) { return width == 2 || width == 4 || width == 8; }
constexpr std::uint32_t shadowNodeVec4s(std::uint32_t width) {
    return width == 2 ? sizeof(GpuBvhNode) / 16 : width / 4 * ML_SHADOW_WIDE_GROUP_VEC4S;
}

// One child slot of a node, as the layout stores it (`node`: the node's first vec4).
struct ShadowBvhChild {
    glm::vec3 lo, hi;
    std::uint32_t reference = 0;
    bool present = false;  // wide nodes' empty slots are not (the binary node's are always)
};
ShadowBvhChild shadowNodeChild(const glm::vec4* node, std::uint32_t width, std::uint32_t slot);
// And the other way: writes child `slot` of the node at `node`.
void setShadowNodeChild(glm::vec4* node, std::uint32_t width, std::uint32_t slot, const ShadowBvhChild& child);

constexpr std::uint32_t shadowLeafReference(std::uint32_t firstTriangle, std::uint32_t count) {
    return kShadowLeafBit | ((count - 1u) << 28) | firstTriangle;
}
constexpr bool shadowReferenceIsLeaf(std::uint32_t reference) { return (reference & kShadowLeafBit) != 0u; }
constexpr std::uint32_t shadowLeafFirst(std::uint32_t reference) { return reference & 0x0FFFFFFFu; }
constexpr std::uint32_t shadowLeafCount(std::uint32_t reference) { return ((reference >> 28) & 7u) + 1u; }

}  // namespace ml
