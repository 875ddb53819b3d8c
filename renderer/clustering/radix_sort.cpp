#include "renderer/clustering/radix_sort.h"

namespace ml {

namespace {
constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
constexpr std::uint32_t kRadix = 1u << RadixSort::kDigitBits;
}  // namespace

RadixSort::RadixSort()
    : histogram_(gl::Program("radix.histogram", {{GL_COMPUTE_SHADER, "radix_sort.comp"}}, {{"ML_RADIX_HISTOGRAM", "1"}})),
      scatter_(gl::Program("radix.scatter", {{GL_COMPUTE_SHADER, "radix_sort.comp"}}, {{"ML_RADIX_SCATTER", "1"}})),
      total_("radix.total", 16) {}

std::size_t RadixSort::scratchBytes(std::uint32_t count) {
    const std::size_t blocks = (std::size_t(count) + kBlockSize - 1) / kBlockSize;
    return std::size_t(count) * 8 + blocks * kRadix * 4;
}

void RadixSort::sort(const gl::Buffer& keys, const gl::Buffer& values, std::uint32_t count) {
    if (count <= 1) return;
    const std::uint32_t blocks = (count + kBlockSize - 1) / kBlockSize;
    keysScratch_.ensure(std::size_t(count) * 4);
    valuesScratch_.ensure(std::size_t(count) * 4);
    histograms_.ensure(std::size_t(blocks) * kRadix * 4);

    // Ping-pong: an even number of passes leaves the result where it started.
    static_assert((32 / kDigitBits) % 2 == 0);
    GLuint keysIn = keys.id(), valuesIn = values.id();
    GLuint keysOut = keysScratch_.buffer().id(), valuesOut = valuesScratch_.buffer().id();
    for (std::uint32_t shift = 0; shift < 32; shift += kDigitBits) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_KEYS_IN, keysIn);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_VALUES_IN, valuesIn);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_KEYS_OUT, keysOut);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_VALUES_OUT, valuesOut);
        auto runPhase = [&](const gl::Program& phase) {
            histograms_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_HISTOGRAMS);
            phase.use();
            phase.set("u_count", count);
            phase.set("u_shift", shift);
            glDispatchCompute(blocks, 1, 1);
            glMemoryBarrier(kComputeToCompute);
        };
        runPhase(histogram_);
        scan_.run(histograms_.buffer(), blocks * kRadix, total_, 0);  // where each (digit, block) goes
        glMemoryBarrier(kComputeToCompute);
        runPhase(scatter_);
        std::swap(keysIn, keysOut);
        std::swap(valuesIn, valuesOut);
    }
}

}  // namespace ml
