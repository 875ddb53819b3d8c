#version 450 core
// Raster floors (renderer/raster_floors.h): the id target cleared by compute, not by the ROPs.
#include "include/bindings.h"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_RASTER_FLOOR_IDS, r32ui) uniform writeonly uimage2D u_ids;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_ids)))) return;
    imageStore(u_ids, p, uvec4(0u));
}
