#version 450 core
// Sorts every light list by light index.
// Why: the fill passes write lists through atomics, so their order changes from run to run,
// and a float sum taken in a different order differs in its last bits. Sorted lists make the
// shaded frame a pure function of the flags and the seed (byte-identical runs, issue 7).
//
// Four programs from this file. ML_SORT_CLASSIFY (one invocation per list) appends every list of
// two or more entries to the short work list, or each chunk of ML_SORT_SHARED_CAPACITY entries of a
// longer one to the chunk work list (and, where a list has several, to the merge work list too),
// and its last workgroup to finish turns their lengths into indirect dispatches: most lists hold
// 0 or 1 lights (every empty normal bin of --normal-cones, the empty space of a frame), and a
// workgroup launched per list only to return cost 1.5 s a frame on llvmpipe at 160x90 with normal
// cones, 15 s at 16x4096. Then one workgroup per listed item. Short lists (no define): a rank
// sort from shared memory, or a bitonic network there. ML_SORT_LONG, a chunk: a bitonic network in
// shared memory, into the list (a list of one chunk) or into a scratch buffer. ML_SORT_MERGE, after
// a barrier, a chunk of a list of several: each entry to its place in the whole list, its place in
// its chunk plus the entries smaller than it in each other chunk (docs/architecture.md,
// "Light-list order", has the costs). A long list's chunks and merges are workgroups of their own,
// so no workgroup holds a hot cluster's whole list (one did: 17,617 entries on the gas station at a
// million lights, the last workgroup of the pass).
#include "include/bindings.h"

#if defined(ML_SORT_CLASSIFY)
#define ML_SORT_WORKGROUP 64
#define ML_SORT_CAPACITY 1
#elif defined(ML_SORT_LONG) || defined(ML_SORT_MERGE)
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

// The work lists: the three indirect dispatches (short at word 0, chunks at 3, merges at 6), the
// three lengths as the classification counts them and the classifying workgroups done (left at 0
// for the next run by the last), the three lengths for the sorting programs, then the short lists'
// indices from word ML_SORT_WORK_LISTS, and after u_listCount words the chunk items and after
// 2 x u_itemCapacity more the merge items, each item two words: its list and its chunk.
layout(std430, binding = ML_SSBO_SORT_WORK) coherent buffer SortWork { uint sortWork[]; };
#define ML_SORT_SHORT_COUNTED 9
#define ML_SORT_CHUNKS_COUNTED 10
#define ML_SORT_MERGES_COUNTED 11
#define ML_SORT_GROUPS_DONE 12
#define ML_SORT_SHORT_LENGTH 13
#define ML_SORT_CHUNKS_LENGTH 14
#define ML_SORT_MERGES_LENGTH 15
#define ML_SORT_WORK_LISTS 16

// Lists: one per cluster, or one per (cluster, normal bin) with --normal-cones.
uniform uint u_listCount;
uniform uint u_listCap;     // capped lists: entries a list holds; 0 for exact lists
uniform uint u_maxGroupsX;  // ML_SORT_CLASSIFY: the device's limit on workgroups in x
uniform uint u_itemCapacity;  // items each of the chunk and merge work lists holds (ListSort)

uint chunkItems() { return ML_SORT_WORK_LISTS + u_listCount; }
uint mergeItems() { return ML_SORT_WORK_LISTS + u_listCount + 2u * u_itemCapacity; }

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
void bitonicSortShared(uint first, uint n, bool toScratch) {
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
    for (uint i = gl_LocalInvocationID.x; i < n; i += ML_SORT_WORKGROUP) {
        if (toScratch) sortScratch[first + i] = s_list[i];
        else lightIndices[first + i] = s_list[i];
    }
}

// A long list's chunks: ML_SORT_SHARED_CAPACITY entries each, the last what is left.
uint chunkLength(uint n, uint chunk) { return min(uint(ML_SORT_SHARED_CAPACITY), n - chunk * ML_SORT_SHARED_CAPACITY); }
uint chunksOf(uint n) { return (n + ML_SORT_SHARED_CAPACITY - 1u) / ML_SORT_SHARED_CAPACITY; }

#if defined(ML_SORT_MERGE)
// How many entries of a chunk, sorted into the scratch buffer, are smaller than x: a binary search.
uint smallerIn(uint chunkFirst, uint chunkSize, uint x) {
    uint lo = 0u, hi = chunkSize;
    while (lo < hi) {
        uint mid = (lo + hi) >> 1;
        if (sortScratch[chunkFirst + mid] < x) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

// Chunk `own` of a list of several, each sorted into the scratch buffer at the list's offsets:
// every entry to its place in the whole list, its place in its chunk plus the entries smaller than
// it in each other chunk (a light appears once per list, so no two entries share a place). The
// list's chunks are a few tens of KiB, so the searches mostly hit in L1.
void mergeChunk(uint first, uint n, uint own) {
    uint chunks = chunksOf(n);
    for (uint i = gl_LocalInvocationID.x; i < chunkLength(n, own); i += ML_SORT_WORKGROUP) {
        uint x = sortScratch[first + own * ML_SORT_SHARED_CAPACITY + i];
        uint place = i;
        for (uint c = 0u; c < chunks; ++c)
            if (c != own) place += smallerIn(first + c * ML_SORT_SHARED_CAPACITY, chunkLength(n, c), x);
        lightIndices[first + place] = x;
    }
}
#endif

#if defined(ML_SORT_CLASSIFY)
// One workgroup per listed list; past the device's limit in x, the rest goes to y.
void writeDispatch(uint at, uint lists) {
    uint x = min(lists, u_maxGroupsX);
    sortWork[at] = x;
    sortWork[at + 1u] = x == 0u ? 0u : (lists + x - 1u) / x;
    sortWork[at + 2u] = 1u;
}

// Appends `count` items, chunks 0 to count - 1 of the list, to the work list at `items`.
void appendChunks(uint counter, uint items, uint list, uint count) {
    uint slot = atomicAdd(sortWork[counter], count);
    for (uint c = 0u; c < count; ++c) {
        sortWork[items + 2u * (slot + c)] = list;
        sortWork[items + 2u * (slot + c) + 1u] = c;
    }
}

void main() {
    uint list = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * ML_SORT_WORKGROUP + gl_GlobalInvocationID.x;
    uint n = list < u_listCount ? listRange(list).y : 0u;
    if (n >= 2u && n <= ML_SORT_SHORT_MAX) {
        sortWork[ML_SORT_WORK_LISTS + atomicAdd(sortWork[ML_SORT_SHORT_COUNTED], 1u)] = list;
    } else if (n > ML_SORT_SHORT_MAX) {
        uint chunks = chunksOf(n);
        appendChunks(ML_SORT_CHUNKS_COUNTED, chunkItems(), list, chunks);
        if (chunks > 1u) appendChunks(ML_SORT_MERGES_COUNTED, mergeItems(), list, chunks);
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
        uint chunks = atomicExchange(sortWork[ML_SORT_CHUNKS_COUNTED], 0u);
        uint merges = atomicExchange(sortWork[ML_SORT_MERGES_COUNTED], 0u);
        atomicExchange(sortWork[ML_SORT_GROUPS_DONE], 0u);
        sortWork[ML_SORT_SHORT_LENGTH] = shortLists;
        sortWork[ML_SORT_CHUNKS_LENGTH] = chunks;
        sortWork[ML_SORT_MERGES_LENGTH] = merges;
        writeDispatch(0u, shortLists);
        writeDispatch(3u, chunks);
        writeDispatch(6u, merges);
    }
}
#else
void main() {
    uint slot = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
#if defined(ML_SORT_LONG) || defined(ML_SORT_MERGE)
#ifdef ML_SORT_LONG
    if (slot >= sortWork[ML_SORT_CHUNKS_LENGTH]) return;
    uint item = chunkItems() + 2u * slot;
#else
    if (slot >= sortWork[ML_SORT_MERGES_LENGTH]) return;
    uint item = mergeItems() + 2u * slot;
#endif
    uint list = sortWork[item], chunk = sortWork[item + 1u];
    uvec2 range = listRange(list);
#ifdef ML_SORT_LONG
    // A list of one chunk is sorted where it lies; a chunk of several into the scratch buffer, for the merge.
    bitonicSortShared(range.x + chunk * ML_SORT_SHARED_CAPACITY, chunkLength(range.y, chunk), range.y > ML_SORT_SHARED_CAPACITY);
#else
    mergeChunk(range.x, range.y, chunk);
#endif
#else
    if (slot >= sortWork[ML_SORT_SHORT_LENGTH]) return;
    uvec2 range = listRange(sortWork[ML_SORT_WORK_LISTS + slot]);
    if (range.y <= ML_SORT_RANK_MAX) rankSort(range.x, range.y);
    else bitonicSortShared(range.x, range.y, false);
#endif
}
#endif
