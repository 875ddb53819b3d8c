#version 450 core
// Bloom, step 2: one direction of the separable Gaussian at half resolution (run across, then
// down). Weights from ml::bloomKernel, centre first; edges clamp.
#include "include/bindings.h"

layout(local_size_x = ML_BLOOM_TILE, local_size_y = ML_BLOOM_TILE) in;
layout(binding = ML_IMG_BLOOM_IN, rgba32f) uniform readonly image2D u_in;
layout(binding = ML_IMG_BLOOM_OUT, rgba32f) uniform writeonly image2D u_out;
uniform uint u_vertical;  // 0: across, 1: down
uniform float u_weights[ML_BLOOM_RADIUS + 1];

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_in);
    if (any(greaterThanEqual(p, size))) return;
    ivec2 step = u_vertical != 0u ? ivec2(0, 1) : ivec2(1, 0);
    vec3 sum = u_weights[0] * imageLoad(u_in, p).rgb;
    for (int i = 1; i <= ML_BLOOM_RADIUS; ++i) {
        vec3 pair = imageLoad(u_in, clamp(p + i * step, ivec2(0), size - 1)).rgb +
                    imageLoad(u_in, clamp(p - i * step, ivec2(0), size - 1)).rgb;
        sum += u_weights[i] * pair;
    }
    imageStore(u_out, p, vec4(sum, 1.0));
}
