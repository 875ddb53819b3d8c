#version 450 core
// Capped light assignment, the seeds' baseline: one invocation per light walks its block of
// clusters (include/light_cluster_range.glsl), tests each cluster against it (--cull, and a spot's cone),
// and appends itself to the cluster's fixed-size list; references past the cap are counted.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/cluster_grid.glsl"
#include "include/spot_cone.glsl"
#include "include/light_cluster_range.glsl"
#include "include/light_cluster_test.glsl"

#ifndef ML_WORKGROUP
#define ML_WORKGROUP ML_ASSIGN_WORKGROUP
#endif
layout(local_size_x = ML_WORKGROUP) in;

layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) writeonly buffer LightIndices { uint lightIndices[]; };
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) readonly buffer ClusterActive { uint clusterActive[]; };
layout(std430, binding = ML_SSBO_ASSIGN_STATS) buffer AssignStats { uint dropped; };  // references lost at the cap


void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= lightCount()) return;
    ClusterRange range;
    if (!lightClusterRange(i, range)) return;
    bool activeOnly = grid.options.z != 0u;
    uint cap = grid.options.y;
    for (uint s = range.lo.z; s <= range.hi.z; ++s) {
        for (uint y = range.lo.y; y <= range.hi.y; ++y) {
            for (uint x = range.lo.x; x <= range.hi.x; ++x) {
                uint cluster = clusterIndex(uvec3(x, y, s));
                if (activeOnly && clusterActive[cluster] == 0u) continue;
                if (!lightReachesCluster(cluster, uvec3(x, y, s), i, range.center, range.radius)) continue;
                uint slot = atomicAdd(clusterCounts[cluster], 1u);
                if (slot < cap) lightIndices[cluster * cap + slot] = i;
                else atomicAdd(dropped, 1u);
            }
        }
    }
}
