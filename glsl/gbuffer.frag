#version 450 core
// The G-buffer pass of clustered deferred shading: what the shading model reads, no position
// (it comes back from depth). Three RGBA16F targets: normal, albedo, specular parameters.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"

layout(location = 3) flat in uint v_materialIndex;  // scene.vert's per-draw attribute

layout(location = 0) in vec3 v_worldPos;
layout(location = 1) in vec3 v_worldNormal;
layout(location = 2) in vec2 v_uv;
layout(location = 0) out vec4 o_normal;
layout(location = 1) out vec4 o_albedo;
layout(location = 2) out vec4 o_specular;

void main() {
    SurfacePoint s = surfaceFromMaterial(v_materialIndex, v_worldPos, v_worldNormal, v_uv);
    o_normal = vec4(s.normal, 0.0);
    o_albedo = vec4(s.albedo, 1.0);
    o_specular = vec4(s.specularStrength, s.shininess, 0.0, 0.0);
}
