// Exclusive prefix sum of a uint buffer on the GPU (glsl/prefix_sum.comp), any length, in one
// dispatch (a chained scan with decoupled look-back). Used to turn per-cluster light counts into
// list offsets, so the lists are sized by what the frame needs rather than by a cap, and the
// glass's per-pixel fragment counts into where each pixel's fragments go (in blocks placed in any
// order: ScanOrder::BlockBases).
#pragma once

#include <cstdint>

#include "glsl/include/bindings.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"

namespace ml {

// Where a run puts the blocks of kBlockSize elements (glsl/prefix_sum.comp).
enum class ScanOrder {
    Chained,     // in order: every element's exclusive prefix sum
    BlockBases,  // each block's elements in order from a base the block reserves by an atomic, the
                 // blocks in whatever order they finish; block b's base at data[count + b]
};

class PrefixSum {
public:
    explicit PrefixSum(ScanOrder order = ScanOrder::Chained);
    // Scans data[0, count) in place; the sum of all elements is written as one uint to
    // total at byte offset totalOffset (a multiple of 4), by the scan itself: the caller's
    // glMemoryBarrier after the run covers both. ScanOrder::BlockBases: data holds
    // count + blocksOf(count) words.
    void run(const gl::Buffer& data, std::uint32_t count, const gl::Buffer& total, std::size_t totalOffset);

    // Elements one workgroup scans.
    static constexpr std::uint32_t kBlockSize = ML_SCAN_WORKGROUP * ML_SCAN_PER_INVOCATION;
    static constexpr std::uint32_t blocksOf(std::uint32_t count) { return (count + kBlockSize - 1) / kBlockSize; }

private:
    gl::Program program_;
    std::uint32_t maxGroupsX_;  // the device's limit on workgroups along x
    // The ticket counter, the total, and each block's published sums (the shader's ScanState).
    gl::GrowableBuffer state_{"scan.state"};
    // Each run's number, in the blocks' flags: a flag left by an earlier run never reads as set.
    std::uint32_t epoch_ = 0;
    std::uint32_t firstTicket_ = 0;  // the shader's ticket counter before this run
};

}  // namespace ml
