#version 450 core
// HDR (linear) -> 8-bit sRGB: exposure, Reinhard per channel, then the sRGB transfer function.
#include "include/bindings.h"
#include "include/tonemap.glsl"

// Pixels an invocation maps, ML_TONEMAP_TILE rows apart (the program sets it; the default lets
// the build validate it): every read is issued before any write.
#ifndef ML_TONEMAP_PIXELS
#define ML_TONEMAP_PIXELS 1
#endif
const int kPixels = ML_TONEMAP_PIXELS;

layout(local_size_x = ML_TONEMAP_TILE, local_size_y = ML_TONEMAP_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(binding = ML_IMG_LDR, rgba8) uniform writeonly image2D u_ldr;
uniform float u_exposure;
#ifdef ML_AUTO_EXPOSURE
// --exposure auto: the exposure glsl/exposure_reduce.comp set this frame, times u_exposure.
layout(std430, binding = ML_SSBO_EXPOSURE) readonly buffer Exposure { float autoExposure; };
#endif
uniform uint u_displayColors;  // 1: a debug view's colours, shown as they are (sRGB-encoded, no curve)

void main() {
    ivec2 size = imageSize(u_hdr);
    ivec2 pixels[kPixels];
    vec3 hdr[kPixels];
    for (int k = 0; k < kPixels; ++k) {
        pixels[k] = ivec2(gl_GlobalInvocationID.x, (gl_WorkGroupID.y * uint(kPixels) + uint(k)) * uint(ML_TONEMAP_TILE) + gl_LocalInvocationID.y);
        hdr[k] = all(lessThan(pixels[k], size)) ? imageLoad(u_hdr, pixels[k]).rgb : vec3(0.0);
    }
#ifdef ML_AUTO_EXPOSURE
    float exposure = autoExposure * u_exposure;
#else
    float exposure = u_exposure;
#endif
    for (int k = 0; k < kPixels; ++k) {
        if (any(greaterThanEqual(pixels[k], size))) continue;
        vec3 ldr = u_displayColors != 0u ? linearToSrgb(hdr[k]) : tonemapToSrgb(hdr[k], exposure);
        imageStore(u_ldr, pixels[k], vec4(ldr, 1.0));
    }
}
