// Exclusive prefix sum of a uint buffer on the GPU (glsl/prefix_sum.comp), any length.
// Used to turn per-cluster light counts into list offsets, so the lists are sized by what
// the frame needs rather than by a cap.
#pragma once

#include <cstdint>
#include <deque>

#include "glsl/include/bindings.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"

namespace ml {

class PrefixSum {
public:
    PrefixSum();
    // Scans data[0, count) in place; the sum of all elements is written as one uint to
    // total at byte offset totalOffset.
    void run(const gl::Buffer& data, std::uint32_t count, const gl::Buffer& total, std::size_t totalOffset);

    // Elements one workgroup scans.
    static constexpr std::uint32_t kBlockSize = 2u * ML_SCAN_WORKGROUP;

private:
    // Phase 0 scans each block and writes block totals to sums; phase 1 adds them back.
    void dispatchPhase(unsigned phase, GLuint data, const gl::Buffer& sums, std::uint32_t count, std::uint32_t blocks) const;
    void scanLevel(GLuint data, std::uint32_t count, std::size_t level, const gl::Buffer& total, std::size_t totalOffset);
    gl::Program program_;
    std::deque<gl::GrowableBuffer> levels_;  // block totals, one buffer per recursion level (deque: references stay valid as levels are added)
};

}  // namespace ml
