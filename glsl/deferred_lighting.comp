#version 450 core
// Clustered deferred lighting as a compute pass (--resolve compute). On GPUs where few SMs run
// graphics work this is far faster than the fragment resolve (design.md).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#include "include/cluster_lists.glsl"
#include "include/debug_views.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/gbuffer_fetch.glsl"
#include "include/deferred_resolve.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform writeonly image2D u_hdr;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    imageStore(u_hdr, p, resolvePixel(p));
}
