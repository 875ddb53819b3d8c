#version 450 core
// Naive forward: every fragment loops over every light. The exact reference.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"

layout(location = 3) flat in uint v_materialIndex;  // scene.vert's per-draw attribute

layout(location = 0) in vec3 v_worldPos;
layout(location = 1) in vec3 v_worldNormal;
layout(location = 2) in vec2 v_uv;
layout(location = 0) out vec4 o_color;

void main() {
    SurfacePoint s = surfaceFromMaterial(v_materialIndex, v_worldPos, v_worldNormal, v_uv);
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    vec3 color = shadeAmbient(s);
    uint n = lightCount();
    for (uint i = 0u; i < n; ++i) {
        color += shadePointLight(s, viewDir, lights[i].positionRadius, lights[i].color.rgb);
    }
    o_color = vec4(color, 1.0);
}
