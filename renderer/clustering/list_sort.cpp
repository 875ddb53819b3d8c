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
      maxGroupsX_(gl::maxWorkGroupsX()) {
    classify_.set("u_maxGroupsX", maxGroupsX_);
}

void ListSort::sort(const gl::Buffer& counts, const gl::Buffer& offsets, const gl::Buffer& indices, std::uint32_t lists,
                    std::uint32_t cap) {
    if (lists == 0) return;
    // A new buffer's counters to 0; after that each run leaves them so.
    if (work_.ensure(workBytes(lists))) {
        const std::uint32_t counters[3] = {0, 0, 0};
        work_.buffer().upload(counters, sizeof counters, kWorkCounters * 4);
    }
    // Lists past the long program's shared memory are merged here, at their own offsets.
    scratch_.ensure(indices.size());
    glMemoryBarrier(kComputeToCompute);
    counts.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
    offsets.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_OFFSETS);
    indices.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_INDICES);
    work_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SORT_WORK);
    scratch_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SORT_SCRATCH);
    // Only lists of two or more entries get a workgroup: they are listed, then dispatched
    // indirectly (glsl/sort_cluster_lists.comp says why). The short and the long program take
    // disjoint lists, so they need no barrier between them.
    const std::uint32_t classifyGroups = gl::groupsFor(lists, 64);
    const std::uint32_t groupsX = std::min(classifyGroups, maxGroupsX_);
    classify_.use();
    classify_.set("u_listCount", lists);
    classify_.set("u_listCap", cap);
    glDispatchCompute(groupsX, (classifyGroups + groupsX - 1) / groupsX, 1);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | kComputeToCompute);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, work_.buffer().id());
    for (const auto& [program, argsOffset] : {std::pair{&short_, 0}, std::pair{&long_, 12}}) {
        program->use();
        program->set("u_listCount", lists);
        program->set("u_listCap", cap);
        glDispatchComputeIndirect(argsOffset);
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(kComputeToCompute);
}

}  // namespace ml
