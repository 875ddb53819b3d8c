#version 450 core
// HDR (linear) -> 8-bit sRGB: exposure, Reinhard per channel, then the sRGB transfer function.
#include "include/bindings.h"
#include "include/tonemap.glsl"

layout(local_size_x = ML_TONEMAP_TILE, local_size_y = ML_TONEMAP_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(binding = ML_IMG_LDR, rgba8) uniform writeonly image2D u_ldr;
uniform float u_exposure;
#ifdef ML_AUTO_EXPOSURE
// --exposure auto: the exposure glsl/exposure_adapt.comp set this frame, times u_exposure.
layout(std430, binding = ML_SSBO_EXPOSURE) readonly buffer Exposure { float autoExposure; };
#endif
uniform uint u_displayColors;  // 1: a debug view's colours, shown as they are (sRGB-encoded, no curve)

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_hdr)))) return;
    vec3 hdr = imageLoad(u_hdr, p).rgb;
#ifdef ML_AUTO_EXPOSURE
    float exposure = autoExposure * u_exposure;
#else
    float exposure = u_exposure;
#endif
    vec3 ldr = u_displayColors != 0u ? linearToSrgb(hdr) : tonemapToSrgb(hdr, exposure);
    imageStore(u_ldr, p, vec4(ldr, 1.0));
}
