#version 450 core
// Fitted slicing: the min and max view depth of the visible samples, reduced over the depth
// buffer (phase 0), then turned into the log slicing of that range (phase 1, one invocation,
// include/fitted_slicing.glsl), where the grid has no cluster bounds to slice it (z-binning):
// cluster_bounds.comp slices it otherwise. Where the raster reduced its own depth as it wrote it
// (the compute raster's finish, the same values), phase 0 does not run.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#define ML_CLUSTER_GRID_WRITABLE
#include "include/cluster_grid.glsl"
#include "include/fitted_slicing.glsl"
#include "include/window_depth.glsl"
#include "include/depth_samples.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
uniform uint u_phase;

shared uint s_min[ML_SCREEN_TILE * ML_SCREEN_TILE];
shared uint s_max[ML_SCREEN_TILE * ML_SCREEN_TILE];

void main() {
    if (u_phase == 1u) {
        grid.slicing = fittedSlicing();
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
