// The GPU radix sort against std::stable_sort on the CPU: sizes around the block size and not
// multiples of it (0 to past a million), keys with many duplicates so stability shows, and
// keys spread over all 32 bits so every digit pass matters.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "gpu_test.h"
#include "renderer/clustering/radix_sort.h"
#include "renderer/hash.h"

namespace ml::test {
namespace {

struct SortCase {
    std::uint32_t count;
    std::uint32_t distinctKeys;  // 0: any 32-bit key
};

class RadixSortTest : public GpuTest, public ::testing::WithParamInterface<SortCase> {};

TEST_P(RadixSortTest, MatchesStdStableSort) {
    const SortCase c = GetParam();
    const std::uint32_t n = c.count;
    std::vector<std::uint32_t> keys(n), values(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t h = pcgHash(i * 3u + 1u) ^ (pcgHash(i) << 7);
        // Few distinct keys spread over the high and low bytes: many ties, every digit used.
        keys[i] = c.distinctKeys ? (h % c.distinctKeys) * 0x01010101u : h;
        values[i] = i;
    }
    // One sentinel past the end: the sort must not write beyond count.
    std::vector<std::uint32_t> paddedKeys = keys, paddedValues = values;
    paddedKeys.push_back(0xDEADBEEFu);
    paddedValues.push_back(0xFEEDFACEu);
    gl::Buffer keyBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.keys", paddedKeys);
    gl::Buffer valueBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.values", paddedValues);
    RadixSort sort;
    sort.sort(keyBuffer, valueBuffer, n);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);

    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    const auto gpuKeys = keyBuffer.downloadAll<std::uint32_t>();
    const auto gpuValues = valueBuffer.downloadAll<std::uint32_t>();
    for (std::uint32_t i = 0; i < n; ++i) {
        ASSERT_EQ(gpuKeys[i], keys[order[i]]) << "key at " << i << " of " << n;
        ASSERT_EQ(gpuValues[i], order[i]) << "value at " << i << " of " << n << " (stability)";
    }
    EXPECT_EQ(gpuKeys[n], 0xDEADBEEFu) << "wrote past the end";
    EXPECT_EQ(gpuValues[n], 0xFEEDFACEu) << "wrote past the end";
}

INSTANTIATE_TEST_SUITE_P(Sizes, RadixSortTest,
    ::testing::Values(SortCase{0, 0}, SortCase{1, 0}, SortCase{2, 3}, SortCase{255, 0}, SortCase{256, 7}, SortCase{1000, 0},
                      SortCase{1023, 5}, SortCase{1024, 0}, SortCase{1025, 11}, SortCase{4097, 0}, SortCase{65537, 300},
                      SortCase{300001, 0}, SortCase{1048576 + 3, 0}, SortCase{1048576 + 3, 1000}),
    [](const auto& info) {
        return std::to_string(info.param.count) + (info.param.distinctKeys ? "_ties" + std::to_string(info.param.distinctKeys) : "_any");
    });

}  // namespace
}  // namespace ml::test
