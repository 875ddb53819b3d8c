// Sorts every light list by light index on the GPU (glsl/sort_cluster_lists.comp), so that a
// float sum over a list adds its lights in one order, naive's, whatever order the atomics of the
// fill wrote them in. Lists of two or more entries are listed first and sorted one workgroup
// each, in two indirect dispatches by length: short lists by rank or a bitonic network in shared
// memory, long ones by a bitonic network in shared memory or, past it, in chunks merged by rank.
//
// Memory: the work lists (11 + 2 x lists words) and, for lists longer than shared memory holds, a
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

    // Bytes of the work lists for `lists` lists.
    static std::size_t workBytes(std::uint32_t lists) { return (kWorkLists + 2 * std::size_t(lists)) * 4; }

private:
    // The work lists' layout: two indirect dispatches (words 0-5), the classification's counters
    // (the two lengths and its workgroups done: 0 between runs), the two lengths for the sorting
    // programs, then the listed lists' indices.
    static constexpr std::size_t kWorkCounters = 6, kWorkLists = 11;

    gl::Program classify_, short_, long_;
    std::uint32_t maxGroupsX_;  // the device's limit on workgroups in x
    gl::GrowableBuffer work_{"clusters.sort-work"};
    gl::GrowableBuffer scratch_{"clusters.sort-scratch"};
};

}  // namespace ml
