#version 450 core
// The compute raster's depth into the depth buffer, for the transparent passes that test against
// it in hardware (renderer/passes/compute_raster.h): drawn over the glass's screen bounds only.
#include "include/bindings.h"
layout(binding = ML_TEX_DEPTH) uniform sampler2D u_rasterDepth;
void main() { gl_FragDepth = texelFetch(u_rasterDepth, ivec2(gl_FragCoord.xy), 0).r; }
