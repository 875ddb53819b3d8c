#version 450 core
// Depth pre-pass: depth is all this pass writes. The alpha-tested variant (ML_ALPHA_TEST)
// discards where the material is not covered, exactly as the shading pass does.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"

void main() { alphaTestFragment(); }
