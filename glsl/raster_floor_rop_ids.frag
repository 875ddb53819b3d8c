#version 450 core
// Raster floors (renderer/passes/raster_floors.h): the triangle id as a colour output through the ROPs,
// as the visibility raster wrote it before it moved to image atomics (visibility.frag).
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
