#version 450 core
// --shadows sampled: traces the rays the compute lighting drew (include/sampled_shadow_lighting.glsl)
// and stores the share that reach their light as the pixel's ratio, for the reuse and the filter
// (renderer/raytracing/sampled_shadows.h). A program of its own, one invocation a pixel: the
// traversal needs few registers, so it runs here at an occupancy that hides its memory latency,
// which the lighting program's registers did not allow. On the H100 this pass takes 0.42-1.06 ms
// of the atrium's frames at 2 rays a pixel, where the lighting with the same rays inside it took
// 12-17 ms (docs/bench/nvidia-h100/sampled-shadows/#the-rays-in-a-pass-of-their-own). Starting
// each 8x8 block's rays at a cut of the tree below the root, built in shared memory, was 7-21 times
// slower (351e339, reverted): every ray tested every cut entry and walked each subtree it met apart.
#ifndef ML_SHADOW_SAMPLES
#define ML_SHADOW_SAMPLES 2  // the renderer always defines it (--shadow-rays-per-pixel)
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shadow_rays.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_SHADOW_RAYS, rgba32f) uniform readonly image2D u_shadowRays;
layout(binding = ML_IMG_SHADOW_LIGHT, rgba32f) uniform image2D u_shadowLight;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_shadowLight);
    if (any(greaterThanEqual(p, size))) return;
    vec4 origin = imageLoad(u_shadowRays, p);
    if (origin.w == 0.0) return;  // no surface, or no light drawn: the ratio stays as the lighting wrote it
    uint blocked = 0u;
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        vec4 target = imageLoad(u_shadowRays, p + ivec2(0, (k + 1) * size.y));
        bool hidden;
        if (target.w >= 2.0) {
            hidden = ((blocked >> uint(target.w - 2.0)) & 1u) != 0u;  // the same light as an earlier slot
        } else {
            // As pointLightShadowed and directionalLightShadowed trace from the same origin.
            vec3 direction = target.w > 0.5 ? target.xyz - origin.xyz : target.xyz * u_lightModel.y;
            hidden = shadowRayBlocked(origin.xyz, direction);
        }
        if (hidden) blocked |= 1u << uint(k);
    }
    vec4 light = imageLoad(u_shadowLight, p);
    light.a = float(ML_SHADOW_SAMPLES - bitCount(blocked)) * (1.0 / float(ML_SHADOW_SAMPLES));
    imageStore(u_shadowLight, p, light);
}
