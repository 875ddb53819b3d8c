#version 450 core
// The view-space AABB of every cluster (mirrors ml::clusterBounds): the tile's four corner
// rays cut at the slice's near and far depth. The first and last slice reach the camera's
// near and far planes, and every box is widened by a relative epsilon, so a fragment's
// slice lookup can never land outside the box its lights were tested against.
// With fitted slicing every invocation slices the visible depth range itself (the same program,
// so the same bits) and the first stores it in the grid for the passes after: no pass of one
// invocation before this one.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#define ML_CLUSTER_GRID_WRITABLE
#include "include/cluster_grid.glsl"
#include "include/fitted_slicing.glsl"

layout(local_size_x = ML_CLUSTER_WORKGROUP) in;
struct ClusterAabb { vec4 minPoint; vec4 maxPoint; };
layout(std430, binding = ML_SSBO_CLUSTER_AABBS) writeonly buffer ClusterAabbs { ClusterAabb aabbs[]; };
uniform uint u_fitsSlicing;  // 1: fitted slicing, sliced here; 0: the grid's slicing as uploaded

void main() {
    vec4 slicing = u_fitsSlicing != 0u ? fittedSlicing() : grid.slicing;
    if (u_fitsSlicing != 0u && gl_GlobalInvocationID.x == 0u) grid.slicing = slicing;
    uint cluster = gl_GlobalInvocationID.x;
    if (cluster >= grid.dims.w) return;
    uint x = cluster % grid.dims.x;
    uint y = (cluster / grid.dims.x) % grid.dims.y;
    uint slice = cluster / (grid.dims.x * grid.dims.y);

    vec4 ndc = clusterTileNdc(uvec2(x, y));
    vec2 z = clusterDepthExtent(slice, slicing.xy);

    vec3 lo = vec3(1e30), hi = vec3(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
        vec2 c = vec2((corner & 1) != 0 ? ndc.z : ndc.x, (corner & 2) != 0 ? ndc.w : ndc.y);
        float d = (corner & 4) != 0 ? z.y : z.x;
        vec3 v = vec3(c.x * d / u_proj[0][0], c.y * d / u_proj[1][1], -d);
        lo = min(lo, v);
        hi = max(hi, v);
    }
    aabbs[cluster] = ClusterAabb(vec4(lo, 0.0), vec4(hi, 0.0));
}
