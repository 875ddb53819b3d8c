#include "renderer/clustering/prefix_sum.h"

#include <algorithm>

#include "glsl/include/bindings.h"

namespace ml {

namespace {
constexpr std::size_t kStateHeaderBytes = 16;  // ticket, reserved room, blocks done, unused
constexpr std::size_t kBlockStateBytes = 16;   // flag, aggregate, inclusive, unused
constexpr std::uint32_t kEpochs = 1u << 30;    // the flag keeps two bits for the status
}  // namespace

PrefixSum::PrefixSum(ScanOrder order)
    : program_(gl::Program::compute("prefix_sum.comp", order == ScanOrder::BlockBases ? shaders::Defines{{"ML_SCAN_BLOCK_BASES", "1"}}
                                                                                        : shaders::Defines{})),
      maxGroupsX_(gl::maxWorkGroupsX()) {}

void PrefixSum::run(const gl::Buffer& data, std::uint32_t count, const gl::Buffer& total, std::size_t totalOffset) {
    if (count == 0) {
        const std::uint32_t zero = 0;
        glClearNamedBufferSubData(total.id(), GL_R32UI, static_cast<GLintptr>(totalOffset), 4, GL_RED_INTEGER,
                                  GL_UNSIGNED_INT, &zero);
        return;
    }
    const std::uint32_t blocks = blocksOf(count);
    // A new buffer, or the epochs run out: every flag to 0 (no run's) and the tickets to 0.
    epoch_ = (epoch_ + 1) % kEpochs;
    if (state_.ensure(kStateHeaderBytes + std::size_t(blocks) * kBlockStateBytes) || epoch_ == 0) {
        glClearNamedBufferData(state_.buffer().id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        epoch_ = 1;
        firstTicket_ = 0;
    }
    // Past the device's limit along x the dispatch goes on in y; the spare workgroups' tickets
    // name no block.
    const std::uint32_t groupsX = std::min(blocks, maxGroupsX_);
    const std::uint32_t groupsY = (blocks - 1) / groupsX + 1;
    program_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SCAN_DATA, data.id());
    state_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SCAN_BLOCKS);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SCAN_TOTAL, total.id());
    program_.set("u_count", count);
    program_.set("u_totalWord", static_cast<std::uint32_t>(totalOffset / 4));
    program_.set("u_epoch", epoch_);
    program_.set("u_firstTicket", firstTicket_);
    glDispatchCompute(groupsX, groupsY, 1);
    firstTicket_ += groupsX * groupsY;  // wraps, as the shader's counter does
}

}  // namespace ml
