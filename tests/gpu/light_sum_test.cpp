// --light-sum (issue 30, lists without a sort): the fixed sum gives the same bits in any light
// order, so the lists go unsorted; the float sum needs the sort. Both agree to float rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gpu_test.h"

namespace ml::test {
namespace {

struct SumCase {
    MethodKind kind;
    const char* name;
};
constexpr SumCase kMethods[] = {{MethodKind::Naive, "naive"},
                                {MethodKind::ForwardPlus, "forward_plus"},
                                {MethodKind::Deferred, "deferred"},
                                {MethodKind::Visibility, "visibility"}};

// Many overlapping lights (long lists filled by racing atomics), spots among them, held still
// so that a light's index changes nothing but the order of the sums.
FrameSettings stillFrame(const Scene& scene, MethodKind kind, LightSum sum) {
    FrameSettings s = smallFrame(scene, 160, 90);
    s.animation = LightAnimation{};
    s.method.kind = kind;
    s.method.clustering.lightSum = sum;
    return s;
}

FloatImage renderHdr(const TestScene& t, const std::vector<Light>& lights, const FrameSettings& s) {
    FrameRenderer renderer(t.scene, lights, s);
    renderer.render(0);
    return renderer.readHdr();
}

std::size_t differingValues(const FloatImage& a, const FloatImage& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
    return n;
}

class LightSumTest : public GpuTest, public ::testing::WithParamInterface<SumCase> {};

// The same lights listed backwards: every list and naive's loop run in another order.
TEST_P(LightSumTest, FixedSumsGiveTheSameBitsInAnyLightOrder) {
    const SumCase c = GetParam();
    const TestScene t = testScene("atrium", 1500, 7, 3.0f, 0.3f);
    std::vector<Light> reversed = t.lights;
    std::reverse(reversed.begin(), reversed.end());
    const FrameSettings s = stillFrame(t.scene, c.kind, LightSum::Fixed);
    const FloatImage forward = renderHdr(t, t.lights, s), backward = renderHdr(t, reversed, s);
    ASSERT_EQ(forward.pixels.size(), backward.pixels.size());
    EXPECT_EQ(differingValues(forward, backward), 0u) << c.name;
    // The check sees order: float sums over the reversed lights differ in their last bits.
    if (c.kind == MethodKind::Naive) {
        const FrameSettings f = stillFrame(t.scene, c.kind, LightSum::Float);
        EXPECT_GT(differingValues(renderHdr(t, t.lights, f), renderHdr(t, reversed, f)), 0u);
    }
}

// Fixed and float sums of one frame agree to float rounding (a wrong scale or rounding would not).
TEST_P(LightSumTest, FixedAndFloatSumsAgree) {
    const SumCase c = GetParam();
    const TestScene t = testScene("atrium", 1500, 7, 3.0f, 0.3f);
    const FloatImage fixed = renderHdr(t, t.lights, stillFrame(t.scene, c.kind, LightSum::Fixed));
    const FloatImage floats = renderHdr(t, t.lights, stillFrame(t.scene, c.kind, LightSum::Float));
    ASSERT_EQ(fixed.pixels.size(), floats.pixels.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < fixed.pixels.size(); ++i)
        worst = std::max(worst, std::abs(double(fixed.pixels[i]) - floats.pixels[i]) / std::max(1.0, std::abs(double(floats.pixels[i]))));
    std::printf("%s: largest difference %.3g (relative above 1)\n", c.name, worst);
    EXPECT_LT(worst, 1e-5) << c.name;
    EXPECT_GT(*std::max_element(fixed.pixels.begin(), fixed.pixels.end()), 0.1f) << "a dark frame would show nothing";
}

// The sort runs for float sums alone.
TEST_P(LightSumTest, SortRunsForFloatSumsAlone) {
    const SumCase c = GetParam();
    if (c.kind == MethodKind::Naive) GTEST_SKIP() << "naive has no lists";
    const TestScene t = testScene("atrium", 200, 7);
    for (LightSum sum : {LightSum::Fixed, LightSum::Float}) {
        FrameSettings s = stillFrame(t.scene, c.kind, sum);
        s.timing = true;  // render() names the passes it ran
        FrameRenderer renderer(t.scene, t.lights, s);
        const auto passes = renderer.render(0);
        const bool sorted = std::any_of(passes.begin(), passes.end(), [](const PassTime& p) { return p.name == "assign.sort"; });
        EXPECT_EQ(sorted, sum == LightSum::Float) << c.name << " " << lightSumName(sum);
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, LightSumTest, ::testing::ValuesIn(kMethods), [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace ml::test
