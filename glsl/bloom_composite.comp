#version 450 core
// Bloom, step 3: the blurred half-resolution image, bilinearly upsampled at each pixel centre
// (by hand, so the CPU reference follows it exactly), times the strength, added into the HDR
// image before the tonemap.
#include "include/bindings.h"

layout(local_size_x = ML_BLOOM_TILE, local_size_y = ML_BLOOM_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform image2D u_hdr;
layout(binding = ML_IMG_BLOOM_IN, rgba32f) uniform readonly image2D u_bloom;
uniform float u_strength;

vec3 bloomAt(ivec2 texel) { return imageLoad(u_bloom, clamp(texel, ivec2(0), imageSize(u_bloom) - 1)).rgb; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_hdr)))) return;
    // The pixel centre in half-resolution texel coordinates: fractions are 0.25 or 0.75.
    vec2 h = (vec2(p) + 0.5) * 0.5 - 0.5;
    ivec2 i0 = ivec2(floor(h));
    vec2 f = h - vec2(i0);
    vec3 below = bloomAt(i0) * (1.0 - f.x) + bloomAt(i0 + ivec2(1, 0)) * f.x;
    vec3 above = bloomAt(i0 + ivec2(0, 1)) * (1.0 - f.x) + bloomAt(i0 + ivec2(1, 1)) * f.x;
    vec3 bloom = below * (1.0 - f.y) + above * f.y;
    vec4 c = imageLoad(u_hdr, p);
    imageStore(u_hdr, p, vec4(c.rgb + u_strength * bloom, c.a));
}
