#version 450 core
// Automatic exposure, step 2 of 2: one workgroup sums the tiles' partials into the frame's
// log-average luminance L, and sets the exposure that maps L to the key (middle grey):
//   target = key / 2^mean(log2 luminance)
// blended with the previous frame's in log space by u_adaptation (1: at once, as `render`
// does; less in `view`, so the picture settles over a fraction of a second instead of
// flickering). A frame with nothing lit keeps the previous exposure.
#include "include/bindings.h"

layout(local_size_x = ML_EXPOSURE_SUM_WORKGROUP) in;
layout(std430, binding = ML_SSBO_EXPOSURE_PARTIALS) readonly buffer ExposurePartials { vec2 partials[]; };
layout(std430, binding = ML_SSBO_EXPOSURE) buffer Exposure {
    float exposure;     // applied by the tonemap; 0 until the first frame sets it
    float logAverage;   // mean log2 luminance of the lit pixels
    float litShare;     // lit pixels over all pixels
    float pad;
};
uniform uint u_partials;
uniform float u_pixels;
uniform float u_key;
uniform float u_adaptation;
uniform float u_minLog2Exposure;
uniform float u_maxLog2Exposure;

shared vec2 s_sums[ML_EXPOSURE_SUM_WORKGROUP];

void main() {
    uint i = gl_LocalInvocationIndex;
    vec2 mine = vec2(0.0);
    for (uint k = i; k < u_partials; k += ML_EXPOSURE_SUM_WORKGROUP) mine += partials[k];
    s_sums[i] = mine;
    barrier();
    for (uint stride = ML_EXPOSURE_SUM_WORKGROUP / 2u; stride > 0u; stride >>= 1) {
        if (i < stride) s_sums[i] += s_sums[i + stride];
        barrier();
    }
    if (i != 0u) return;
    vec2 total = s_sums[0];
    if (total.y < 1.0) {
        if (!(exposure > 0.0)) exposure = 1.0;
        litShare = 0.0;
        return;
    }
    float average = total.x / total.y;
    float target = clamp(log2(u_key) - average, u_minLog2Exposure, u_maxLog2Exposure);
    float previous = exposure > 0.0 ? log2(exposure) : target;
    exposure = exp2(mix(previous, target, u_adaptation));
    logAverage = average;
    litShare = total.y / u_pixels;
}
