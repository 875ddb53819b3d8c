// Determinism (issue 7): the same flags and seed give byte-identical output across runs and
// across the EGL and OSMesa back ends, for every method. The float output is compared as well
// as the PNG, since 8-bit rounding hides most last-bit differences of a reordered float sum.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <iterator>
#include <string>

#include "gpu_test.h"

namespace ml::test {
namespace {

std::string fileBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class Determinism : public ::testing::TestWithParam<const char*> {};

TEST_P(Determinism, RunsAndBackendsGiveIdenticalBytes) {
    const std::string method = GetParam();  // and the light sum where not the method's default
    const std::string dir = testOutputDir().string();
    // Many lights in few large clusters, so every list is long and filled by racing atomics.
    const std::string common = "render --method " + method +
                               " --scene atrium --detail 0.25 --size 160x90 --lights 1500 --light-radius 6 --tiles-x 8"
                               " --slices 6 --frames 3";
    const char* runs[][2] = {{"egl", "a"}, {"egl", "b"}, {"osmesa", "c"}};
    for (const auto& run : runs) {
        std::string output;
        const std::string stem = dir + "/" + run[1];
        ASSERT_EQ(runManylights(common + " --backend " + run[0] + " --out " + stem + ".png --out-float " + stem + ".exr",
                                output),
                  0)
            << output;
    }
    for (const char* ext : {".png", ".exr"}) {
        const std::string a = fileBytes(dir + "/a" + ext);
        ASSERT_FALSE(a.empty());
        // Compared as booleans: a failure should name the files, not print megabytes of them.
        EXPECT_TRUE(a == fileBytes(dir + "/b" + ext)) << method << ": two EGL runs differ (" << dir << "/a" << ext << ", b" << ext << ")";
        EXPECT_TRUE(a == fileBytes(dir + "/c" + ext)) << method << ": EGL and OSMesa differ (" << dir << "/a" << ext << ", c" << ext << ")";
    }
}

// Each method with float sums over sorted lists (the default) and with fixed sums over the lists
// as the fill's atomics left them.
INSTANTIATE_TEST_SUITE_P(Methods, Determinism,
                         ::testing::Values("naive", "forward-plus", "deferred", "visibility", "naive --light-sum fixed",
                                           "forward-plus --light-sum fixed", "deferred --light-sum fixed",
                                           "visibility --light-sum fixed"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& ch : name)
                                 if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                             return name;
                         });

}  // namespace
}  // namespace ml::test
