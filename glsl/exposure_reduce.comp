#version 450 core
// Automatic exposure, step 1 of 2: each workgroup sums log2(luminance) over the lit pixels of
// its ML_EXPOSURE_TILE-wide tile and writes (sum, count) to its partial. Pixels darker than
// ML_EXPOSURE_MIN_LUMINANCE hold nothing (the clear colour), so a small object on black is
// exposed for itself. An invocation sums several pixels, a workgroup's width apart, so that each
// warp's reads stay in rows and the tree and its barriers are paid once per tile.
#include "include/bindings.h"

layout(local_size_x = ML_EXPOSURE_WORKGROUP, local_size_y = ML_EXPOSURE_WORKGROUP) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(std430, binding = ML_SSBO_EXPOSURE_PARTIALS) writeonly buffer ExposurePartials { vec2 partials[]; };

shared vec2 s_sums[ML_EXPOSURE_WORKGROUP * ML_EXPOSURE_WORKGROUP];

void main() {
    ivec2 size = imageSize(u_hdr);
    ivec2 origin = ivec2(gl_WorkGroupID.xy) * ML_EXPOSURE_TILE + ivec2(gl_LocalInvocationID.xy);
    vec2 mine = vec2(0.0);
    for (int y = 0; y < ML_EXPOSURE_TILE; y += ML_EXPOSURE_WORKGROUP) {
        for (int x = 0; x < ML_EXPOSURE_TILE; x += ML_EXPOSURE_WORKGROUP) {
            ivec2 p = origin + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            vec3 c = imageLoad(u_hdr, p).rgb;
            float luminance = dot(c, vec3(0.2126, 0.7152, 0.0722));  // Rec. 709, linear
            // Not NaN and lit (a NaN fails the comparison); infinities are clamped by the log's range.
            if (luminance > ML_EXPOSURE_MIN_LUMINANCE) mine += vec2(clamp(log2(luminance), -64.0, 64.0), 1.0);
        }
    }
    uint i = gl_LocalInvocationIndex;
    s_sums[i] = mine;
    barrier();
    for (uint stride = (ML_EXPOSURE_WORKGROUP * ML_EXPOSURE_WORKGROUP) / 2u; stride > 0u; stride >>= 1) {
        if (i < stride) s_sums[i] += s_sums[i + stride];
        barrier();
    }
    if (i == 0u) partials[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = s_sums[0];
}
