#include "renderer/clustering/prefix_sum.h"

#include <string>

#include "glsl/include/bindings.h"

namespace ml {

PrefixSum::PrefixSum() : program_(gl::Program::compute("prefix_sum.comp")) {}

void PrefixSum::run(const gl::Buffer& data, std::uint32_t count, const gl::Buffer& total, std::size_t totalOffset) {
    if (count == 0) {
        const std::uint32_t zero = 0;
        glClearNamedBufferSubData(total.id(), GL_R32UI, static_cast<GLintptr>(totalOffset), 4, GL_RED_INTEGER,
                                  GL_UNSIGNED_INT, &zero);
        return;
    }
    program_.use();
    scanLevel(data.id(), count, 0, total, totalOffset);
}

void PrefixSum::scanLevel(GLuint data, std::uint32_t count, std::size_t level, const gl::Buffer& total,
                          std::size_t totalOffset) {
    const std::uint32_t blocks = (count + kBlockSize - 1) / kBlockSize;
    while (levels_.size() <= level) levels_.emplace_back("scan.blocks." + std::to_string(levels_.size()));
    gl::GrowableBuffer& sums = levels_[level];
    sums.ensure(std::size_t(blocks) * 4);

    dispatchPhase(0, data, sums.buffer(), count, blocks);

    if (blocks == 1) {
        // One block: its total is the total of everything.
        glCopyNamedBufferSubData(sums.buffer().id(), total.id(), 0, static_cast<GLintptr>(totalOffset), 4);
        return;
    }
    scanLevel(sums.buffer().id(), blocks, level + 1, total, totalOffset);

    program_.use();
    dispatchPhase(1, data, sums.buffer(), count, blocks);
}

void PrefixSum::dispatchPhase(unsigned phase, GLuint data, const gl::Buffer& sums, std::uint32_t count,
                              std::uint32_t blocks) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SCAN_DATA, data);
    sums.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SCAN_BLOCKS);
    program_.set("u_count", count);
    program_.set("u_phase", phase);
    glDispatchCompute(blocks, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace ml
