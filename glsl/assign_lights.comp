#version 450 core
// Light assignment, one invocation per light. Each light finds a conservative range of
// clusters from its view-space bounds (slices from its depth extent, tiles from the screen
// rectangle of its bounding box), then keeps the clusters whose AABB its sphere reaches.
//   ML_ASSIGN_COUNT:  count lights per cluster (exact lists, step 1)
//   ML_ASSIGN_FILL:   write each light into its clusters' lists at offsets from the prefix sum (step 3)
//   ML_ASSIGN_CAPPED: the seeds' baseline: append into fixed-size lists; overflow is counted
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/cluster_grid.glsl"

#ifndef ML_WORKGROUP
#define ML_WORKGROUP ML_ASSIGN_WORKGROUP
#endif
layout(local_size_x = ML_WORKGROUP) in;

struct ClusterAabb { vec4 minPoint; vec4 maxPoint; };
layout(std430, binding = ML_SSBO_CLUSTER_AABBS) readonly buffer ClusterAabbs { ClusterAabb aabbs[]; };
layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) readonly buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) writeonly buffer LightIndices { uint lightIndices[]; };
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) readonly buffer ClusterActive { uint clusterActive[]; };
layout(std430, binding = ML_SSBO_ASSIGN_STATS) buffer AssignStats { uint dropped; };  // references lost at the cap
#ifdef ML_ASSIGN_FILL
// Per-cluster write cursors, zeroed before the fill pass.
layout(std430, binding = ML_SSBO_FILL_CURSORS) buffer FillCursors { uint cursors[]; };
#endif

void visit(uint cluster, uint lightIndex) {
#if defined(ML_ASSIGN_COUNT)
    atomicAdd(clusterCounts[cluster], 1u);
#elif defined(ML_ASSIGN_FILL)
    uint slot = atomicAdd(cursors[cluster], 1u);
    lightIndices[clusterOffsets[cluster] + slot] = lightIndex;
#else
    uint cap = grid.options.y;
    uint slot = atomicAdd(clusterCounts[cluster], 1u);
    if (slot < cap) lightIndices[cluster * cap + slot] = lightIndex;
    else atomicAdd(dropped, 1u);
#endif
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= lightCount()) return;
    vec4 pr = lights[i].positionRadius;
    float r = pr.w;
    if (!(r > 0.0)) return;
    vec3 c = (u_view * vec4(pr.xyz, 1.0)).xyz;
    float zMin = -c.z - r, zMax = -c.z + r;

    // The first and last slices reach the camera's planes (see cluster_bounds.comp).
    float gridNear = min(grid.tile.z, grid.slicing.x) * (1.0 - 1e-4);
    float gridFar = max(grid.tile.w, grid.slicing.y) * (1.0 + 1e-4);
    if (zMax < gridNear || zMin > gridFar) return;
    uint s0 = sliceForDepth(max(zMin, 1e-7));
    uint s1 = sliceForDepth(zMax);

    uvec2 t0 = uvec2(0u), t1 = grid.dims.xy - 1u;
    if (zMin > gridNear * 1e-3) {
        // Entirely in front of the camera: project the corners of the sphere's bounding box.
        vec2 lo = vec2(1e30), hi = vec2(-1e30);
        for (int k = 0; k < 8; ++k) {
            vec3 v = c + r * vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
            vec2 ndc = vec2(u_proj[0][0] * v.x, u_proj[1][1] * v.y) / -v.z;
            lo = min(lo, ndc);
            hi = max(hi, ndc);
        }
        if (any(lessThan(hi, vec2(-1.0))) || any(greaterThan(lo, vec2(1.0)))) return;
        // A hundredth of a pixel of slack: rounding must not drop a tile the sphere touches.
        vec2 pxLo = (clamp(lo, -1.0, 1.0) * 0.5 + 0.5) * u_viewport.xy - 0.01;
        vec2 pxHi = (clamp(hi, -1.0, 1.0) * 0.5 + 0.5) * u_viewport.xy + 0.01;
        t0 = tileForPixel(pxLo);
        t1 = tileForPixel(pxHi);
    }

    float r2 = r * r;
    bool activeOnly = grid.options.z != 0u;
    for (uint s = s0; s <= s1; ++s) {
        for (uint y = t0.y; y <= t1.y; ++y) {
            for (uint x = t0.x; x <= t1.x; ++x) {
                uint cluster = clusterIndex(uvec3(x, y, s));
                if (activeOnly && clusterActive[cluster] == 0u) continue;
                vec3 d = max(max(aabbs[cluster].minPoint.xyz - c, c - aabbs[cluster].maxPoint.xyz), vec3(0.0));
                if (dot(d, d) <= r2) visit(cluster, i);
            }
        }
    }
}
