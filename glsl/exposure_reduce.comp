#version 450 core
// Automatic exposure, in one dispatch: each workgroup sums log2(luminance) over the lit pixels of
// its ML_EXPOSURE_TILE-wide tile and writes (sum, count) to its partial; the last workgroup to
// finish (a counter) sums the partials into the frame's log-average luminance L and sets the
// exposure that maps L to the key (middle grey):
//   target = key / 2^mean(log2 luminance)
// blended with the previous frame's in log space by u_adaptation (1: at once, as `render`
// does; less in `view`, so the picture settles over a fraction of a second instead of
// flickering). A frame with nothing lit keeps the previous exposure. Pixels darker than
// ML_EXPOSURE_MIN_LUMINANCE hold nothing (the clear colour), so a small object on black is
// exposed for itself. An invocation sums several pixels, a workgroup's width apart, so that each
// warp's reads stay in rows and the tree and its barriers are paid once per tile.
#include "include/bindings.h"

layout(local_size_x = ML_EXPOSURE_WORKGROUP, local_size_y = ML_EXPOSURE_WORKGROUP) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform readonly image2D u_hdr;
layout(std430, binding = ML_SSBO_EXPOSURE_PARTIALS) coherent buffer ExposurePartials {
    uint finished;  // workgroups done this frame; the last sets it back to 0
    uint pad_;
    vec2 partials[];
};
layout(std430, binding = ML_SSBO_EXPOSURE) buffer Exposure {
    float exposure;     // applied by the tonemap; 0 until the first frame sets it
    float logAverage;   // mean log2 luminance of the lit pixels
    float litShare;     // lit pixels over all pixels
    float pad;
};
uniform float u_pixels;
uniform float u_key;
uniform float u_adaptation;
uniform float u_minLog2Exposure;
uniform float u_maxLog2Exposure;

const uint kInvocations = uint(ML_EXPOSURE_WORKGROUP * ML_EXPOSURE_WORKGROUP);
shared vec2 s_sums[kInvocations];
shared bool s_last;

// The workgroup's values summed into s_sums[0] (every invocation calls it).
void sumShared(uint i, vec2 mine) {
    s_sums[i] = mine;
    barrier();
    for (uint stride = kInvocations / 2u; stride > 0u; stride >>= 1) {
        if (i < stride) s_sums[i] += s_sums[i + stride];
        barrier();
    }
}

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
    sumShared(i, mine);
    uint tiles = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
    if (i == 0u) {
        partials[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = s_sums[0];
        memoryBarrierBuffer();  // the partial is visible before the count says so
        s_last = atomicAdd(finished, 1u) == tiles - 1u;
    }
    barrier();
    if (!s_last) return;
    memoryBarrierBuffer();
    mine = vec2(0.0);
    for (uint k = i; k < tiles; k += kInvocations) mine += partials[k];
    sumShared(i, mine);
    if (i != 0u) return;
    finished = 0u;
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
