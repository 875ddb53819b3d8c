#version 450 core
// The compute raster's last pass (renderer/passes/compute_raster.h): each pixel's nearest
// triangle to the visibility buffer's id target (index + 1; 0 background) and its depth to an
// R32F target (0 where nothing was drawn), and the store reset for the next frame.
#extension GL_ARB_gpu_shader_int64 : require
#if ML_RASTER_ATOMIC64
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/window_depth.glsl"
#include "include/compute_raster.glsl"

// Pixels an invocation finishes, ML_RASTER_FINISH_ROW apart in its row (the program sets it;
// the default lets the build validate it): every read is issued before any write, which the
// compiler could not move past another pixel's reset (the store is one buffer).
#ifndef ML_RASTER_FINISH_PIXELS
#define ML_RASTER_FINISH_PIXELS 1
#endif
const int kPixels = ML_RASTER_FINISH_PIXELS;

layout(local_size_x = ML_RASTER_FINISH_ROW) in;  // a row strip: the store is row-major
layout(binding = ML_IMG_VISIBILITY_IDS, r32ui) uniform writeonly uimage2D u_ids;
layout(binding = ML_IMG_RASTER_DEPTH, r32f) uniform writeonly image2D u_depth;

void main() {
    ivec2 pixels[kPixels];
    bool inside[kPixels];
    uint keys[kPixels], triangles[kPixels];
    for (int k = 0; k < kPixels; ++k) {
        pixels[k] = ivec2((gl_WorkGroupID.x * uint(kPixels) + uint(k)) * uint(ML_RASTER_FINISH_ROW) + gl_LocalInvocationID.x, gl_WorkGroupID.y);
        inside[k] = all(lessThan(pixels[k], ivec2(u_viewport.xy)));
        uint at = uint(pixels[k].y) * uint(u_viewport.x) + uint(pixels[k].x);
        keys[k] = ~0u;
        triangles[k] = ~0u;
        if (!inside[k]) continue;
#if ML_RASTER_ATOMIC64
        uvec2 word = unpackUint2x32(depthIds[at]);
        triangles[k] = word.x;
        keys[k] = word.y;
#else
        keys[k] = depthIds[at];
        triangles[k] = depthIds[rasterPixelCount() + at];
#endif
    }
    for (int k = 0; k < kPixels; ++k) {
        if (!inside[k]) continue;
        uint at = uint(pixels[k].y) * uint(u_viewport.x) + uint(pixels[k].x);
#if ML_RASTER_ATOMIC64
        depthIds[at] = ~0ul;
#else
        depthIds[at] = ~0u;
        depthIds[rasterPixelCount() + at] = ~0u;
#endif
        bool drawn = keys[k] != ~0u;
        imageStore(u_ids, pixels[k], uvec4(drawn ? triangles[k] + 1u : 0u));
        imageStore(u_depth, pixels[k], vec4(rasterKeyDepth(keys[k])));  // the background's key gives depth 0
    }
}
