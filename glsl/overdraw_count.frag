#version 450 core
// --view overdraw: each fragment that reaches the shader adds 1 to its pixel (the pass blends
// ONE + ONE into an R32F target). Opaque ranges keep early depth testing, so a fragment counts
// when it passes LESS at its turn in the draw order, as the visibility raster would shade it;
// the alpha-tested variant (ML_ALPHA_TEST) counts what survives its coverage test.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"

layout(location = 0) out float o_fragments;

void main() {
    alphaTestFragment();
    o_fragments = 1.0;
}
