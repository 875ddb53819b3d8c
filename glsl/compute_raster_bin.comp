#version 450 core
// The compute raster's binning (renderer/passes/compute_raster.h): a workgroup per large
// triangle lists (triangle, tile) for every screen tile of its pixel bounds that its edges do not
// all pass by (a tile wholly outside one edge holds none of its pixels), for the tile
// pass, and for every triangle of the clipped list (ML_RASTER_CLIPPED_PAIR marks them). A
// triangle whose tiles do not fit the list goes to the hardware's list instead. With
// ML_RASTER_ALPHA_TEST the alpha-tested triangles' lists, into their own pairs.
#extension GL_ARB_gpu_shader_int64 : require
#if ML_RASTER_ATOMIC64
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/window_depth.glsl"
#include "include/compute_raster.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = ML_SSBO_RASTER_WORK) coherent buffer RasterWork { uint rasterWork[]; };
layout(std430, binding = ML_SSBO_RASTER_LARGE) readonly buffer RasterLarge { uvec4 largeTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_PAIRS) writeonly buffer RasterPairs { uvec2 pairs[]; };
layout(std430, binding = ML_SSBO_RASTER_HARDWARE) writeonly buffer RasterHardware { uint hardwareTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_CLIPPED) readonly buffer RasterClipped { uvec4 clippedTriangles[]; };

uniform uint u_largeCapacity;
uniform uint u_pairCapacity;
uniform uint u_largeFirst;  // where the lists' large triangles start (the alpha-tested ones: after the opaque ones)
#include "include/compute_raster_pairs.glsl"
#if ML_RASTER_ALPHA_TEST
uniform uint u_spans;  // alpha-tested spans, their draws after ML_RASTER_WORK_WORDS (first: word 2)

// A triangle whose tiles do not fit: to its span's hardware list (the last span starting at or before it).
void toHardware(uint triangle) {
    uint draw = ML_RASTER_WORK_WORDS;
    for (uint i = 1u; i < u_spans && rasterWork[ML_RASTER_WORK_WORDS + 4u * i + 2u] / 3u <= triangle; ++i) draw = ML_RASTER_WORK_WORDS + 4u * i;
    hardwareTriangles[rasterWork[draw + 2u] / 3u + atomicAdd(rasterWork[draw], 3u) / 3u] = triangle;
}
#else
void toHardware(uint triangle) { hardwareTriangles[atomicAdd(rasterWork[ML_RASTER_WORK_HARDWARE_DRAW], 3u) / 3u] = triangle; }
#endif

shared uint s_count;
shared uint s_first;

// Whether a screen tile may hold pixels of the triangle (rasterTileTouches; for a clipped one, an
// edge plane at the tile's four corners).
bool tileTouches(bool clipped, uint index, uvec2 tile, int size) {
    ivec2 lo = ivec2(tile) * size, hi = lo + (size - 1);
    if (clipped) {
        ivec2 corners[4] = ivec2[](lo, ivec2(hi.x, lo.y), ivec2(lo.x, hi.y), hi);
        uvec4 q0 = clippedTriangles[5u * index], q1 = clippedTriangles[5u * index + 1u], q2 = clippedTriangles[5u * index + 2u];
        vec3 edges[3] = vec3[](uintBitsToFloat(q0.xyz), uintBitsToFloat(uvec3(q0.w, q1.xy)), uintBitsToFloat(uvec3(q1.zw, q2.x)));
        for (int e = 0; e < 3; ++e) {
            bool inside = false;
            for (int k = 0; k < 4; ++k) inside = inside || dot(edges[e], vec3(vec2(corners[k]) + 0.5, 1.0)) >= 0.0;
            if (!inside) return false;
        }
        return true;
    }
    uvec4 r0 = largeTriangles[3u * index], r1 = largeTriangles[3u * index + 1u];
    ivec2 v[3] = ivec2[](ivec2(r0.xy), ivec2(r0.zw), ivec2(r1.xy));
    return rasterTileTouches(v, tile, size);
}

void main() {
    uint largeCount = min(rasterWork[ML_RASTER_LARGE_COUNT], u_largeCapacity - u_largeFirst);
#if ML_RASTER_ALPHA_TEST
    uint count = largeCount;  // the alpha-tested ones across the eye plane went to the hardware
#else
    uint count = largeCount + min(rasterWork[ML_RASTER_WORK_CLIPPED_COUNT], u_largeCapacity);
#endif
    for (uint item = gl_WorkGroupID.x; item < count; item += gl_NumWorkGroups.x) {
        bool clipped = item >= largeCount;
        uint large = clipped ? (item - largeCount) | ML_RASTER_CLIPPED_PAIR : u_largeFirst + item;
        // Tile bounds in .zw, the triangle in .y (large); bounds in .xy, the triangle in the
        // record before's .w (clipped).
        uvec4 record = clipped ? clippedTriangles[5u * (item - largeCount) + 4u].zwxy : largeTriangles[3u * large + 2u];
        if (clipped) record.y = clippedTriangles[5u * (item - largeCount) + 3u].w;
        else if ((record.w & ML_RASTER_BINNED) != 0u) continue;  // its setup listed its tiles
        uint fine = record.z & ML_RASTER_FINE_PAIR;
        int size = fine != 0u ? ML_RASTER_FINE_TILE : ML_RASTER_TILE;
        uvec2 lo = rasterWordTile(record.z), hi = rasterWordTile(record.w);
        uvec2 extent = hi - lo + 1u;
        uint boundsTiles = extent.x * extent.y;
        uint index = large & ~ML_RASTER_CLIPPED_PAIR;
        if (gl_LocalInvocationIndex == 0u) s_count = 0u;
        barrier();
        uint touched = 0u;
        for (uint i = gl_LocalInvocationIndex; i < boundsTiles; i += gl_WorkGroupSize.x)
            if (tileTouches(clipped, index, lo + uvec2(i % extent.x, i / extent.x), size)) ++touched;
        atomicAdd(s_count, touched);
        barrier();
        uint tiles = s_count;
        if (gl_LocalInvocationIndex == 0u) {
            uint first = rasterTakePairSlots(tiles);
            if (first == ~0u) toHardware(record.y);
            s_first = first;
        }
        barrier();
        uint first = s_first;
        barrier();
        if (first == ~0u) continue;
        if (gl_LocalInvocationIndex == 0u) s_count = 0u;
        barrier();
        for (uint i = gl_LocalInvocationIndex; i < boundsTiles; i += gl_WorkGroupSize.x) {
            uvec2 tile = lo + uvec2(i % extent.x, i / extent.x);
            if (tileTouches(clipped, index, tile, size)) pairs[first + atomicAdd(s_count, 1u)] = uvec2(large, rasterTileWord(tile, fine));
        }
        barrier();
    }
}
