// The light-list sort on its own (renderer/clustering/list_sort.h), on lists written here in a
// shuffled order: every path by length (rank sort, bitonic in shared memory for short and long
// lists, chunks merged by rank past shared memory: two chunks, three, five with a last chunk of
// one entry), exact lists with gaps between them that must stay untouched, and capped lists whose
// counts pass the cap (only the first cap entries are a list).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "glsl/include/bindings.h"
#include "gpu_test.h"
#include "renderer/clustering/list_sort.h"

namespace ml::test {
namespace {

constexpr std::uint32_t kGap = 0xDEADBEEFu;  // words between and after lists: never written

// Sorts `lists` as exact lists, one after another with gaps of kGap between, and expects each
// sorted and every other word untouched.
void expectSortedInPlace(const std::vector<std::vector<std::uint32_t>>& lists) {
    std::vector<std::uint32_t> counts, offsets, indices;
    for (const auto& list : lists) {
        indices.insert(indices.end(), 3, kGap);
        counts.push_back(static_cast<std::uint32_t>(list.size()));
        offsets.push_back(static_cast<std::uint32_t>(indices.size()));
        indices.insert(indices.end(), list.begin(), list.end());
    }
    indices.insert(indices.end(), 3, kGap);
    const gl::Buffer countBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.counts", counts);
    const gl::Buffer offsetBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.offsets", offsets);
    const gl::Buffer indexBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.indices", indices);
    ListSort sort;
    sort.sort(countBuffer, offsetBuffer, indexBuffer, static_cast<std::uint32_t>(lists.size()), 0);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    const auto sorted = indexBuffer.downloadAll<std::uint32_t>();

    std::vector<std::uint32_t> expected = indices;
    for (std::size_t i = 0; i < lists.size(); ++i) std::sort(expected.begin() + offsets[i], expected.begin() + offsets[i] + counts[i]);
    for (std::size_t i = 0; i < lists.size(); ++i) {
        const std::vector<std::uint32_t> got(sorted.begin() + offsets[i], sorted.begin() + offsets[i] + counts[i]);
        const std::vector<std::uint32_t> want(expected.begin() + offsets[i], expected.begin() + offsets[i] + counts[i]);
        EXPECT_EQ(got, want) << "list " << i << " of " << counts[i] << " entries";
    }
    EXPECT_EQ(sorted, expected) << "a word outside the lists changed";
}

// Lengths of every path's edges, some lists between.
std::vector<std::uint32_t> listLengths() {
    const std::uint32_t cap = ML_SORT_SHARED_CAPACITY;
    return {0, 1, 2, 3, 17, ML_SORT_RANK_MAX, ML_SORT_RANK_MAX + 1, ML_SORT_SHORT_MAX, ML_SORT_SHORT_MAX + 1, 1000, cap - 1,
            cap, cap + 1, 5000, 2 * cap, 2 * cap + 1, 3 * cap + 77, 4 * cap + 1, 0, 2, 9};
}

// Each list's entries: distinct light indices below 2^20 in a shuffled order.
std::vector<std::vector<std::uint32_t>> shuffledLists(const std::vector<std::uint32_t>& lengths, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<std::uint32_t> pool(1u << 20);
    std::iota(pool.begin(), pool.end(), 0u);
    std::shuffle(pool.begin(), pool.end(), rng);
    std::vector<std::vector<std::uint32_t>> lists;
    for (const std::uint32_t n : lengths) {
        const std::size_t start = std::uniform_int_distribution<std::size_t>(0, pool.size() - n)(rng);
        lists.emplace_back(pool.begin() + std::ptrdiff_t(start), pool.begin() + std::ptrdiff_t(start + n));
    }
    return lists;
}

TEST_F(GpuTest, ListSortSortsExactListsInPlaceAndWritesNothingElse) { expectSortedInPlace(shuffledLists(listLengths(), 7)); }

// Many long lists at once, as a hot frame has (the gas station at a million lights: 109 lists past
// shared memory, up to 17,617 entries): every chunk and merge a workgroup of its own, the work
// lists filled to the room ListSort gives them (each list's chunks, and one more where it ends
// part-way), short lists between.
TEST_F(GpuTest, ListSortSortsManyLongListsAtOnce) {
    std::mt19937 rng(23);
    std::vector<std::uint32_t> lengths;
    for (int i = 0; i < 40; ++i) {
        lengths.push_back(std::uniform_int_distribution<std::uint32_t>(ML_SORT_SHORT_MAX + 1, 4 * ML_SORT_SHARED_CAPACITY + 300)(rng));
        lengths.push_back(std::uniform_int_distribution<std::uint32_t>(0, ML_SORT_SHORT_MAX)(rng));
    }
    expectSortedInPlace(shuffledLists(lengths, 29));
}

TEST_F(GpuTest, ListSortSortsTheFirstCapEntriesOfCappedLists) {
    const std::uint32_t cap = ML_SORT_SHARED_CAPACITY + 905;  // two chunks, the second short
    const auto lists = shuffledLists({0, 1, 300, cap - 1, cap, cap + 1, 3 * cap}, 11);
    std::vector<std::uint32_t> counts, indices(lists.size() * cap, kGap);
    for (std::size_t i = 0; i < lists.size(); ++i) {
        counts.push_back(static_cast<std::uint32_t>(lists[i].size()));  // a capped list's count may pass its cap
        std::copy_n(lists[i].begin(), std::min<std::size_t>(lists[i].size(), cap), indices.begin() + std::ptrdiff_t(i * cap));
    }
    const std::vector<std::uint32_t> unusedOffsets(lists.size(), 0);
    const gl::Buffer countBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.counts", counts);
    const gl::Buffer offsetBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.offsets", unusedOffsets);
    const gl::Buffer indexBuffer = gl::Buffer::fromSpan<std::uint32_t>("test.indices", indices);
    ListSort sort;
    sort.sort(countBuffer, offsetBuffer, indexBuffer, static_cast<std::uint32_t>(lists.size()), cap);
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    const auto sorted = indexBuffer.downloadAll<std::uint32_t>();

    std::vector<std::uint32_t> expected = indices;
    for (std::size_t i = 0; i < lists.size(); ++i) {
        const auto first = expected.begin() + std::ptrdiff_t(i * cap);
        std::sort(first, first + std::min<std::ptrdiff_t>(std::ptrdiff_t(counts[i]), cap));
    }
    EXPECT_EQ(sorted, expected);
}

}  // namespace
}  // namespace ml::test
