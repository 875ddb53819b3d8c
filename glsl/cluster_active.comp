#version 450 core
// Active clusters (Olsson et al. 2012): flag every cluster that holds a visible sample, so the
// assignment can skip the rest (--active-only).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"
#include "include/window_depth.glsl"
#include "include/depth_samples.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) writeonly buffer ClusterActive { uint clusterActive[]; };

// A depth this many float steps away from the stored one still marks (see main).
const uint kDepthSteps = 4u;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, depthSize()))) return;
    // Every sample: with --msaa a pixel's samples may hold surfaces in different clusters. The
    // tile is the pixel centre's, as a fragment finds it from gl_FragCoord.
    for (int s = 0; s < ML_MSAA_SAMPLES; ++s) {
        float d = depthSample(p, s);
        if (isBackgroundDepth(d)) continue;
        // Forward+ finds a fragment's slice from its interpolated world position, not from this
        // stored depth: the two differ by the depth's rounding, a few of its float steps (with the
        // depth not yet reversed, up to 1e-4 of the view depth far from the camera). A fragment on
        // a slice boundary then picked the unmarked neighbour and shaded with an empty list (14/255
        // off naive on the atrium at 128 log slices). So both ends of that interval are marked,
        // with the relative nudge of the other sample markers (normal bins, transparent samples) on
        // top; slices are far thicker than the interval, so no cluster lies between the two.
        uint bits = floatBitsToUint(d);
        float a = viewDepthFromWindowDepth(uintBitsToFloat(bits - min(bits, kDepthSteps)));
        float b = viewDepthFromWindowDepth(uintBitsToFloat(bits + kDepthSteps));
        float near = min(a, b) * (1.0 - 1e-5), far = max(a, b) * (1.0 + 1e-5);
        clusterActive[clusterForFragment(vec2(p) + 0.5, near)] = 1u;
        clusterActive[clusterForFragment(vec2(p) + 0.5, far)] = 1u;
    }
}
