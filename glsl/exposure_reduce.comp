#version 450 core
// Automatic exposure, step 1 of 2: each workgroup sums log2(luminance) over the lit pixels of
// its tile and writes (sum, count) to its partial. Pixels darker than ML_EXPOSURE_MIN_LUMINANCE
// hold nothing (the clear colour), so a small object on black is exposed for itself.
#include "include/bindings.h"

layout(local_size_x = ML_EXPOSURE_TILE, local_size_y = ML_EXPOSURE_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(std430, binding = ML_SSBO_EXPOSURE_PARTIALS) writeonly buffer ExposurePartials { vec2 partials[]; };

shared vec2 s_sums[ML_EXPOSURE_TILE * ML_EXPOSURE_TILE];

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec2 mine = vec2(0.0);
    if (all(lessThan(p, imageSize(u_hdr)))) {
        vec3 c = imageLoad(u_hdr, p).rgb;
        float luminance = dot(c, vec3(0.2126, 0.7152, 0.0722));  // Rec. 709, linear
        // Not NaN and lit (a NaN fails the comparison); infinities are clamped by the log's range.
        if (luminance > ML_EXPOSURE_MIN_LUMINANCE) mine = vec2(clamp(log2(luminance), -64.0, 64.0), 1.0);
    }
    uint i = gl_LocalInvocationIndex;
    s_sums[i] = mine;
    barrier();
    for (uint stride = (ML_EXPOSURE_TILE * ML_EXPOSURE_TILE) / 2u; stride > 0u; stride >>= 1) {
        if (i < stride) s_sums[i] += s_sums[i + stride];
        barrier();
    }
    if (i == 0u) partials[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = s_sums[0];
}
