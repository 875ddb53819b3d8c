#version 450 core
// The compute raster's binning (renderer/passes/compute_raster.h): a workgroup per large
// triangle lists (triangle, tile) for every screen tile its pixel bounds overlap, for the tile
// pass, and for every triangle of the clipped list (ML_RASTER_CLIPPED_PAIR marks them). A
// triangle whose tiles do not fit the list goes to the hardware's list instead.
#include "include/bindings.h"

layout(local_size_x = 64) in;

layout(std430, binding = ML_SSBO_RASTER_WORK) coherent buffer RasterWork { uint rasterWork[]; };
layout(std430, binding = ML_SSBO_RASTER_LARGE) readonly buffer RasterLarge { uvec4 largeTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_PAIRS) writeonly buffer RasterPairs { uvec2 pairs[]; };
layout(std430, binding = ML_SSBO_RASTER_HARDWARE) writeonly buffer RasterHardware { uint hardwareTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_CLIPPED) readonly buffer RasterClipped { uvec4 clippedTriangles[]; };

uniform uint u_largeCapacity;
uniform uint u_pairCapacity;

shared uint s_first;

void main() {
    uint largeCount = min(rasterWork[ML_RASTER_WORK_LARGE_COUNT], u_largeCapacity);
    uint count = largeCount + min(rasterWork[ML_RASTER_WORK_CLIPPED_COUNT], u_largeCapacity);
    for (uint item = gl_WorkGroupID.x; item < count; item += gl_NumWorkGroups.x) {
        bool clipped = item >= largeCount;
        uint large = clipped ? (item - largeCount) | ML_RASTER_CLIPPED_PAIR : item;
        // Tile bounds in .zw, the triangle in .y (large); bounds in .xy, the triangle in the
        // record before's .w (clipped).
        uvec4 record = clipped ? clippedTriangles[5u * (item - largeCount) + 4u].zwxy : largeTriangles[3u * large + 2u];
        if (clipped) record.y = clippedTriangles[5u * (item - largeCount) + 3u].w;
        uvec2 lo = uvec2(record.z & 0xffffu, record.z >> 16), hi = uvec2(record.w & 0xffffu, record.w >> 16);
        uvec2 size = hi - lo + 1u;
        uint tiles = size.x * size.y;
        if (gl_LocalInvocationIndex == 0u) {
            uint first = atomicAdd(rasterWork[ML_RASTER_WORK_PAIR_COUNT], tiles);
            if (first + tiles > u_pairCapacity || first + tiles < first) {
                uint at = atomicAdd(rasterWork[ML_RASTER_WORK_HARDWARE_DRAW], 3u) / 3u;
                hardwareTriangles[at] = record.y;
                first = 0xffffffffu;
            } else {
                atomicMax(rasterWork[ML_RASTER_WORK_TILE_DISPATCH], min(first + tiles, 65535u));
            }
            s_first = first;
        }
        barrier();
        uint first = s_first;
        barrier();
        if (first == 0xffffffffu) continue;
        for (uint i = gl_LocalInvocationIndex; i < tiles; i += gl_WorkGroupSize.x) {
            uvec2 tile = lo + uvec2(i % size.x, i / size.x);
            pairs[first + i] = uvec2(large, tile.x | (tile.y << 16));
        }
    }
}
