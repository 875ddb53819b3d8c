#version 450 core
// HDR (linear) -> 8-bit sRGB: exposure, Reinhard per channel, then the sRGB transfer function.
#include "include/bindings.h"
#include "include/tonemap.glsl"

layout(local_size_x = ML_TONEMAP_TILE, local_size_y = ML_TONEMAP_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(binding = ML_IMG_LDR, rgba8) uniform writeonly image2D u_ldr;
uniform float u_exposure;
uniform uint u_displayColors;  // 1: a debug view's colours, shown as they are (sRGB-encoded, no curve)

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_hdr)))) return;
    vec3 hdr = imageLoad(u_hdr, p).rgb;
    vec3 ldr = u_displayColors != 0u ? linearToSrgb(hdr) : tonemapToSrgb(hdr, u_exposure);
    imageStore(u_ldr, p, vec4(ldr, 1.0));
}
