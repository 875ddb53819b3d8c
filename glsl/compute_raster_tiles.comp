#version 450 core
// The compute raster's tile pass (renderer/passes/compute_raster.h): a workgroup per (large
// triangle, screen tile) from the binning, ML_RASTER_TILE_ROWS pixels of a column per invocation.
// The pass waits on memory (the pair, its triangle, the store: one after another), so an
// invocation that takes several pixels keeps more pairs in flight; it steps its edges down the
// column (the same integers as rasterEdges64 at each pixel). With ML_RASTER_ALPHA_TEST, one
// texture set's alpha-tested triangles among the alpha-tested pairs (a dispatch per set, its
// textures bound), each pixel alpha-tested (include/compute_raster_coverage.glsl).
#extension GL_ARB_gpu_shader_int64 : require
#if ML_RASTER_ATOMIC64
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/window_depth.glsl"
#include "include/compute_raster.glsl"
#include "include/compute_raster_coverage.glsl"

#define ML_RASTER_TILE_ROWS 4  // 2 and 8 were slower on the H200 (docs/bench/nvidia-h200/tile-columns/)
const int kRows = ML_RASTER_TILE_ROWS;

layout(local_size_x = ML_RASTER_TILE, local_size_y = ML_RASTER_TILE / ML_RASTER_TILE_ROWS) in;

layout(std430, binding = ML_SSBO_RASTER_WORK) readonly buffer RasterWork { uint rasterWork[]; };
layout(std430, binding = ML_SSBO_RASTER_LARGE) readonly buffer RasterLarge { uvec4 largeTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_PAIRS) readonly buffer RasterPairs { uvec2 pairs[]; };
layout(std430, binding = ML_SSBO_RASTER_CLIPPED) readonly buffer RasterClipped { uvec4 clippedTriangles[]; };

#if ML_RASTER_ALPHA_TEST
uniform uint u_firstTriangle, u_triangles;  // the span this dispatch's texture set covers
#endif

// The large triangle at index and (out) its id.
RasterTriangle largeTriangle(uint index, out uint id) {
    uvec4 r0 = largeTriangles[3u * index], r1 = largeTriangles[3u * index + 1u], r2 = largeTriangles[3u * index + 2u];
    RasterTriangle t;
    t.v0 = ivec2(r0.xy);
    t.v1 = ivec2(r0.zw);
    t.v2 = ivec2(r1.xy);
    t.z = vec3(uintBitsToFloat(r1.zw), uintBitsToFloat(r2.x));
    id = r2.y;
    return t;
}

void main() {
    uint count = min(rasterWork[ML_RASTER_PAIR_COUNT], rasterWork[ML_RASTER_PAIR_END]);  // the pairs written (include/compute_raster_pairs.glsl)
    for (uint pair = gl_WorkGroupID.x; pair < count; pair += gl_NumWorkGroups.x) {
        uvec2 entry = pairs[pair];
        ivec2 tile = ivec2(rasterWordTile(entry.y));
        if ((entry.y & ML_RASTER_FINE_PAIR) != 0u) {
            // An 8x8 tile (never a clipped triangle's): a pixel an invocation.
            ivec2 pixel = tile * ML_RASTER_FINE_TILE + ivec2(gl_LocalInvocationIndex % ML_RASTER_FINE_TILE, gl_LocalInvocationIndex / ML_RASTER_FINE_TILE);
            if (any(greaterThanEqual(pixel, ivec2(u_viewport.xy)))) continue;
            uint id;
            RasterTriangle t = largeTriangle(entry.x, id);
#if ML_RASTER_ALPHA_TEST
            if (id - u_firstTriangle >= u_triangles) continue;  // another set's
#endif
            float depth;
            if (rasterCoversEdges(t, rasterEdges64(t, pixel), depth)) rasterStoreCovered(pixel, depth, id);
            continue;
        }
        ivec2 first = tile * ML_RASTER_TILE + ivec2(gl_LocalInvocationID.x, gl_LocalInvocationID.y * kRows);
        if (any(greaterThanEqual(first, ivec2(u_viewport.xy)))) continue;
        int rows = min(kRows, int(u_viewport.y) - first.y);
        if ((entry.x & ML_RASTER_CLIPPED_PAIR) != 0u) {
            uint at = 5u * (entry.x & ~ML_RASTER_CLIPPED_PAIR);
            uvec4 q0 = clippedTriangles[at], q1 = clippedTriangles[at + 1u], q2 = clippedTriangles[at + 2u], q3 = clippedTriangles[at + 3u];
            ClippedTriangle c;
            c.edge0 = uintBitsToFloat(q0.xyz);
            c.edge1 = uintBitsToFloat(uvec3(q0.w, q1.xy));
            c.edge2 = uintBitsToFloat(uvec3(q1.zw, q2.x));
            c.depthNumerator = uintBitsToFloat(q2.yzw);
            c.depthDenominator = uintBitsToFloat(q3.xyz);
            for (int row = 0; row < rows; ++row) {
                float clippedDepth;
                ivec2 pixel = first + ivec2(0, row);
                if (rasterCoversClipped(c, pixel, clippedDepth)) rasterStore(pixel, clippedDepth, q3.w);
            }
            continue;
        }
        uint id;
        RasterTriangle t = largeTriangle(entry.x, id);
#if ML_RASTER_ALPHA_TEST
        if (id - u_firstTriangle >= u_triangles) continue;  // another set's
#endif
        // Every pixel's coverage and depth first, then the stores: their reads issue together.
        i64vec3 e = rasterEdges64(t, first);
        i64vec3 down = rasterEdgeStepsY(t);
        float depths[kRows];
        bool covered[kRows];
        for (int row = 0; row < kRows; ++row) {
            covered[row] = row < rows && rasterCoversEdges(t, e, depths[row]);
            e += down;
        }
        for (int row = 0; row < kRows; ++row)
            if (covered[row]) rasterStoreCovered(first + ivec2(0, row), depths[row], id);
    }
}
