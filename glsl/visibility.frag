#version 450 core
// Visibility buffer: the raster pass writes only depth and which triangle is nearest (index + 1;
// 0 is background). Everything else is rebuilt in compute (visibility_resolve.comp). The
// alpha-tested variant (ML_ALPHA_TEST) leaves uncovered fragments out, as every method does.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"

layout(location = 0) out uint o_triangle;

void main() {
    alphaTestFragment();
    o_triangle = v_firstTriangle + uint(gl_PrimitiveID) + 1u;
}
