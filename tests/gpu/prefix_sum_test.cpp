// The GPU prefix sum against the CPU, on sizes around the block size and not multiples of it.
#include <gtest/gtest.h>

#include <numeric>

#include "gpu_test.h"
#include "renderer/clustering/prefix_sum.h"
#include "renderer/hash.h"

namespace ml::test {
namespace {

class PrefixSumTest : public GpuTest, public ::testing::WithParamInterface<std::uint32_t> {};

TEST_P(PrefixSumTest, MatchesTheCpuExclusiveScan) {
    const std::uint32_t n = GetParam();
    std::vector<std::uint32_t> values(n);
    for (std::uint32_t i = 0; i < n; ++i) values[i] = pcgHash(i) % 50u;
    // One sentinel past the end: the scan must not write beyond count.
    std::vector<std::uint32_t> padded = values;
    padded.push_back(0xDEADBEEFu);
    gl::Buffer data = gl::Buffer::fromSpan<std::uint32_t>("test.scan", padded);
    gl::Buffer total("test.total", 8);
    PrefixSum scan;
    scan.run(data, n, total, 4);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);

    const auto gpu = data.downloadAll<std::uint32_t>();
    std::vector<std::uint32_t> expected(n);
    std::exclusive_scan(values.begin(), values.end(), expected.begin(), 0u);
    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(gpu[i], expected[i]) << "index " << i << " of " << n;
    EXPECT_EQ(gpu[n], 0xDEADBEEFu) << "wrote past the end";
    std::uint32_t sum = 0;
    total.download(&sum, 4, 4);
    EXPECT_EQ(sum, std::accumulate(values.begin(), values.end(), 0u));
}

INSTANTIATE_TEST_SUITE_P(Sizes, PrefixSumTest,
    ::testing::Values(0u, 1u, 7u, 255u, 256u, 511u, 512u, 513u, 1000u, 4097u, 262143u, 262144u, 262145u, 300001u),
    [](const auto& info) { return std::to_string(info.param) + "_values"; });

}  // namespace
}  // namespace ml::test
