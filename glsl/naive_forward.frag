#version 450 core
#if ML_FIXED_LIGHT_SUM  // include/light_sum.glsl
#extension GL_ARB_gpu_shader_int64 : require
#endif
// Naive forward: every fragment loops over every light. The exact reference. With ML_TRANSPARENT
// it shades the transparent pass and writes the surface's alpha for blending.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/sun_lights.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"
#include "include/every_light.glsl"

layout(location = 0) out vec4 o_color;

void main() {
    float alpha;
    SurfacePoint s = fragmentSurfaceAndAlpha(alpha);
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    o_color = vec4(shadeUnclustered(s, viewDir) + shadeEveryLight(s, viewDir), ML_TRANSPARENT != 0 ? alpha : 1.0);
}
