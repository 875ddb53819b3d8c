#version 450 core
// The view-space AABB of every cluster (mirrors ml::clusterBounds): the tile's four corner
// rays cut at the slice's near and far depth. The first and last slice reach the camera's
// near and far planes, and every box is widened by a relative epsilon, so a fragment's
// slice lookup can never land outside the box its lights were tested against.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"

layout(local_size_x = ML_CLUSTER_WORKGROUP) in;
struct ClusterAabb { vec4 minPoint; vec4 maxPoint; };
layout(std430, binding = ML_SSBO_CLUSTER_AABBS) writeonly buffer ClusterAabbs { ClusterAabb aabbs[]; };

void main() {
    uint cluster = gl_GlobalInvocationID.x;
    if (cluster >= grid.dims.w) return;
    uint x = cluster % grid.dims.x;
    uint y = (cluster / grid.dims.x) % grid.dims.y;
    uint slice = cluster / (grid.dims.x * grid.dims.y);

    vec2 size = u_viewport.xy;
    vec2 p0 = min(vec2(x, y) * grid.tile.x, size);
    vec2 p1 = min(vec2(x + 1u, y + 1u) * grid.tile.x, size);
    float z0 = slice == 0u ? min(grid.tile.z, grid.slicing.x) : sliceBoundary(slice);
    float z1 = slice + 1u == grid.dims.z ? max(grid.tile.w, grid.slicing.y) : sliceBoundary(slice + 1u);
    z0 *= 1.0 - 1e-4;
    z1 *= 1.0 + 1e-4;

    vec3 lo = vec3(1e30), hi = vec3(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
        vec2 px = vec2((corner & 1) != 0 ? p1.x : p0.x, (corner & 2) != 0 ? p1.y : p0.y);
        float z = (corner & 4) != 0 ? z1 : z0;
        vec2 ndc = px / size * 2.0 - 1.0;
        vec3 v = vec3(ndc.x * z / u_proj[0][0], ndc.y * z / u_proj[1][1], -z);
        lo = min(lo, v);
        hi = max(hi, v);
    }
    aabbs[cluster] = ClusterAabb(vec4(lo, 0.0), vec4(hi, 0.0));
}
