#version 450 core
// Fitted slicing: the min and max view depth of the visible samples, reduced over the depth
// buffer (phase 0), then turned into the log slicing of that range (phase 1, one invocation).
// With no visible sample the camera's near and far are sliced instead. Where the raster reduced
// its own depth as it wrote it (the compute raster's finish, the same values), phase 1 takes its
// words and phase 0 does not run.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#define ML_CLUSTER_GRID_WRITABLE
#include "include/cluster_grid.glsl"
#include "include/window_depth.glsl"
#include "include/depth_samples.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
uniform uint u_phase;
uniform uint u_rasterRangeWord;  // ~0u: phase 0 ran; else where the raster's range lies in its work buffer
layout(std430, binding = ML_SSBO_RASTER_WORK) readonly buffer RasterWork { uint rasterWork[]; };

shared uint s_min[ML_SCREEN_TILE * ML_SCREEN_TILE];
shared uint s_max[ML_SCREEN_TILE * ML_SCREEN_TILE];

void main() {
    if (u_phase == 1u) {
        float n = grid.tile.z, f = grid.tile.w;
        // Positive floats order like their bit patterns.
        uvec2 range = grid.reduction.xy;  // from the glass's extent (ClusteredLighting::uploadGrid)
        if (u_rasterRangeWord != ~0u)
            range = uvec2(min(range.x, rasterWork[u_rasterRangeWord]), max(range.y, rasterWork[u_rasterRangeWord + 1u]));
        if (range.x <= range.y) {
            n = uintBitsToFloat(range.x);
            f = uintBitsToFloat(range.y);
        }
        f = max(f, n * (1.0 + 1e-4) + 1e-6);
        grid.slicing.x = n;
        grid.slicing.y = f;
        grid.slicing.z = float(grid.dims.z) / log(f / n);
        grid.slicing.w = -log(n) * grid.slicing.z;
        return;
    }
    // Each invocation reduces a block of ML_DEPTH_RANGE_BLOCK^2 pixels first: a workgroup per
    // 8x8 pixels made 57,600 workgroups at 2560x1440, whose barriers cost more than the reads.
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * ML_DEPTH_RANGE_BLOCK;
    ivec2 size = depthSize();
    uint lane = gl_LocalInvocationIndex;
    // View depth of every pixel (every sample with --msaa), as the shading passes compute it
    // (so the range holds each one exactly, rounding included).
    uint lo = 0xFFFFFFFFu, hi = 0u;
    for (int y = 0; y < ML_DEPTH_RANGE_BLOCK; ++y) {
        for (int x = 0; x < ML_DEPTH_RANGE_BLOCK; ++x) {
            ivec2 p = first + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            for (int s = 0; s < ML_MSAA_SAMPLES; ++s) {
                float d = depthSample(p, s);
                if (!isBackgroundDepth(d)) {
                    uint bits = floatBitsToUint(viewDepthFromWindowDepth(d));
                    lo = min(lo, bits);
                    hi = max(hi, bits);
                }
            }
        }
    }
    s_min[lane] = lo;
    s_max[lane] = hi;
    for (uint stride = (ML_SCREEN_TILE * ML_SCREEN_TILE) / 2u; stride > 0u; stride >>= 1) {
        barrier();
        if (lane < stride) {
            s_min[lane] = min(s_min[lane], s_min[lane + stride]);
            s_max[lane] = max(s_max[lane], s_max[lane + stride]);
        }
    }
    if (lane == 0u) {
        if (s_min[0] != 0xFFFFFFFFu) atomicMin(grid.reduction.x, s_min[0]);
        if (s_max[0] != 0u) atomicMax(grid.reduction.y, s_max[0]);
    }
}
