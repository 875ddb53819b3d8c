// Sorts every light list by light index on the GPU (glsl/sort_cluster_lists.comp), so that a
// float sum over a list adds its lights in one order, naive's, whatever order the atomics of the
// fill wrote them in. Lists of two or more entries are listed first and sorted in indirect
// dispatches by length: short lists a workgroup each, by rank or a bitonic network in shared
// memory; longer ones a workgroup per chunk of shared memory's capacity, bitonic there, and the
// chunks of a list of several merged by rank after a barrier, a workgroup per chunk again.
//
// Memory: the work lists (16 + lists + 4 x items words, where items bound the long lists' chunks:
// lists + entries / ML_SORT_SHARED_CAPACITY + 1) and, for lists longer than shared memory holds, a
// scratch copy of the list buffer.
#pragma once

#include <cstddef>
#include <cstdint>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"

namespace ml {

class ListSort {
public:
    ListSort();

    // Sorts lists [0, lists): list i holds counts[i] entries of indices from offsets[i] or, with
    // a cap (capped lists), min(counts[i], cap) entries from i * cap. Each list holds a light at
    // most once. Binds its buffers at their points; the lists are sorted in place.
    void sort(const gl::Buffer& counts, const gl::Buffer& offsets, const gl::Buffer& indices, std::uint32_t lists,
              std::uint32_t cap);

    // Bytes of the work lists for `lists` lists in an index buffer of `indexBytes`.
    static std::size_t workBytes(std::uint32_t lists, std::size_t indexBytes) {
        return (kWorkLists + lists + 4 * itemCapacity(lists, indexBytes)) * 4;
    }

private:
    // The work lists' layout: three indirect dispatches (words 0-8), the classification's counters
    // (the three lengths and its workgroups done: 0 between runs), the three lengths for the
    // sorting programs, then the short lists' indices, the chunk items and the merge items.
    static constexpr std::size_t kWorkCounters = 9, kWorkLists = 16;
    // Room for the chunks of the lists longer than ML_SORT_SHORT_MAX, each a workgroup's item.
    static std::uint32_t itemCapacity(std::uint32_t lists, std::size_t indexBytes);

    gl::Program classify_, short_, long_, merge_;
    std::uint32_t maxGroupsX_;  // the device's limit on workgroups in x
    gl::GrowableBuffer work_{"clusters.sort-work"};
    gl::GrowableBuffer scratch_{"clusters.sort-scratch"};
};

}  // namespace ml
