#version 450 core
// The compute raster's last pass (renderer/passes/compute_raster.h): each pixel's nearest
// triangle to the visibility buffer's id target (index + 1; 0 background) and its depth to an
// R32F target (0 where nothing was drawn), and the pixels nothing was drawn at set empty
// (include/compute_raster.glsl: the store is not reset).
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
// compiler could not move past another pixel's store write (the store is one buffer).
#ifndef ML_RASTER_FINISH_PIXELS
#define ML_RASTER_FINISH_PIXELS 1
#endif
const int kPixels = ML_RASTER_FINISH_PIXELS;

layout(local_size_x = ML_RASTER_FINISH_ROW) in;  // a row strip: the store is row-major
layout(binding = ML_IMG_VISIBILITY_IDS, r32ui) uniform writeonly uimage2D u_ids;
layout(binding = ML_IMG_RASTER_DEPTH, r32f) uniform writeonly image2D u_depth;

#if ML_RASTER_VIEW_DEPTH_RANGE
// Fitted slicing's range, as cluster_depth_range.comp's phase 0 would reduce it from the depth
// written here (the same floats, the same function; positive floats order as their bits), so
// that pass reads no depth: over the workgroup, then into the frame's two words.
layout(std430, binding = ML_SSBO_RASTER_WORK) coherent buffer RasterWork { uint rasterWork[]; };
shared uint s_nearest[ML_RASTER_FINISH_ROW], s_farthest[ML_RASTER_FINISH_ROW];

void addViewDepthRange(uint nearest, uint farthest) {
    uint lane = gl_LocalInvocationIndex;
    s_nearest[lane] = nearest;
    s_farthest[lane] = farthest;
    for (uint stride = uint(ML_RASTER_FINISH_ROW) / 2u; stride > 0u; stride >>= 1) {
        barrier();
        if (lane < stride) {
            s_nearest[lane] = min(s_nearest[lane], s_nearest[lane + stride]);
            s_farthest[lane] = max(s_farthest[lane], s_farthest[lane + stride]);
        }
    }
    if (lane != 0u) return;
    // Most workgroups find the frame's words already past theirs: a read spares the atomic (a
    // stale word is only further from the answer, so the test never skips one that is needed).
    uint at = ML_RASTER_WORK_VIEW_DEPTH_RANGE;
    if (s_nearest[0] < rasterWork[at]) atomicMin(rasterWork[at], s_nearest[0]);
    if (s_farthest[0] > rasterWork[at + 1u]) atomicMax(rasterWork[at + 1u], s_farthest[0]);
}
#endif

void main() {
    ivec2 pixels[kPixels];
    bool inside[kPixels];
    uint keys[kPixels], triangles[kPixels];
    bool empty[kPixels];  // the store's words at the pixel are ML_RASTER_STORE_EMPTY already
    for (int k = 0; k < kPixels; ++k) {
        pixels[k] = ivec2((gl_WorkGroupID.x * uint(kPixels) + uint(k)) * uint(ML_RASTER_FINISH_ROW) + gl_LocalInvocationID.x, gl_WorkGroupID.y);
        inside[k] = all(lessThan(pixels[k], ivec2(u_viewport.xy)));
        uint at = uint(pixels[k].y) * uint(u_viewport.x) + uint(pixels[k].x);
        keys[k] = ML_RASTER_STORE_EMPTY;
        triangles[k] = 0u;
        empty[k] = true;
        if (!inside[k]) continue;
#if ML_RASTER_ATOMIC64
        uint64_t stored = depthIds[at];
        uvec2 word = unpackUint2x32(stored ^ packUint2x32(uvec2(u_storeFlip)));
        empty[k] = stored == packUint2x32(uvec2(ML_RASTER_STORE_EMPTY));
        triangles[k] = word.x;
        keys[k] = word.y;
#else
        uint storedKey = depthIds[at], storedTriangle = depthIds[rasterPixelCount() + at];
        empty[k] = storedKey == ML_RASTER_STORE_EMPTY && storedTriangle == ML_RASTER_STORE_EMPTY;
        keys[k] = storedKey ^ u_storeFlip;
        triangles[k] = storedTriangle ^ u_storeFlip;
#endif
        // A word of another frame, or empty: nothing drawn here this frame.
        if (keys[k] >= ML_RASTER_STORE_EMPTY) keys[k] = ML_RASTER_STORE_EMPTY;
    }
    for (int k = 0; k < kPixels; ++k) {
        if (!inside[k]) continue;
        uint at = uint(pixels[k].y) * uint(u_viewport.x) + uint(pixels[k].x);
        bool drawn = keys[k] != ML_RASTER_STORE_EMPTY;
        if (!drawn && !empty[k]) {
#if ML_RASTER_ATOMIC64
            depthIds[at] = packUint2x32(uvec2(ML_RASTER_STORE_EMPTY));
#else
            depthIds[at] = ML_RASTER_STORE_EMPTY;
            depthIds[rasterPixelCount() + at] = ML_RASTER_STORE_EMPTY;
#endif
        }
        imageStore(u_ids, pixels[k], uvec4(drawn ? triangles[k] + 1u : 0u));
        imageStore(u_depth, pixels[k], vec4(rasterKeyDepth(keys[k])));  // the background's key gives depth 0
    }
#if ML_RASTER_VIEW_DEPTH_RANGE
    uint nearest = ~0u, farthest = 0u;
    for (int k = 0; k < kPixels; ++k) {
        float depth = rasterKeyDepth(keys[k]);
        if (!inside[k] || isBackgroundDepth(depth)) continue;
        uint bits = floatBitsToUint(viewDepthFromWindowDepth(depth));
        nearest = min(nearest, bits);
        farthest = max(farthest, bits);
    }
    addViewDepthRange(nearest, farthest);
#endif
}
