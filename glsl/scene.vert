#version 450 core
// Scene geometry, already in world space (the loader flattens transforms). Every raster pass
// uses this shader, and gl_Position is invariant, so a depth pre-pass and the shading pass
// that tests against it produce bit-identical depth. The optional vertex streams exist only
// where the scene's materials use them (ML_MATERIAL_FEATURES, include/material.glsl).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/material_features.glsl"

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
// Per draw range (instance divisor 1, baseInstance = range): material, first triangle. Direct and
// multi-draw-indirect submission both feed it (renderer/scene/scene_gpu.h).
layout(location = 3) in uvec2 a_drawParams;

layout(location = 0) out vec3 v_worldPos;
layout(location = 1) out vec3 v_worldNormal;
layout(location = 3) flat out uint v_materialIndex;
layout(location = 4) flat out uint v_firstTriangle;
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
layout(location = 4) in vec4 a_tangent;
layout(location = 5) out vec4 v_tangent;
#endif
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
layout(location = 6) in vec4 a_color;
layout(location = 7) out vec4 v_color;
#endif

invariant gl_Position;

void main() {
    v_worldPos = a_position;
    v_worldNormal = a_normal;
    v_materialIndex = a_drawParams.x;
    v_firstTriangle = a_drawParams.y;
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
    v_tangent = a_tangent;
#endif
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
    v_color = a_color;
#endif
    // Camera-relative: a_position - eye is exact for nearby geometry even far from the origin,
    // where viewProj * a_position would cancel large terms and shift depth (issue 7, 1e5 units).
    gl_Position = u_proj * vec4(mat3(u_view) * (a_position - u_cameraPos.xyz), 1.0);
}
