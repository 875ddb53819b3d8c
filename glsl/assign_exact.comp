#version 450 core
// Exact light assignment. Per light (--assign exact, the default), fully parallel: serial
// per-light loops over clusters leave the GPU idle when lights are few or large and scale with
// the grid, so every (light, candidate cluster) pair gets its own invocation:
//   ML_EXACT_CLEAR   (per list)       every list's count and offset and the totals to 0
//   ML_EXACT_RANGES  (per light)      the light's block of candidate clusters and their number
//   [prefix sum of candidates per light, on the host side of the pipeline]
//   ML_EXACT_DISPATCH (one invocation) indirect dispatch arguments for the candidate passes, and
//                                     the candidates for the CPU, which sizes the lists by them
//   ML_EXACT_COUNT   (per candidate)  the --cull test and a spot's cone (include/light_cluster_test.glsl); count per list,
//                                     into the offsets' buffer
//   [prefix sum of the counts in place: list offsets]
//   ML_EXACT_FILL    (per candidate)  the same test; write the light into the list, counting again
//                                     into the counts' buffer, which leaves each list's length there
// The clear is one dispatch, and no buffer is cleared or copied between the passes: on an H200 a
// glClearNamedBufferSubData or a buffer copy between two passes cost 5-7 us, as much as a pass's
// own work at a thousand lights (docs/bench/nvidia-h200/fewer-steps/).
// A workgroup takes ML_ASSIGN_CANDIDATE_RUN rounds of consecutive candidates, one an invocation;
// an invocation finds its first candidate's light by binary search over the candidate offsets,
// and each later one's by stepping forward from there.
// Per cluster (--assign per-cluster, seed 003): after ML_EXACT_RANGES, one invocation per
// cluster loops over every light (a workgroup stages them through shared memory), keeping those
// whose block holds the cluster and that pass the same test:
//   ML_PER_CLUSTER_COUNT, [prefix sum], ML_PER_CLUSTER_FILL (lists come out in light order)
// Both give the same lists, as sets. With --normal-cones (ML_NORMAL_CONES) a list belongs to a
// (cluster, normal bin) key: a light that passes the cull test goes into each bin the
// cluster's visible samples occupy whose samples' normal cone it may light (include/normal_bins.glsl).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/cluster_grid.glsl"
#include "include/spot_cone.glsl"
#include "include/light_cluster_range.glsl"
#include "include/light_cluster_test.glsl"
#include "include/normal_bins.glsl"

#ifndef ML_WORKGROUP
#define ML_WORKGROUP ML_ASSIGN_WORKGROUP
#endif
// A scratch build may set the round count (docs/bench/nvidia-h100/assign-runs measured 1 to 16).
#ifndef ML_CANDIDATE_RUN
#define ML_CANDIDATE_RUN ML_ASSIGN_CANDIDATE_RUN
#endif
layout(local_size_x = ML_WORKGROUP) in;

layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) writeonly buffer LightIndices { uint lightIndices[]; };
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) readonly buffer ClusterActive { uint clusterActive[]; };
// [0] dropped (capped only), [1] list entries, [2] candidates: totals written by the prefix sums;
// --normal-cones: [3] pairs that pass the cull test in clusters holding a visible sample, [4] of
// those, pairs kept in at least one normal bin
// [5] running candidate sum and [6] its overflow flag (ranges pass; the scan's total wraps at 2^32)
layout(std430, binding = ML_SSBO_ASSIGN_STATS) buffer AssignStats { uint totals[8]; };
layout(std430, binding = ML_SSBO_LIGHT_RANGES) buffer LightRanges { uvec4 lightRanges[]; };  // lo.xyz, tiles across
layout(std430, binding = ML_SSBO_LIGHT_VIEW) buffer LightView { vec4 lightView[]; };        // bounding sphere: centre, radius
layout(std430, binding = ML_SSBO_CANDIDATE_OFFSETS) buffer CandidateOffsets { uint candidateOffsets[]; };
layout(std430, binding = ML_SSBO_DISPATCH) writeonly buffer DispatchArgs { uvec4 dispatchArgs; };
// [0] candidates, [1] their wrap flag: AssignStats [5] and [6] where the CPU reads them behind a fence.
layout(std430, binding = ML_SSBO_ASSIGN_CANDIDATES) writeonly buffer AssignCandidates { uint candidatesForHost[2]; };
layout(std430, binding = ML_SSBO_NORMAL_BIN_MASKS) readonly buffer NormalBinMasks { uint normalBinMasks[]; };
layout(std430, binding = ML_SSBO_NORMAL_CONES) readonly buffer NormalCones { ivec4 normalCones[]; };

uniform uint u_maxGroupsX;
uniform uint u_lists;  // ML_EXACT_CLEAR: the lists (clusters, or clusters x normal bins)

#if defined(ML_EXACT_CLEAR)
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < u_lists) {
        clusterCounts[i] = 0u;
        clusterOffsets[i] = 0u;
    }
    if (i < 8u) totals[i] = 0u;
}
#elif defined(ML_EXACT_RANGES)
shared uint s_candidates;
shared uint s_wrapped;

// Adds to a 32-bit sum and flags a wrap: a million large lights can name more than 2^32
// (light, cluster) candidates, which the 32-bit prefix sum would silently wrap.
void addCandidates(uint count) {
    uint before = atomicAdd(totals[5], count);
    if (before > 0xFFFFFFFFu - count) atomicOr(totals[6], 1u);
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
        if (s_wrapped != 0u) atomicOr(totals[6], 1u);
        else if (s_candidates > 0u) addCandidates(s_candidates);
    }
}
#elif defined(ML_EXACT_DISPATCH)
void main() {
    // At least one group (it finds nothing to do when there are no candidates); beyond the
    // device's limit in x, the rest goes to y.
    candidatesForHost[0] = totals[5];
    candidatesForHost[1] = totals[6];
    if (totals[6] != 0u) totals[2] = 0u;  // wrapped: test nothing; the host reports it
    const uint span = ML_WORKGROUP * ML_CANDIDATE_RUN;  // candidates a workgroup takes
    uint groups = max(totals[2] / span + uint(totals[2] % span != 0u), 1u);
    uint x = min(groups, u_maxGroupsX);
    dispatchArgs = uvec4(x, (groups + x - 1u) / x, 1u, 0u);
}
#else
#if defined(ML_EXACT_COUNT) || defined(ML_PER_CLUSTER_COUNT)
#define ML_COUNTING 1
#endif

#if defined(ML_NORMAL_CONES)
// Pairs kept and removed by the normal cones, summed per workgroup before one global atomic.
shared uint s_pairsTested, s_pairsKept;
#endif

// One list entry: counted (where the scan then makes the offsets), or written at the list's next
// slot, which counts it again where the lists' lengths are read.
void addToList(uint key, uint light) {
#if defined(ML_COUNTING)
    atomicAdd(clusterOffsets[key], 1u);
#else
    uint slot = atomicAdd(clusterCounts[key], 1u);
    lightIndices[clusterOffsets[key] + slot] = light;
#endif
}

// A (light, cluster) pair that passed the cull test: into the cluster's list, or with normal
// cones into the list of every occupied normal bin the light may face.
void addPair(uint cluster, uint light) {
#if defined(ML_NORMAL_CONES)
    // The light itself (a spot's apex), not the centre of its bounding sphere.
    vec3 position = (u_view * vec4(lights[light].positionRadius.xyz, 1.0)).xyz;
    uint mask = normalBinMasks[cluster];
    bool kept = false;
    while (mask != 0u) {
        uint bin = uint(findLSB(mask));
        mask &= mask - 1u;
        uint key = cluster * ML_NORMAL_BINS + bin;
        if (!lightMayFaceNormalCone(normalConeOfList(normalCones[key]), aabbs[cluster].minPoint.xyz, aabbs[cluster].maxPoint.xyz, position))
            continue;
        addToList(key, light);
        kept = true;
    }
#if defined(ML_COUNTING)
    if (normalBinMasks[cluster] != 0u) {
        atomicAdd(s_pairsTested, 1u);
        if (kept) atomicAdd(s_pairsKept, 1u);
    }
#endif
#else
    addToList(cluster, light);
#endif
}

// Clusters the assignment skips: --active-only clusters without a visible sample; with normal
// cones, clusters whose samples occupy no bin (the same ones).
bool clusterSkipped(uint cluster) {
#if defined(ML_NORMAL_CONES)
    return normalBinMasks[cluster] == 0u;
#else
    return grid.options.z != 0u && clusterActive[cluster] == 0u;
#endif
}

#if defined(ML_PER_CLUSTER_COUNT) || defined(ML_PER_CLUSTER_FILL)
shared vec4 s_view[ML_WORKGROUP];   // centre, radius
shared uvec4 s_block[ML_WORKGROUP]; // first tile x, y, slice; w: tiles across | tiles down << 16 (0: reaches none)
shared uint s_slices[ML_WORKGROUP];

void assignPairs() {
    uint cluster = gl_GlobalInvocationID.x;
    bool valid = cluster < grid.dims.w && !clusterSkipped(cluster);
    uvec3 c = uvec3(cluster % grid.dims.x, (cluster / grid.dims.x) % grid.dims.y, cluster / (grid.dims.x * grid.dims.y));
    uint count = lightCount();
    for (uint first = 0u; first < count; first += ML_WORKGROUP) {
        uint i = first + gl_LocalInvocationID.x;
        // candidateOffsets holds each light's candidate count here (no prefix sum in this mode).
        uint candidates = i < count ? candidateOffsets[i] : 0u;
        s_block[gl_LocalInvocationID.x] = candidates > 0u ? lightRanges[i] : uvec4(0u);
        s_view[gl_LocalInvocationID.x] = candidates > 0u ? lightView[i] : vec4(0.0);
        if (candidates > 0u) {
            uvec4 b = lightRanges[i];
            s_slices[gl_LocalInvocationID.x] = candidates / ((b.w & 0xFFFFu) * (b.w >> 16));
        }
        barrier();
        uint batch = min(uint(ML_WORKGROUP), count - first);
        for (uint k = 0u; valid && k < batch; ++k) {
            uvec4 b = s_block[k];
            if (b.w == 0u) continue;
            uvec3 size = uvec3(b.w & 0xFFFFu, b.w >> 16, s_slices[k]);
            if (any(lessThan(c, b.xyz)) || any(greaterThanEqual(c, b.xyz + size))) continue;
            vec4 v = s_view[k];
            if (lightReachesCluster(cluster, c, first + k, v.xyz, v.w)) addPair(cluster, first + k);
        }
        barrier();
    }
}
#else
// The light whose candidates hold candidate k: the last light in [lo, hi) whose candidates start
// at or before k, given that lo's do (candidateOffsets[lo] <= k). Lights without candidates
// share their successor's offset and are skipped by taking the last.
uint lastLightStartingBy(uint k, uint lo, uint hi) {
    ++lo;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (candidateOffsets[mid] <= k) lo = mid + 1u;
        else hi = mid;
    }
    return lo - 1u;
}

// The same, forward from a light at or before it: an invocation's next candidate lies
// ML_WORKGROUP further on, in the same light's block or a few lights later, so the bracket
// grows from `from` by doubling steps (one read when the light stays) before the binary search.
uint lightHoldingFrom(uint k, uint from) {
    uint count = lightCount();
    uint lo = from, hi = count, step = 1u;
    while (step < count - lo) {
        uint probe = lo + step;
        if (candidateOffsets[probe] > k) {
            hi = probe;
            break;
        }
        lo = probe;
        step <<= 1;
    }
    return lastLightStartingBy(k, lo, hi);
}

void assignPairs() {
    // A workgroup takes ML_WORKGROUP x ML_CANDIDATE_RUN consecutive candidates in
    // ML_CANDIDATE_RUN steps; in each step neighbouring invocations take neighbouring candidates,
    // so they test neighbouring clusters of a light and their atomics share cache lines.
    const uint span = ML_WORKGROUP * ML_CANDIDATE_RUN;
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint total = totals[2];
    if (total == 0u || group > (total - 1u) / span || gl_LocalInvocationID.x >= total - group * span) return;
    uint k = group * span + gl_LocalInvocationID.x;
    uint light = lastLightStartingBy(k, 0u, lightCount());
    for (uint step = 0u;; ++step) {
        uint local = k - candidateOffsets[light];
        uvec4 range = lightRanges[light];
        uint nx = range.w & 0xFFFFu, ny = range.w >> 16;
        uvec3 c = range.xyz + uvec3(local % nx, (local / nx) % ny, local / (nx * ny));
        uint cluster = clusterIndex(c);
        if (!clusterSkipped(cluster)) {
            vec4 v = lightView[light];
            if (lightReachesCluster(cluster, c, light, v.xyz, v.w)) addPair(cluster, light);
        }
        if (step + 1u == ML_CANDIDATE_RUN || total - k <= ML_WORKGROUP) break;
        k += ML_WORKGROUP;
        light = lightHoldingFrom(k, light);
    }
}
#endif

void main() {
#if defined(ML_NORMAL_CONES)
    if (gl_LocalInvocationIndex == 0u) {
        s_pairsTested = 0u;
        s_pairsKept = 0u;
    }
    barrier();
    assignPairs();
#if defined(ML_COUNTING)
    barrier();
    if (gl_LocalInvocationIndex == 0u && s_pairsTested > 0u) {
        atomicAdd(totals[3], s_pairsTested);
        atomicAdd(totals[4], s_pairsKept);
    }
#endif
#else
    assignPairs();
#endif
}
#endif
