// Stable radix sort of (key, value) uint pairs on the GPU (glsl/radix_sort.comp): four passes of
// 8-bit digits, each a per-workgroup histogram, an exclusive prefix sum of all histograms
// (PrefixSum) and a stable scatter. Any count, 0 included. z-binning sorts lights by view depth
// with it.
//
// Memory: a scratch copy of keys and values (8 B per element) and 256 x 4 B per block of
// ML_RADIX_WORKGROUP x ML_RADIX_ROUNDS elements (1 KiB per 1024 elements).
#pragma once

#include <cstdint>

#include "glsl/include/bindings.h"
#include "renderer/clustering/prefix_sum.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"

namespace ml {

class RadixSort {
public:
    RadixSort();
    // Sorts keys[0, count) ascending, moving values[0, count) with them; equal keys keep their
    // order. The result is in keys and values; elements past count are not touched.
    void sort(const gl::Buffer& keys, const gl::Buffer& values, std::uint32_t count);

    static constexpr std::uint32_t kBlockSize = ML_RADIX_WORKGROUP * ML_RADIX_ROUNDS;
    static constexpr std::uint32_t kDigitBits = 8;

    // Bytes of scratch and histograms for `count` elements.
    static std::size_t scratchBytes(std::uint32_t count);

private:
    gl::Program histogram_, scatter_;
    PrefixSum scan_;
    gl::GrowableBuffer keysScratch_{"radix.keys-scratch"};
    gl::GrowableBuffer valuesScratch_{"radix.values-scratch"};
    gl::GrowableBuffer histograms_{"radix.histograms"};
    gl::Buffer total_;
};

}  // namespace ml
