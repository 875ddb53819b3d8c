#version 450 core
#if ML_FIXED_LIGHT_SUM  // include/light_sum.glsl
#extension GL_ARB_gpu_shader_int64 : require
#endif
// Clustered forward (Forward+): after the depth pre-pass, each visible fragment finds its
// cluster (tile from the pixel, slice from view depth) and loops over that cluster's lights.
// With ML_TRANSPARENT it is the transparent pass of every clustered method: shaded colour and
// the surface's alpha, blended over the opaque frame (debug views leave that pass out).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/sun_lights.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#include "include/cluster_lists.glsl"
#include "include/debug_views.glsl"
#include "include/every_light.glsl"

layout(location = 0) out vec4 o_color;

#ifndef ML_MSAA_SAMPLES
#define ML_MSAA_SAMPLES 1
#endif
#if ML_MSAA_SAMPLES > 1 && !defined(ML_ZBIN)
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) readonly buffer ClusterActive { uint clusterActive[]; };
// With --msaa a fragment is shaded once, at the pixel centre, which may lie off the samples it
// covers (its surface extended to the centre), so in a cluster no sample marked: --active-only
// gave that cluster no lights. Such a fragment (a few on edges) loops over every light instead.
bool clusterListSkipped(uint cluster) { return grid.options.z != 0u && clusterActive[cluster] == 0u; }
#else
bool clusterListSkipped(uint cluster) { return false; }
#endif

vec3 shadeLights(SurfacePoint s, vec3 viewDir, uint cluster, float viewDepth) {
    if (clusterListSkipped(cluster)) return shadeEveryLight(s, viewDir);
    return shadeClusterLights(s, viewDir, cluster, viewDepth);
}

void main() {
    float alpha;
    SurfacePoint s = fragmentSurfaceAndAlpha(alpha);
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    float viewDepth = -(u_view * vec4(v_worldPos, 1.0)).z;
    uint cluster = clusterForFragment(gl_FragCoord.xy, viewDepth);
#if ML_TRANSPARENT
    o_color = vec4(shadeUnclustered(s, viewDir) + shadeLights(s, viewDir, cluster, viewDepth), alpha);
#else
    uint view = grid.options.w;
    vec3 color = vec3(0.0);
    if (view == ML_VIEW_SHADED || view == ML_VIEW_OVERFLOW) color = shadeUnclustered(s, viewDir) + shadeLights(s, viewDir, cluster, viewDepth);
    o_color = vec4(debugViewColor(view, s, cluster, viewDepth, color), 1.0);
#endif
}
