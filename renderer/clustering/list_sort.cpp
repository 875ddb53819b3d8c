#include "renderer/clustering/list_sort.h"

#include <algorithm>
#include <utility>

#include "glsl/include/bindings.h"

namespace ml {

namespace {
constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
}  // namespace

ListSort::ListSort()
    : classify_(gl::Program::compute("sort_cluster_lists.comp", {{"ML_SORT_CLASSIFY", "1"}})),
      short_(gl::Program::compute("sort_cluster_lists.comp")),
      long_(gl::Program::compute("sort_cluster_lists.comp", {{"ML_SORT_LONG", "1"}})),
      merge_(gl::Program::compute("sort_cluster_lists.comp", {{"ML_SORT_MERGE", "1"}})),
      maxGroupsX_(gl::maxWorkGroupsX()) {
    classify_.set("u_maxGroupsX", maxGroupsX_);
}

std::uint32_t ListSort::itemCapacity(std::uint32_t lists, std::size_t indexBytes) {
    // A list of n > ML_SORT_SHORT_MAX entries takes ceil(n / capacity) <= 1 + floor(n / capacity)
    // items, and the lists hold at most the index buffer's words.
    const std::size_t words = indexBytes / 4;
    return static_cast<std::uint32_t>(std::min<std::size_t>(lists, words / ML_SORT_SHORT_MAX) + words / ML_SORT_SHARED_CAPACITY + 1);
}

void ListSort::sort(const gl::Buffer& counts, const gl::Buffer& offsets, const gl::Buffer& indices, std::uint32_t lists,
                    std::uint32_t cap) {
    if (lists == 0) return;
    // A new buffer's counters to 0; after that each run leaves them so.
    if (work_.ensure(workBytes(lists, indices.size()))) {
        const std::uint32_t counters[4] = {0, 0, 0, 0};
        work_.buffer().upload(counters, sizeof counters, kWorkCounters * 4);
    }
    // The chunks of lists past the long program's shared memory, sorted, at their own offsets.
    scratch_.ensure(indices.size());
    glMemoryBarrier(kComputeToCompute);
    counts.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
    offsets.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_OFFSETS);
    indices.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_INDICES);
    work_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SORT_WORK);
    scratch_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SORT_SCRATCH);
    // Only lists of two or more entries get a workgroup: they are listed, then dispatched
    // indirectly (glsl/sort_cluster_lists.comp says why). Short lists and chunks are disjoint
    // words, so they need no barrier between them; the merges read the chunks.
    const std::uint32_t classifyGroups = gl::groupsFor(lists, 64);
    const std::uint32_t groupsX = std::min(classifyGroups, maxGroupsX_);
    const std::uint32_t items = itemCapacity(lists, indices.size());
    classify_.use();
    classify_.set("u_listCount", lists);
    classify_.set("u_listCap", cap);
    classify_.set("u_itemCapacity", items);
    glDispatchCompute(groupsX, (classifyGroups + groupsX - 1) / groupsX, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | kComputeToCompute);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, work_.buffer().id());
    const auto dispatch = [&](const gl::Program& program, GLintptr argsOffset) {
        program.use();
        program.set("u_listCount", lists);
        program.set("u_listCap", cap);
        program.set("u_itemCapacity", items);
        glDispatchComputeIndirect(argsOffset);
    };
    dispatch(short_, 0);
    dispatch(long_, 12);
    glMemoryBarrier(kComputeToCompute);  // the merges read the sorted chunks
    dispatch(merge_, 24);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(kComputeToCompute);
}

}  // namespace ml
