#version 450 core
// The methods' colour -> one linear HDR value per output pixel, before bloom and the tonemap:
// the mean of the pixel's ML_MSAA_SAMPLES samples (--msaa), or of its ML_SUPERSAMPLE x
// ML_SUPERSAMPLE block of the image drawn at K times the size (--supersample). A box filter in
// linear light, as the supersampled reference is defined, summed in a fixed order so every
// driver resolves alike (glBlitFramebuffer's resolve is implementation-defined).
#include "include/bindings.h"
#ifndef ML_MSAA_SAMPLES
#define ML_MSAA_SAMPLES 1
#endif
#ifndef ML_SUPERSAMPLE
#define ML_SUPERSAMPLE 1
#endif

layout(local_size_x = ML_TONEMAP_TILE, local_size_y = ML_TONEMAP_TILE) in;
#if ML_MSAA_SAMPLES > 1
layout(binding = ML_TEX_RESOLVE_SOURCE) uniform sampler2DMS u_source;
#else
layout(binding = ML_TEX_RESOLVE_SOURCE) uniform sampler2D u_source;
#endif
layout(binding = ML_IMG_HDR, rgba32f) uniform writeonly image2D u_output;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_output)))) return;
    vec3 sum = vec3(0.0);
#if ML_MSAA_SAMPLES > 1
    for (int i = 0; i < ML_MSAA_SAMPLES; ++i) sum += texelFetch(u_source, p, i).rgb;
    sum /= float(ML_MSAA_SAMPLES);
#else
    for (int y = 0; y < ML_SUPERSAMPLE; ++y)
        for (int x = 0; x < ML_SUPERSAMPLE; ++x) sum += texelFetch(u_source, p * ML_SUPERSAMPLE + ivec2(x, y), 0).rgb;
    sum /= float(ML_SUPERSAMPLE * ML_SUPERSAMPLE);
#endif
    imageStore(u_output, p, vec4(sum, 1.0));
}
