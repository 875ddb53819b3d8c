#version 450 core
#if ML_FIXED_LIGHT_SUM  // include/light_sum.glsl
#extension GL_ARB_gpu_shader_int64 : require
#endif
// Clustered deferred lighting as a full-screen fragment pass (--resolve fragment).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/sun_lights.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#include "include/cluster_lists.glsl"
#include "include/debug_views.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/gbuffer_fetch.glsl"
#include "include/deferred_resolve.glsl"

layout(location = 0) out vec4 o_color;

void main() { o_color = resolvePixel(ivec2(gl_FragCoord.xy)); }
