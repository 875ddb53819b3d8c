#version 450 core
// Raster floors (renderer/raster_floors.h): the triangle id by an image atomic instead of a colour
// output, behind an early depth test that writes depth. Each fragment that passes LESS at its
// turn is nearer than every one before it at the pixel, so the last to pass (the largest id when
// ids grow with the draw order) is the one a colour write would have left.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"

layout(early_fragment_tests) in;
layout(binding = ML_IMG_RASTER_FLOOR_IDS, r32ui) uniform coherent uimage2D u_ids;

void main() { imageAtomicMax(u_ids, ivec2(gl_FragCoord.xy), v_firstTriangle + uint(gl_PrimitiveID) + 1u); }
