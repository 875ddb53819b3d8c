#version 450 core
// Before the visibility resolve: which texture sets each 8x8 screen tile holds. Each tile is
// appended to the list of every set (slot = set + 1; 0 is untextured) one of its pixels needs,
// and that slot's indirect dispatch counts it, so the resolve visits, per set, only the tiles
// that hold it instead of the whole screen (H100, atrium: the resolve 0.32 -> 0.18 ms).
//
// The pass waits on memory, not on arithmetic: each pixel is an id, then its triangle's
// material, then the material's set, three reads one after another. So an invocation takes a
// block of kBlock x kBlock pixels of one tile and issues each step's reads for all of them at
// once, and a workgroup covers kBlock x kBlock tiles (docs/bench/nvidia-h200/classify-blocks/).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"

// Pixels an invocation classifies along each axis; the program sets it (VisibilityBuffer), the
// default lets the build validate it.
#ifndef ML_CLASSIFY_BLOCK
#define ML_CLASSIFY_BLOCK 2
#endif
const int kBlock = ML_CLASSIFY_BLOCK;
const int kPixels = kBlock * kBlock;

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_VISIBILITY) uniform usampler2D u_visibility;
layout(std430, binding = ML_SSBO_TRIANGLE_MATERIALS) readonly buffer TriangleMaterials { uint triangleMaterial[]; };
layout(std430, binding = ML_SSBO_RESOLVE_TILES) writeonly buffer ResolveTiles { uint resolveTiles[]; };
layout(std430, binding = ML_SSBO_RESOLVE_DISPATCH) buffer ResolveDispatch { uint resolveDispatch[]; };  // 3 per slot

shared uint s_slots[kPixels];  // per tile of the workgroup, the slots its pixels need

void main() {
    uint lane = gl_LocalInvocationIndex;
    if (lane < uint(kPixels)) s_slots[lane] = 0u;
    barrier();
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    ivec2 first = ivec2(gl_WorkGroupID.xy) * (kBlock * ML_SCREEN_TILE) + local * kBlock;
    uint ids[kPixels];
    for (int k = 0; k < kPixels; ++k) {
        ivec2 p = first + ivec2(k % kBlock, k / kBlock);
        ids[k] = all(lessThan(p, ivec2(u_viewport.xy))) ? texelFetch(u_visibility, p, 0).r : 0u;
    }
    uint materialOf[kPixels];
    for (int k = 0; k < kPixels; ++k) materialOf[k] = ids[k] != 0u ? triangleMaterial[ids[k] - 1u] : 0u;
    uint slots = 0u;
    for (int k = 0; k < kPixels; ++k)
        if (ids[k] != 0u) slots |= 1u << materials[materialOf[k]].info.z;  // info.z = set + 1
    // The block lies in one tile: the workgroup's tile (local * kBlock) / ML_SCREEN_TILE.
    ivec2 tileInGroup = local * kBlock / ML_SCREEN_TILE;
    if (slots != 0u) atomicOr(s_slots[tileInGroup.y * kBlock + tileInGroup.x], slots);
    barrier();
    if (lane >= uint(kPixels)) return;
    uvec2 tiles = (uvec2(u_viewport.xy) + uint(ML_SCREEN_TILE - 1)) / uint(ML_SCREEN_TILE);
    uvec2 at = gl_WorkGroupID.xy * uint(kBlock) + uvec2(lane % uint(kBlock), lane / uint(kBlock));
    if (any(greaterThanEqual(at, tiles))) return;
    uint tile = at.y * tiles.x + at.x, tileCount = tiles.x * tiles.y;
    for (uint mask = s_slots[lane]; mask != 0u; mask &= mask - 1u) {
        uint slot = findLSB(mask);
        uint index = atomicAdd(resolveDispatch[3u * slot], 1u);
        resolveTiles[slot * tileCount + index] = tile;
    }
}
