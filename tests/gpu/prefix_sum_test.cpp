// The GPU prefix sum against the CPU, on sizes around the block size and not multiples of it, up to
// a 2560x1440 screen's glass counts (900 blocks looking back).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <utility>

#include "gpu_test.h"
#include "renderer/clustering/prefix_sum.h"
#include "renderer/hash.h"

namespace ml::test {
namespace {

std::vector<std::uint32_t> cpuExclusiveScan(const std::vector<std::uint32_t>& values) {
    std::vector<std::uint32_t> scanned(values.size());
    std::exclusive_scan(values.begin(), values.end(), scanned.begin(), 0u);
    return scanned;
}

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
    const std::vector<std::uint32_t> expected = cpuExclusiveScan(values);
    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(gpu[i], expected[i]) << "index " << i << " of " << n;
    EXPECT_EQ(gpu[n], 0xDEADBEEFu) << "wrote past the end";
    std::uint32_t sum = 0;
    total.download(&sum, 4, 4);
    EXPECT_EQ(sum, std::accumulate(values.begin(), values.end(), 0u));
}

// One scan object run again and again, its blocks' state kept between runs: a run must not read
// an earlier run's sums as its own, whether the next is longer (the state re-created) or shorter.
using PrefixSumRunsTest = GpuTest;

TEST_F(PrefixSumRunsTest, EachRunScansOnlyItsOwnValues) {
    PrefixSum scan;
    gl::Buffer total("test.total", 4);
    for (std::uint32_t n : {5000u, 70000u, 3000u, 70000u, 1u, 1025u, 70000u}) {
        std::vector<std::uint32_t> values(n);
        for (std::uint32_t i = 0; i < n; ++i) values[i] = pcgHash(i * 7u + n) % 9u;
        gl::Buffer data = gl::Buffer::fromSpan<std::uint32_t>("test.scan", values);
        scan.run(data, n, total, 0);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        const auto gpu = data.downloadAll<std::uint32_t>();
        ASSERT_EQ(gpu, cpuExclusiveScan(values)) << n << " values";
        std::uint32_t sum = 0;
        total.download(&sum, 4, 0);
        EXPECT_EQ(sum, std::accumulate(values.begin(), values.end(), 0u)) << n << " values";
    }
}

// Thousands of blocks looking back at once, run after run: a block that took an earlier block's
// sum for 0 shifts every offset after it. (A look-back whose loads of the sums were plain, or
// atomic only in the branch its flag chose, did so on llvmpipe in most runs of 40.)
TEST_F(PrefixSumRunsTest, ThousandsOfBlocksScanAlikeRunAfterRun) {
    const std::uint32_t n = 2560u * 1648u;
    std::vector<std::uint32_t> values(n);
    for (std::uint32_t i = 0; i < n; ++i) values[i] = pcgHash(i) % 3u;
    const std::vector<std::uint32_t> expected = cpuExclusiveScan(values);
    PrefixSum scan;
    gl::Buffer total("test.total", 4);
    gl::Buffer data = gl::Buffer::fromSpan<std::uint32_t>("test.scan", values);
    for (int run = 0; run < 12; ++run) {
        data.upload(values.data(), n * 4, 0);
        scan.run(data, n, total, 0);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        const auto gpu = data.downloadAll<std::uint32_t>();
        for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(gpu[i], expected[i]) << "index " << i << ", run " << run;
    }
}

// ScanOrder::BlockBases (the glass's per-pixel counts): each block's elements in order from its
// base, written after the elements; the blocks' ranges, in any order, tile [0, total) without a gap
// or an overlap, run after run of one object (its room and count of blocks left at 0 by each).
TEST_F(PrefixSumRunsTest, BlocksInAnyOrderTileTheTotal) {
    PrefixSum scan(ScanOrder::BlockBases);
    gl::Buffer total("test.total", 4);
    for (std::uint32_t n : {1u, 4096u, 4097u, 70000u, 3000u, 2560u * 1440u, 5000u, 2560u * 1440u}) {
        std::vector<std::uint32_t> values(n);
        for (std::uint32_t i = 0; i < n; ++i) values[i] = pcgHash(i * 3u + n) % 5u;
        const std::uint32_t blocks = PrefixSum::blocksOf(n);
        std::vector<std::uint32_t> padded = values;
        padded.resize(std::size_t(n) + blocks + 1, 0u);
        padded.back() = 0xDEADBEEFu;  // past the bases: never written
        gl::Buffer data = gl::Buffer::fromSpan<std::uint32_t>("test.scan", padded);
        scan.run(data, n, total, 0);
        glMemoryBarrier(GL_ALL_BARRIER_BITS);
        const auto gpu = data.downloadAll<std::uint32_t>();
        std::uint32_t sum = 0;
        total.download(&sum, 4, 0);
        ASSERT_EQ(sum, std::accumulate(values.begin(), values.end(), 0u)) << n << " values";
        std::vector<std::pair<std::uint32_t, std::uint32_t>> ranges;  // each block's [base, end)
        for (std::uint32_t b = 0; b < blocks; ++b) {
            std::uint32_t place = gpu[n + b];
            for (std::uint32_t i = b * PrefixSum::kBlockSize; i < std::min(n, (b + 1) * PrefixSum::kBlockSize); ++i) {
                ASSERT_EQ(gpu[i], place) << "index " << i << " of " << n;
                place += values[i];
            }
            ranges.emplace_back(gpu[n + b], place);
        }
        std::sort(ranges.begin(), ranges.end());
        std::uint32_t next = 0;
        for (const auto& [begin, end] : ranges) {
            ASSERT_EQ(begin, next) << n << " values: a gap or an overlap";
            next = end;
        }
        EXPECT_EQ(next, sum);
        EXPECT_EQ(gpu.back(), 0xDEADBEEFu) << "wrote past the bases";
    }
}

INSTANTIATE_TEST_SUITE_P(Sizes, PrefixSumTest,
    ::testing::Values(0u, 1u, 7u, 255u, 256u, 511u, 512u, 513u, 1000u, 1023u, 1024u, 1025u, 4095u, 4096u, 4097u, 8193u, 262143u,
                      262144u, 262145u, 300001u, 3686400u),
    [](const auto& info) { return std::to_string(info.param) + "_values"; });

}  // namespace
}  // namespace ml::test
