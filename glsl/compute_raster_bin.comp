#version 450 core
// The compute raster's binning (renderer/passes/compute_raster.h): a workgroup per large
// triangle lists (triangle, tile) for every screen tile its pixel bounds overlap, for the tile
// pass. A triangle whose tiles do not fit the list goes to the hardware's list instead.
#include "include/bindings.h"

layout(local_size_x = 64) in;

layout(std430, binding = ML_SSBO_RASTER_WORK) coherent buffer RasterWork { uint rasterWork[]; };
layout(std430, binding = ML_SSBO_RASTER_LARGE) readonly buffer RasterLarge { uvec4 largeTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_PAIRS) writeonly buffer RasterPairs { uvec2 pairs[]; };
layout(std430, binding = ML_SSBO_RASTER_HARDWARE) writeonly buffer RasterHardware { uint hardwareTriangles[]; };

uniform uint u_largeCapacity;
uniform uint u_pairCapacity;

shared uint s_first;

void main() {
    uint count = min(rasterWork[ML_RASTER_WORK_LARGE_COUNT], u_largeCapacity);
    for (uint large = gl_WorkGroupID.x; large < count; large += gl_NumWorkGroups.x) {
        uvec4 record = largeTriangles[3u * large + 2u];
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
