#version 450 core
// Active clusters (Olsson et al. 2012): flag every cluster that holds a visible sample, so the
// assignment can skip the rest (--active-only).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_DEPTH) uniform sampler2D u_depth;
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) writeonly buffer ClusterActive { uint clusterActive[]; };

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(u_depth, 0)))) return;
    float d = texelFetch(u_depth, p, 0).r;
    if (d >= 1.0) return;
    clusterActive[clusterForFragment(vec2(p) + 0.5, viewDepthFromWindowDepth(d))] = 1u;
}
