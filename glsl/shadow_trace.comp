#version 450 core
// --shadows sampled: traces the rays the compute lighting drew (include/sampled_shadow_lighting.glsl)
// and stores the share that reach their light as the pixel's ratio, for the reuse and the filter
// (renderer/raytracing/sampled_shadows.h). A program of its own, one invocation a pixel: the
// traversal needs few registers and the lighting many, and traced inside the lighting the rays
// ran at a fifth of the exact rays' rate on the H100 (docs/bench/nvidia-h100/sampled-shadows);
// this pass's own time there is not yet measured.
//
// A workgroup's rays start below the root: the box around all of them is walked down the tree
// once, breadth first, to at most kCutEntries nodes that overlap it (the cut), and each ray tests
// the cut's boxes from shared memory and walks down from those it meets. Every triangle a ray can
// meet lies in a node that overlaps the box, so the result is the walk from the root's; the ray
// skips the levels above the cut, which every ray of the block would have walked alike.
#ifndef ML_SHADOW_SAMPLES
#define ML_SHADOW_SAMPLES 2  // the renderer always defines it (--shadow-rays-per-pixel)
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shadow_rays.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_SHADOW_RAYS, rgba32f) uniform readonly image2D u_shadowRays;
layout(binding = ML_IMG_SHADOW_LIGHT, rgba32f) uniform image2D u_shadowLight;

const uint kCutEntries = 16u;
shared uint s_cutRef[kCutEntries];  // 0: an entry dropped (the root is no one's child)
shared vec3 s_cutLo[kCutEntries], s_cutHi[kCutEntries];
shared uint s_cutCount;
shared int s_boxKey[6];  // the block's rays' box, lo then hi, as orderedKey

// A float's bits as an int that orders as the float does, for atomicMin and atomicMax (and back:
// the mapping is its own inverse).
int orderedKey(float f) {
    int bits = floatBitsToInt(f);
    return bits >= 0 ? bits : bits ^ 0x7FFFFFFF;
}
float orderedValue(int key) { return intBitsToFloat(key >= 0 ? key : key ^ 0x7FFFFFFF); }

void growBlockBox(vec3 p) {
    for (int i = 0; i < 3; ++i) {
        atomicMin(s_boxKey[i], orderedKey(p[i]));
        atomicMax(s_boxKey[3 + i], orderedKey(p[i]));
    }
}

bool boxesOverlap(vec3 lo, vec3 hi, vec3 otherLo, vec3 otherHi) { return all(lessThanEqual(lo, otherHi)) && all(lessThanEqual(otherLo, hi)); }

// The cut (one invocation builds it): level by level from the root, every inner node of the cut
// is replaced by its children that overlap the box, while the cut stays within kCutEntries.
void buildCut(vec3 lo, vec3 hi) {
    s_cutRef[0] = 0u;  // the root, whose box is everything
    s_cutLo[0] = lo;
    s_cutHi[0] = hi;
    uint count = 1u;
    bool full = false;
    for (uint level = 0u; level < uint(ML_SHADOW_STACK) && !full; ++level) {
        uint levelCount = count;
        bool grew = false;
        for (uint e = 0u; e < levelCount; ++e) {
            uint ref = s_cutRef[e];
            if ((ref & ML_SHADOW_LEAF_BIT) != 0u) continue;  // a leaf (a dropped entry is compacted out below)
            uint children[ML_SHADOW_BVH_WIDTH];
            vec3 childLo[ML_SHADOW_BVH_WIDTH], childHi[ML_SHADOW_BVH_WIDTH];
            uint meets = 0u;
            for (uint slot = 0u; slot < uint(ML_SHADOW_BVH_WIDTH); ++slot) {
                vec3 cLo, cHi;
                uint child = shadowNodeChild(ref, slot, cLo, cHi);
                if (child != 0u && boxesOverlap(cLo, cHi, lo, hi)) {
                    children[meets] = child;
                    childLo[meets] = cLo;
                    childHi[meets] = cHi;
                    ++meets;
                }
            }
            if (count - 1u + meets > kCutEntries) {
                full = true;
                break;
            }
            // The node's place takes its first child (or marks it dropped); the others go after.
            s_cutRef[e] = meets > 0u ? children[0] : 0u;
            if (meets > 0u) {
                s_cutLo[e] = childLo[0];
                s_cutHi[e] = childHi[0];
            }
            for (uint c = 1u; c < meets; ++c) {
                s_cutRef[count] = children[c];
                s_cutLo[count] = childLo[c];
                s_cutHi[count] = childHi[c];
                ++count;
            }
            grew = true;
        }
        if (!grew) break;
        // Drop the dropped, so that they do not count against the cut's size.
        uint kept = 0u;
        for (uint e = 0u; e < count; ++e) {
            if (s_cutRef[e] == 0u) continue;
            s_cutRef[kept] = s_cutRef[e];
            s_cutLo[kept] = s_cutLo[e];
            s_cutHi[kept] = s_cutHi[e];
            ++kept;
        }
        count = kept;
        if (count == 0u) break;
    }
    s_cutCount = count;
}

// Whether the ray meets anything, walking down from the cut's entries.
bool cutRayBlocked(vec3 origin, vec3 direction) {
    if (!shadowRayTraced(origin, direction)) return false;
    vec3 inverse = shadowRayInverse(direction);
    for (uint e = 0u; e < s_cutCount; ++e) {
        uint ref = s_cutRef[e];
        if (ref == 0u) {
            if (shadowSubtreeBlocks(0u, origin, direction, inverse)) return true;  // the cut is the root
        } else if (shadowBoxHit(s_cutLo[e], s_cutHi[e], origin, inverse) && shadowSubtreeBlocks(ref, origin, direction, inverse)) {
            return true;
        }
    }
    return false;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_shadowLight);
    if (gl_LocalInvocationIndex == 0u) {
        for (int i = 0; i < 3; ++i) {
            s_boxKey[i] = orderedKey(uintBitsToFloat(0x7F800000u));       // +infinity
            s_boxKey[3 + i] = orderedKey(uintBitsToFloat(0xFF800000u));   // -infinity
        }
    }
    barrier();
    // Every invocation takes part in the barriers; those without rays add nothing to the box.
    vec4 origin = all(lessThan(p, size)) ? imageLoad(u_shadowRays, p) : vec4(0.0);
    bool drew = origin.w != 0.0;  // else no surface, or no light drawn: the ratio stays as the lighting wrote it
    // Per slot, the ray's direction, or the earlier slot of the same light (w >= 2: its index + 2).
    vec4 rays[ML_SHADOW_SAMPLES];
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        vec4 target = drew ? imageLoad(u_shadowRays, p + ivec2(0, (k + 1) * size.y)) : vec4(0.0, 0.0, 0.0, 2.0);
        if (target.w >= 2.0) {
            rays[k] = target;
            continue;
        }
        // As pointLightShadowed and directionalLightShadowed trace from the same origin.
        vec3 direction = target.w > 0.5 ? target.xyz - origin.xyz : target.xyz * u_lightModel.y;
        rays[k] = vec4(direction, 0.0);
        if (!shadowNotFinite(origin.xyz) && !shadowNotFinite(direction)) {
            growBlockBox(origin.xyz);
            growBlockBox(origin.xyz + direction);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        vec3 lo = vec3(orderedValue(s_boxKey[0]), orderedValue(s_boxKey[1]), orderedValue(s_boxKey[2]));
        vec3 hi = vec3(orderedValue(s_boxKey[3]), orderedValue(s_boxKey[4]), orderedValue(s_boxKey[5]));
        // Padded, so that a hit that the triangle test's rounding places just past the segment's
        // end still falls in a node of the cut.
        vec3 pad = 1e-4 * (hi - lo + abs(lo) + abs(hi)) + 1e-6;
        if (u_shadows.y > 0u && all(lessThanEqual(lo, hi))) buildCut(lo - pad, hi + pad);
        else s_cutCount = 0u;
    }
    barrier();
    if (!drew) return;
    uint blocked = 0u;
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        bool hidden = rays[k].w >= 2.0 ? ((blocked >> uint(rays[k].w - 2.0)) & 1u) != 0u  // the same light as an earlier slot
                                       : cutRayBlocked(origin.xyz, rays[k].xyz);
        if (hidden) blocked |= 1u << uint(k);
    }
    vec4 light = imageLoad(u_shadowLight, p);
    light.a = float(ML_SHADOW_SAMPLES - bitCount(blocked)) * (1.0 / float(ML_SHADOW_SAMPLES));
    imageStore(u_shadowLight, p, light);
}
