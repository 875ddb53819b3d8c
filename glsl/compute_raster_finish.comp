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

layout(local_size_x = ML_RASTER_FINISH_ROW) in;  // a row strip: the store is row-major
layout(binding = ML_IMG_VISIBILITY_IDS, r32ui) uniform writeonly uimage2D u_ids;
layout(binding = ML_IMG_RASTER_DEPTH, r32f) uniform writeonly image2D u_depth;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    uint at = uint(p.y) * uint(u_viewport.x) + uint(p.x);
#if ML_RASTER_ATOMIC64
    uvec2 word = unpackUint2x32(depthIds[at]);
    depthIds[at] = ~0ul;
    uint triangle = word.x, key = word.y;
#else
    uint key = depthIds[at], triangle = depthIds[rasterPixelCount() + at];
    depthIds[at] = ~0u;
    depthIds[rasterPixelCount() + at] = ~0u;
#endif
    bool drawn = key != ~0u;
    imageStore(u_ids, p, uvec4(drawn ? triangle + 1u : 0u));
    imageStore(u_depth, p, vec4(rasterKeyDepth(key)));  // the background's key gives depth 0
}
