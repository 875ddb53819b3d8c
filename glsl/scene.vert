#version 450 core
// Scene geometry, already in world space (the loader flattens transforms). Every raster pass
// uses this shader, and gl_Position is invariant, so a depth pre-pass and the shading pass
// that tests against it produce bit-identical depth.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

layout(location = 0) out vec3 v_worldPos;
layout(location = 1) out vec3 v_worldNormal;
layout(location = 2) out vec2 v_uv;

invariant gl_Position;

void main() {
    v_worldPos = a_position;
    v_worldNormal = a_normal;
    v_uv = a_uv;
    // Camera-relative: a_position - eye is exact for nearby geometry even far from the origin,
    // where viewProj * a_position would cancel large terms and shift depth (issue 7, 1e5 units).
    gl_Position = u_proj * vec4(mat3(u_view) * (a_position - u_cameraPos.xyz), 1.0);
}
