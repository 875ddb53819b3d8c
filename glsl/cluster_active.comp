#version 450 core
// Active clusters (Olsson et al. 2012): flag every cluster that holds a visible sample, so the
// assignment can skip the rest (--active-only).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"
#include "include/depth_samples.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) writeonly buffer ClusterActive { uint clusterActive[]; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, depthSize()))) return;
    // Every sample: with --msaa a pixel's samples may hold surfaces in different clusters. The
    // tile is the pixel centre's, as a fragment finds it from gl_FragCoord.
    for (int s = 0; s < ML_MSAA_SAMPLES; ++s) {
        float d = depthSample(p, s);
        if (d < 1.0) clusterActive[clusterForFragment(vec2(p) + 0.5, viewDepthFromWindowDepth(d))] = 1u;
    }
}
