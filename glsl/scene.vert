#version 450 core
// Scene geometry, already in world space (the loader flattens transforms). Every raster pass
// uses this shader, and gl_Position is invariant, so a depth pre-pass and the shading pass
// that tests against it produce bit-identical depth. It passes on no attribute to shade with:
// fragments rebuild their surface from their triangle (include/scene_fragment.glsl).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"

layout(location = 0) in vec3 a_position;
// Per draw range (instance divisor 1, baseInstance = range): material, first triangle. Direct and
// multi-draw-indirect submission both feed it (renderer/scene/scene_gpu.h).
layout(location = 3) in uvec2 a_drawParams;

layout(location = 0) out vec3 v_worldPos;
layout(location = 3) flat out uint v_materialIndex;
layout(location = 4) flat out uint v_firstTriangle;

invariant gl_Position;

void main() {
    v_worldPos = a_position;
    v_materialIndex = a_drawParams.x;
    v_firstTriangle = a_drawParams.y;
    // Camera-relative: a_position - eye is exact for nearby geometry even far from the origin,
    // where viewProj * a_position would cancel large terms and shift depth (issue 7, 1e5 units).
    gl_Position = u_proj * vec4(mat3(u_view) * (a_position - u_cameraPos.xyz), 1.0);
}
