#version 450 core
// Bloom, step 1 (renderer/passes/bloom_pass.h): the bright part of each pixel, averaged over each 2x2
// block into the half-resolution image (edges clamp: an odd last column or row counts twice).
#include "include/bindings.h"
#include "include/bloom.glsl"

layout(local_size_x = ML_BLOOM_TILE, local_size_y = ML_BLOOM_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(binding = ML_IMG_BLOOM_OUT, rgba32f) uniform writeonly image2D u_half;
uniform float u_threshold;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_half)))) return;
    ivec2 last = imageSize(u_hdr) - 1;
    vec3 sum = bloomBrightPart(imageLoad(u_hdr, min(2 * p, last)).rgb, u_threshold);
    sum += bloomBrightPart(imageLoad(u_hdr, min(2 * p + ivec2(1, 0), last)).rgb, u_threshold);
    sum += bloomBrightPart(imageLoad(u_hdr, min(2 * p + ivec2(0, 1), last)).rgb, u_threshold);
    sum += bloomBrightPart(imageLoad(u_hdr, min(2 * p + ivec2(1, 1), last)).rgb, u_threshold);
    imageStore(u_half, p, vec4(sum * 0.25, 1.0));
}
