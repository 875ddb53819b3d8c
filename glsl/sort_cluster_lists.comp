#version 450 core
// Sorts every light list by light index.
// Why: the fill passes write lists through atomics, so their order changes from run to run,
// and a float sum taken in a different order differs in its last bits. Sorted lists make the
// shaded frame a pure function of the flags and the seed (byte-identical runs, issue 7).
//
// Three programs from this file. ML_SORT_CLASSIFY (one invocation per list) appends every list of
// two or more entries to the short or the long work list, and its last workgroup to finish turns
// their lengths into indirect dispatches: most lists hold 0 or 1 lights (every empty normal bin
// of --normal-cones, the empty space of a frame), and a workgroup launched per list only to
// return cost 1.5 s a frame on llvmpipe at 160x90 with normal cones, 15 s at 16x4096.
// Then one workgroup per listed list. ML_SORT_LONG selects the long-list program; without it, the
// short one (lengths and sizes in include/bindings.h). Short lists: a rank sort from shared
// memory, or a bitonic network there. Long lists: a bitonic network in shared memory, or for a
// list longer than that, one per chunk and a merge by rank through a scratch buffer
// (docs/architecture.md, "Light-list order", has the costs).
#include "include/bindings.h"

#if defined(ML_SORT_CLASSIFY)
#define ML_SORT_WORKGROUP 64
#define ML_SORT_CAPACITY 1
#elif defined(ML_SORT_LONG)
#define ML_SORT_WORKGROUP ML_SORT_LONG_WORKGROUP
#define ML_SORT_CAPACITY ML_SORT_SHARED_CAPACITY
#else
#define ML_SORT_WORKGROUP ML_SORT_SHORT_WORKGROUP
#define ML_SORT_CAPACITY ML_SORT_SHORT_MAX
#endif
layout(local_size_x = ML_SORT_WORKGROUP) in;

layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) readonly buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) readonly buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) coherent buffer LightIndices { uint lightIndices[]; };
// Long lists past shared memory: each entry at its merged place, at the list's own offset.
layout(std430, binding = ML_SSBO_SORT_SCRATCH) coherent buffer SortScratch { uint sortScratch[]; };

// The work lists: the two indirect dispatches (short at word 0, long at word 3), the two lengths
// as the classification counts them and the classifying workgroups done (left at 0 for the next
// run by the last), the two lengths for the sorting programs, then the short lists' indices from
// word ML_SORT_WORK_LISTS and the long ones' u_listCount after.
layout(std430, binding = ML_SSBO_SORT_WORK) coherent buffer SortWork { uint sortWork[]; };
#define ML_SORT_SHORT_COUNTED 6
#define ML_SORT_LONG_COUNTED 7
#define ML_SORT_GROUPS_DONE 8
#define ML_SORT_SHORT_LENGTH 9
#define ML_SORT_LONG_LENGTH 10
#define ML_SORT_WORK_LISTS 11

// Lists: one per cluster, or one per (cluster, normal bin) with --normal-cones.
uniform uint u_listCount;
uniform uint u_listCap;     // capped lists: entries a list holds; 0 for exact lists
uniform uint u_maxGroupsX;  // ML_SORT_CLASSIFY: the device's limit on workgroups in x

// Where a list starts and how long it is. Capped lists live at list * cap and keep at most cap
// entries.
uvec2 listRange(uint list) {
    uint n = clusterCounts[list];
    if (u_listCap > 0u) return uvec2(list * u_listCap, min(n, u_listCap));
    return uvec2(clusterOffsets[list], n);
}

shared uint s_list[ML_SORT_CAPACITY];

// Rank sort: a light appears at most once per list, so an entry's place is the number of
// entries smaller than it. One barrier and n^2 / ML_SORT_WORKGROUP compares from shared
// memory, whose reads all threads share: the cheapest for short lists, quadratic beyond.
void rankSort(uint first, uint n) {
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) s_list[i] = lightIndices[first + i];
    barrier();
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) {
        uint x = s_list[i], rank = 0u;
        for (uint m = 0u; m < n; ++m) rank += uint(s_list[m] < x);
        lightIndices[first + rank] = x;
    }
}

uint nextPowerOfTwo(uint n) { return n <= 1u ? 1u : 1u << (findMSB(n - 1u) + 1); }

// Bitonic sort in shared memory: n log^2 n / 2 compare-exchanges, a barrier per step. The list
// is padded to a power of two with 0xFFFFFFFF, which sorts last and is never written back.
void bitonicSortShared(uint first, uint n) {
    uint padded = nextPowerOfTwo(n);
    for (uint i = gl_LocalInvocationID.x; i < padded; i += ML_SORT_WORKGROUP)
        s_list[i] = i < n ? lightIndices[first + i] : 0xFFFFFFFFu;
    barrier();
    for (uint k = 2u; k <= padded; k <<= 1) {
        for (uint j = k >> 1; j > 0u; j >>= 1) {
            for (uint p = gl_LocalInvocationID.x; p < padded / 2u; p += ML_SORT_WORKGROUP) {
                // Pair p's lower index: p with a zero inserted at bit j (j is a power of two,
                // and a division by a variable costs tens of instructions).
                uint a = ((p & ~(j - 1u)) << 1) | (p & (j - 1u));
                uint b = a + j;
                uint x = s_list[a], y = s_list[b];
                bool ascending = (a & k) == 0u;
                if ((x > y) == ascending) {
                    s_list[a] = y;
                    s_list[b] = x;
                }
            }
            barrier();
        }
    }
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) lightIndices[first + i] = s_list[i];
}

// How many entries of a sorted chunk are smaller than x: a binary search.
uint smallerIn(uint chunkFirst, uint chunkSize, uint x) {
    uint lo = 0u, hi = chunkSize;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (lightIndices[chunkFirst + mid] < x) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

// A list too long for shared memory (a hot cluster): its chunks of ML_SORT_CAPACITY sorted in
// shared memory one after another, then every entry written to its place in the whole list,
// its place in its own chunk plus the entries smaller than it in each other chunk (a light
// appears once per list, so no two entries share a place), through the scratch buffer and back.
// A bitonic network in the buffer took 1.0-1.2 ms on the gas station's lists of up to 14,650
// lights at a million (H100), one workgroup and a barrier for each of its 105 steps.
uint chunkLength(uint n, uint chunk) { return min(uint(ML_SORT_CAPACITY), n - chunk * ML_SORT_CAPACITY); }

void chunkSortAndMerge(uint first, uint n) {
    uint chunks = (n + ML_SORT_CAPACITY - 1u) / ML_SORT_CAPACITY;
    for (uint c = 0u; c < chunks; ++c) {
        bitonicSortShared(first + c * ML_SORT_CAPACITY, chunkLength(n, c));
        barrier();  // the next chunk refills s_list
    }
    memoryBarrierBuffer();
    barrier();
    for (uint e = gl_LocalInvocationID.x; e < n; e += ML_SORT_WORKGROUP) {
        uint own = e / ML_SORT_CAPACITY;
        uint x = lightIndices[first + e];
        uint place = e - own * ML_SORT_CAPACITY;
        for (uint c = 0u; c < chunks; ++c) {
            if (c != own) place += smallerIn(first + c * ML_SORT_CAPACITY, chunkLength(n, c), x);
        }
        sortScratch[first + place] = x;
    }
    memoryBarrierBuffer();
    barrier();
    for (uint e = gl_LocalInvocationID.x; e < n; e += ML_SORT_WORKGROUP) lightIndices[first + e] = sortScratch[first + e];
}

#if defined(ML_SORT_CLASSIFY)
// One workgroup per listed list; past the device's limit in x, the rest goes to y.
void writeDispatch(uint at, uint lists) {
    uint x = min(lists, u_maxGroupsX);
    sortWork[at] = x;
    sortWork[at + 1u] = x == 0u ? 0u : (lists + x - 1u) / x;
    sortWork[at + 2u] = 1u;
}

void main() {
    uint list = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * ML_SORT_WORKGROUP + gl_GlobalInvocationID.x;
    uint n = list < u_listCount ? listRange(list).y : 0u;
    if (n >= 2u) {
        bool isLong = n > ML_SORT_SHORT_MAX;
        uint slot = atomicAdd(sortWork[isLong ? ML_SORT_LONG_COUNTED : ML_SORT_SHORT_COUNTED], 1u);
        sortWork[ML_SORT_WORK_LISTS + (isLong ? u_listCount : 0u) + slot] = list;
    }
    // The last workgroup to finish writes the dispatches, not a pass of its own, and leaves the
    // counters at 0 for the next run, not a buffer upload before it: every workgroup's appends are
    // in before it counts itself done, so the lengths it takes are final.
    memoryBarrierBuffer();
    barrier();
    if (gl_LocalInvocationIndex == 0u &&
        atomicAdd(sortWork[ML_SORT_GROUPS_DONE], 1u) == gl_NumWorkGroups.x * gl_NumWorkGroups.y - 1u) {
        memoryBarrierBuffer();
        uint shortLists = atomicExchange(sortWork[ML_SORT_SHORT_COUNTED], 0u);
        uint longLists = atomicExchange(sortWork[ML_SORT_LONG_COUNTED], 0u);
        atomicExchange(sortWork[ML_SORT_GROUPS_DONE], 0u);
        sortWork[ML_SORT_SHORT_LENGTH] = shortLists;
        sortWork[ML_SORT_LONG_LENGTH] = longLists;
        writeDispatch(0u, shortLists);
        writeDispatch(3u, longLists);
    }
}
#else
void main() {
    uint slot = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
#ifdef ML_SORT_LONG
    if (slot >= sortWork[ML_SORT_LONG_LENGTH]) return;
    uvec2 range = listRange(sortWork[ML_SORT_WORK_LISTS + u_listCount + slot]);
    if (range.y <= ML_SORT_CAPACITY) bitonicSortShared(range.x, range.y);
    else chunkSortAndMerge(range.x, range.y);
#else
    if (slot >= sortWork[ML_SORT_SHORT_LENGTH]) return;
    uvec2 range = listRange(sortWork[ML_SORT_WORK_LISTS + slot]);
    if (range.y <= ML_SORT_RANK_MAX) rankSort(range.x, range.y);
    else bitonicSortShared(range.x, range.y);
#endif
}
#endif
