#version 450 core
// Naive forward: every fragment loops over every light. The exact reference.
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
    SurfacePoint s = fragmentSurface();
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    o_color = vec4(addEveryLight(s, viewDir, shadeUnclustered(s, viewDir)), 1.0);
}
