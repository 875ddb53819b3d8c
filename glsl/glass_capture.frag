#version 450 core
// The transparent pass's capture (renderer/passes/glass_fragments.h): the transparent ranges,
// rastered against the opaque depth, keep each fragment that passes and shade none of them.
// Drawn twice over the same fragments: first each pixel counts its own (ML_GLASS_FILL 0); the
// counts are scanned into where each pixel's fragments start; then each fragment takes the next
// place of its pixel (ML_GLASS_FILL 1), which leaves every pixel's entry at where its fragments
// end. A fragment is its depth's bits and its triangle (8 B), what the shading needs to rebuild it.
layout(early_fragment_tests) in;
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"
#include "include/glass_window.glsl"

layout(std430, binding = ML_SSBO_GLASS_PIXELS) buffer GlassPixels { uint glassPixels[]; };
#if ML_GLASS_FILL
layout(std430, binding = ML_SSBO_GLASS_FRAGMENTS) writeonly buffer GlassFragments { uvec2 glassFragments[]; };
uniform uint u_capacity;  // fragments the buffer holds: a count that wrapped past 2^32 writes none out of it
#endif

// Where the opaque depth was computed (the visibility buffer's compute raster: an R32F texture,
// none of it in the depth buffer), the capture makes the depth test itself, GL_GREATER against
// the same float as the hardware's test of a copy would (include/window_depth.glsl), and the
// raster runs without one.
uniform uint u_testsComputedDepth;
layout(binding = ML_TEX_DEPTH) uniform sampler2D u_computedDepth;

void main() {
    if (u_testsComputedDepth != 0u && !(gl_FragCoord.z > texelFetch(u_computedDepth, ivec2(gl_FragCoord.xy), 0).r)) return;
    uint pixel = glassPixel(ivec2(gl_FragCoord.xy));
    uint at = atomicAdd(glassPixels[pixel], 1u);
#if ML_GLASS_FILL
    if (at < u_capacity) glassFragments[at] = uvec2(floatBitsToUint(gl_FragCoord.z), v_firstTriangle + uint(gl_PrimitiveID));
#endif
}
