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

void main() {
    uint pixel = glassPixel(ivec2(gl_FragCoord.xy));
    uint at = atomicAdd(glassPixels[pixel], 1u);
#if ML_GLASS_FILL
    if (at < u_capacity) glassFragments[at] = uvec2(floatBitsToUint(gl_FragCoord.z), v_firstTriangle + uint(gl_PrimitiveID));
#endif
}
