#version 450 core
// Exact light assignment, fully parallel. Serial per-light loops over clusters leave the GPU
// idle when lights are few or large and scale with the grid; here every (light, candidate
// cluster) pair gets its own invocation:
//   ML_EXACT_RANGES  (per light)      the light's block of candidate clusters and their number
//   [prefix sum of candidates per light, on the host side of the pipeline]
//   ML_EXACT_DISPATCH (one invocation) indirect dispatch arguments for the candidate passes
//   ML_EXACT_COUNT   (per candidate)  sphere against the cluster's AABB; count per cluster
//   [prefix sum of counts: list offsets]
//   ML_EXACT_FILL    (per candidate)  the same test; write the light into the cluster's list
// A candidate finds its light by binary search over the candidate offsets.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/cluster_grid.glsl"
#include "include/light_cluster_range.glsl"

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
layout(std430, binding = ML_SSBO_FILL_CURSORS) buffer FillCursors { uint cursors[]; };
// [0] dropped (capped only), [1] list entries, [2] candidates: totals written by the prefix sums;
// [4] running candidate sum and [5] its overflow flag (ranges pass; the scan's total wraps at 2^32)
layout(std430, binding = ML_SSBO_ASSIGN_STATS) buffer AssignStats { uint totals[8]; };
layout(std430, binding = ML_SSBO_LIGHT_RANGES) buffer LightRanges { uvec4 lightRanges[]; };  // lo.xyz, tiles across
layout(std430, binding = ML_SSBO_LIGHT_VIEW) buffer LightView { vec4 lightView[]; };        // centre, radius
layout(std430, binding = ML_SSBO_CANDIDATE_OFFSETS) buffer CandidateOffsets { uint candidateOffsets[]; };
layout(std430, binding = ML_SSBO_DISPATCH) writeonly buffer DispatchArgs { uvec4 dispatchArgs; };

uniform uint u_maxGroupsX;

#if defined(ML_EXACT_RANGES)
shared uint s_candidates;
shared uint s_wrapped;

// Adds to a 32-bit sum and flags a wrap: a million large lights can name more than 2^32
// (light, cluster) candidates, which the 32-bit prefix sum would silently wrap.
void addCandidates(uint count) {
    uint before = atomicAdd(totals[4], count);
    if (before > 0xFFFFFFFFu - count) atomicOr(totals[5], 1u);
}

void main() {
    if (gl_LocalInvocationID.x == 0u) {
        s_candidates = 0u;
        s_wrapped = 0u;
    }
    barrier();
    uint i = gl_GlobalInvocationID.x;
    uint candidates = 0u;
    if (i < lightCount()) {
        ClusterRange range;
        if (lightClusterRange(i, range)) {
            uvec3 n = range.hi - range.lo + 1u;
            candidates = n.x * n.y * n.z;
            lightRanges[i] = uvec4(range.lo, (n.y << 16) | n.x);
            lightView[i] = vec4(range.center, range.radius);
        }
        candidateOffsets[i] = candidates;
    }
    // One global atomic per workgroup.
    if (candidates > 0u && atomicAdd(s_candidates, candidates) > 0xFFFFFFFFu - candidates) s_wrapped = 1u;
    barrier();
    if (gl_LocalInvocationID.x == 0u) {
        if (s_wrapped != 0u) atomicOr(totals[5], 1u);
        else if (s_candidates > 0u) addCandidates(s_candidates);
    }
}
#elif defined(ML_EXACT_DISPATCH)
void main() {
    // At least one group (it finds nothing to do when there are no candidates); beyond the
    // device's limit in x, the rest goes to y.
    if (totals[5] != 0u) totals[2] = 0u;  // wrapped: test nothing; the host reports it
    uint groups = max((totals[2] + ML_WORKGROUP - 1u) / ML_WORKGROUP, 1u);
    uint x = min(groups, u_maxGroupsX);
    dispatchArgs = uvec4(x, (groups + x - 1u) / x, 1u, 0u);
}
#else
void main() {
    uint k = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * ML_WORKGROUP + gl_LocalInvocationID.x;
    if (k >= totals[2]) return;
    // The light whose candidates hold k: the last offset <= k (zero-candidate lights share
    // their successor's offset and are skipped by taking the last).
    uint lo = 0u, hi = lightCount();
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (candidateOffsets[mid] <= k) lo = mid + 1u;
        else hi = mid;
    }
    uint light = lo - 1u;
    uint local = k - candidateOffsets[light];
    uvec4 range = lightRanges[light];
    uint nx = range.w & 0xFFFFu, ny = range.w >> 16;
    uvec3 c = range.xyz + uvec3(local % nx, (local / nx) % ny, local / (nx * ny));
    uint cluster = clusterIndex(c);
    if (grid.options.z != 0u && clusterActive[cluster] == 0u) return;
    vec4 v = lightView[light];
    vec3 d = max(max(aabbs[cluster].minPoint.xyz - v.xyz, v.xyz - aabbs[cluster].maxPoint.xyz), vec3(0.0));
    if (dot(d, d) > v.w * v.w) return;
#if defined(ML_EXACT_COUNT)
    atomicAdd(clusterCounts[cluster], 1u);
#else
    uint slot = atomicAdd(cursors[cluster], 1u);
    lightIndices[clusterOffsets[cluster] + slot] = light;
#endif
}
#endif
