#version 450 core
// The shadow BVH follows an animated pose (renderer/raytracing/shadow_bvh_refit.h): the tree
// built on the loaded pose keeps its shape, and each frame, after the vertex animation, its
// triangles take the posed corners (u_pass 0, one invocation a triangle) and its boxes are
// recomputed from them, one level of nodes a dispatch from the deepest up (u_pass 1, one
// invocation a node): a leaf's box bounds its triangles' corners, an inner child's box its own
// children's boxes, written at the last dispatch. The layout is shadow_bvh_layout.h's at
// ML_SHADOW_BVH_WIDTH children a node.
#include "include/bindings.h"
#ifndef ML_SHADOW_BVH_WIDTH
#define ML_SHADOW_BVH_WIDTH 4  // kDefaultShadowBvhWidth; the renderer always defines it
#endif

layout(local_size_x = ML_SHADOW_REFIT_WORKGROUP) in;

layout(std430, binding = ML_SSBO_SHADOW_BVH) buffer ShadowBvhBuffer {
    uvec4 shadowBvhHeader;  // the ray count (shadow_rays.glsl), untouched
    vec4 shadowBvh[];
};
layout(std430, binding = ML_SSBO_VERTICES) readonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
layout(std430, binding = ML_SSBO_SHADOW_REFIT_CORNERS) readonly buffer Corners { uvec4 triangleCorners[]; };
layout(std430, binding = ML_SSBO_SHADOW_REFIT_ORDER) readonly buffer Order { uint nodeOrder[]; };

uniform uint u_pass;           // 0: triangles; 1: a level of nodes
uniform uint u_first;          // pass 1: the level's first entry in nodeOrder
uniform uint u_count;          // triangles, or the level's nodes
uniform uint u_firstTriangle;  // triangle 0's first vec4 in shadowBvh
uniform uint u_nodes;          // nodes in the tree (1: the one-leaf tree, shadow_bvh.h)

#if ML_SHADOW_BVH_WIDTH == 2
uint childReference(uint node, uint slot) { return floatBitsToUint(shadowBvh[4u * node + slot].w); }
// The binary node's slots are always filled, but for the one-leaf tree's second, an empty box.
bool childPresent(uint node, uint slot) { return slot == 0u || u_nodes > 1u; }
vec3 childMin(uint node, uint slot) { return shadowBvh[4u * node + 2u * slot].xyz; }
vec3 childMax(uint node, uint slot) { return shadowBvh[4u * node + 2u * slot + 1u].xyz; }
void setChildBox(uint node, uint slot, vec3 lo, vec3 hi) {
    shadowBvh[4u * node + 2u * slot].xyz = lo;
    shadowBvh[4u * node + 2u * slot + 1u].xyz = hi;
}
#else
uint groupAt(uint node, uint slot) {
    return uint(ML_SHADOW_BVH_WIDTH / 4 * ML_SHADOW_WIDE_GROUP_VEC4S) * node + slot / 4u * uint(ML_SHADOW_WIDE_GROUP_VEC4S);
}
uint childReference(uint node, uint slot) { return floatBitsToUint(shadowBvh[groupAt(node, slot) + 6u][slot % 4u]); }
bool childPresent(uint node, uint slot) { return childReference(node, slot) != 0u; }
vec3 childMin(uint node, uint slot) {
    uint g = groupAt(node, slot), k = slot % 4u;
    return vec3(shadowBvh[g][k], shadowBvh[g + 2u][k], shadowBvh[g + 4u][k]);
}
vec3 childMax(uint node, uint slot) {
    uint g = groupAt(node, slot), k = slot % 4u;
    return vec3(shadowBvh[g + 1u][k], shadowBvh[g + 3u][k], shadowBvh[g + 5u][k]);
}
void setChildBox(uint node, uint slot, vec3 lo, vec3 hi) {
    uint g = groupAt(node, slot), k = slot % 4u;
    shadowBvh[g][k] = lo.x;
    shadowBvh[g + 1u][k] = hi.x;
    shadowBvh[g + 2u][k] = lo.y;
    shadowBvh[g + 3u][k] = hi.y;
    shadowBvh[g + 4u][k] = lo.z;
    shadowBvh[g + 5u][k] = hi.z;
}
#endif

vec3 vertexPosition(uint v) { return vec3(vertexData[8u * v], vertexData[8u * v + 1u], vertexData[8u * v + 2u]); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) return;
    if (u_pass == 0u) {
        uvec4 corners = triangleCorners[i];
        uint at = u_firstTriangle + 3u * i;
        for (uint k = 0u; k < 3u; ++k) shadowBvh[at + k].xyz = vertexPosition(corners[k]);
        return;
    }
    uint node = nodeOrder[u_first + i];
    for (uint slot = 0u; slot < uint(ML_SHADOW_BVH_WIDTH); ++slot) {
        if (!childPresent(node, slot)) continue;
        uint ref = childReference(node, slot);
        vec3 lo = vec3(1e38), hi = vec3(-1e38);
        if ((ref & ML_SHADOW_LEAF_BIT) != 0u) {
            uint first = ref & 0x0FFFFFFFu, count = ((ref >> 28) & 7u) + 1u;
            for (uint t = first; t < first + count; ++t)
                for (uint k = 0u; k < 3u; ++k) {
                    vec3 p = shadowBvh[u_firstTriangle + 3u * t + k].xyz;
                    lo = min(lo, p);
                    hi = max(hi, p);
                }
        } else {
            for (uint s = 0u; s < uint(ML_SHADOW_BVH_WIDTH); ++s) {
                if (!childPresent(ref, s)) continue;
                lo = min(lo, childMin(ref, s));
                hi = max(hi, childMax(ref, s));
            }
        }
        setChildBox(node, slot, lo, hi);
    }
}
