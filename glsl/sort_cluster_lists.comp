#version 450 core
// Sorts every light list by light index, one workgroup per list.
// Why: the fill passes write lists through atomics, so their order changes from run to run,
// and a float sum taken in a different order differs in its last bits. Sorted lists make the
// shaded frame a pure function of the flags and the seed (byte-identical runs, issue 7).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"

layout(local_size_x = ML_SORT_WORKGROUP) in;

layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) readonly buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) readonly buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) coherent buffer LightIndices { uint lightIndices[]; };

// Lists to sort: one per cluster, or one per (cluster, normal bin) with --normal-cones.
uniform uint u_listCount;

shared uint s_list[ML_SORT_SHARED_CAPACITY];

// A short list (at most one entry per thread): rank sort. A light appears at most once per
// list, so an entry's place is the number of entries smaller than it: one barrier, n compares
// per thread.
void rankSort(uint first, uint n) {
    uint i = gl_LocalInvocationID.x;
    if (i < n) s_list[i] = lightIndices[first + i];
    barrier();
    if (i < n) {
        uint x = s_list[i], rank = 0u;
        for (uint m = 0u; m < n; ++m) rank += uint(s_list[m] < x);
        lightIndices[first + rank] = x;
    }
}

// Longer lists: a bitonic sort in its "flip" form, O(n log^2 n), in shared memory up to
// ML_SORT_SHARED_CAPACITY entries and in place in the buffer beyond (a hot cluster). Every
// compare-exchange puts the smaller value first, so a list of any length behaves as if padded
// with +infinity to a power of two, and pairs whose partner lies at or past n are skipped.
// Pair p of a step has its lower index a with bit j clear; the first step of each stage k
// pairs a with its mirror in the block (a ^ (k - 1)), the later ones with a + j.
#define BITONIC_SORT(ELEMENT, SYNC)                                                         \
    {                                                                                       \
        uint padded = 1u;                                                                   \
        while (padded < n) padded <<= 1;                                                    \
        for (uint k = 2u; k <= padded; k <<= 1) {                                           \
            for (uint j = k >> 1; j > 0u; j >>= 1) {                                        \
                for (uint p = gl_LocalInvocationID.x; p < padded / 2u; p += ML_SORT_WORKGROUP) { \
                    uint a = (p / j) * 2u * j + (p % j);                                    \
                    uint b = (j == (k >> 1)) ? (a ^ (k - 1u)) : (a + j);                    \
                    if (b >= n) continue;                                                   \
                    uint x = ELEMENT(a), y = ELEMENT(b);                                    \
                    if (x > y) {                                                            \
                        ELEMENT(a) = y;                                                     \
                        ELEMENT(b) = x;                                                     \
                    }                                                                       \
                }                                                                           \
                SYNC;                                                                       \
            }                                                                               \
        }                                                                                   \
    }

#define SHARED_ELEMENT(i) s_list[i]
#define BUFFER_ELEMENT(i) lightIndices[first + (i)]

void bitonicSortShared(uint first, uint n) {
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) s_list[i] = lightIndices[first + i];
    barrier();
    BITONIC_SORT(SHARED_ELEMENT, barrier())
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) lightIndices[first + i] = s_list[i];
}

void bitonicSortBuffer(uint first, uint n) {
    BITONIC_SORT(BUFFER_ELEMENT, memoryBarrierBuffer(); barrier())
}

void main() {
    uint list = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (list >= u_listCount) return;
    // Capped lists live at cluster * cap and keep at most cap entries.
    uint cap = grid.options.y;
    uint n = clusterCounts[list];
    uint first = cap > 0u ? list * cap : clusterOffsets[list];
    if (cap > 0u) n = min(n, cap);
    if (n < 2u) return;
    if (n <= ML_SORT_WORKGROUP) rankSort(first, n);
    else if (n <= ML_SORT_SHARED_CAPACITY) bitonicSortShared(first, n);
    else bitonicSortBuffer(first, n);
}
