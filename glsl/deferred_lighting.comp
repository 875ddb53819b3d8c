#version 450 core
#if ML_FIXED_LIGHT_SUM  // include/light_sum.glsl
#extension GL_ARB_gpu_shader_int64 : require
#endif
// Clustered deferred lighting as a compute pass (--resolve compute). On GPUs where few SMs run
// graphics work this is far faster than the fragment resolve (design.md).
//
// With --shadows sampled (ML_SHADOW_SAMPLES) every light is summed unshadowed and a few drawn a
// pixel to trace (include/shadow_sampling.glsl); the shadow passes then scale the lights' part.
//
// With per-cluster lists, a workgroup (an 8x8 pixel block) serves the lists its pixels need one
// at a time (include/list_rounds.glsl), the sums bit for bit those of the per-pixel loop.
#if defined(ML_SHADOW_SAMPLES) && ML_SHADOW_RAYS
#define ML_SHADOW_SAMPLED_LIGHTING 1
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/sun_lights.glsl"
#include "include/spot_cone.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#include "include/cluster_lists.glsl"
#include "include/debug_views.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/gbuffer_fetch.glsl"
#include "include/deferred_resolve.glsl"
#ifdef ML_SHADOW_SAMPLED_LIGHTING
#include "include/sampled_shadow_lighting.glsl"
#endif

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform writeonly image2D u_hdr;

#ifdef ML_ZBIN
// Z-binning has no list per cluster to share: each pixel walks its own bin and tile.
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
#ifdef ML_SHADOW_SAMPLED_LIGHTING
    beginShadowSampling(p, 0u);
    ResolvedPixel px;
    bool surface = resolveSurface(p, px);
    vec3 lightSum = surface && viewShadesLights() ? shadeClusterLights(px.surface, px.viewDir, px.cluster, px.viewDepth) : vec3(0.0);
    imageStore(u_hdr, p, finishSampledPixel(p, surface, px, lightSum));
#else
    imageStore(u_hdr, p, resolvePixel(p));
#endif
}
#else
#include "include/list_rounds.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    bool inside = all(lessThan(p, ivec2(u_viewport.xy)));
    ResolvedPixel px;
    bool surface = inside && resolveSurface(p, px);
    // The list this pixel still waits for; every invocation takes part in every round (barriers).
    uint pending = surface && viewShadesLights() ? clusterListKey(px.cluster, px.surface.normal) : kNoList;
    LightSum lightSum = noLight();
#ifdef ML_SHADOW_SAMPLED_LIGHTING
    beginShadowSampling(p, 0u);
#endif
    bool served;
    while (serveListRound(pending, px.surface, px.viewDir, lightSum, served))
        if (served) pending = kNoList;
    if (!inside) return;
#ifdef ML_SHADOW_SAMPLED_LIGHTING
    imageStore(u_hdr, p, finishSampledPixel(p, surface, px, lightSumValue(lightSum)));
#else
    imageStore(u_hdr, p, surface ? finishPixel(px, lightSumValue(lightSum)) : kBackground);
#endif
}
#endif
