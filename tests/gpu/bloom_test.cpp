// --bloom: the GPU passes against their CPU mirror (renderer/reference/bloom_reference.h), where bloom
// appears, and that it is the same for every method.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gpu_test.h"
#include "renderer/reference/bloom_reference.h"

namespace ml::test {
namespace {

float luminance(const float* c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }

// One bright light close to the boxes' floor, a few dim ones: a small hot spot.
TestScene hotSpotScene() {
    TestScene t = testScene("boxes", 8, 3, 0.5f);
    t.lights.push_back(Light{{0.3f, 0.4f, 0.2f}, 3.0f, {40.0f, 30.0f, 20.0f}});
    return t;
}

class Bloom : public GpuTest {
protected:
    // The frame without and with bloom; odd sizes exercise the half-resolution edges.
    void renderBoth(int width, int height, const BloomSettings& bloom) {
        const TestScene t = hotSpotScene();
        FrameSettings s = smallFrame(t.scene, width, height);
        FrameRenderer renderer(t.scene, t.lights, s);
        renderer.render(0);
        off_ = renderer.readHdr();
        renderer.setBloom(bloom);
        renderer.render(0);
        on_ = renderer.readHdr();
    }
    FloatImage off_, on_;
};

TEST_F(Bloom, GpuMatchesTheCpuReference) {
    for (const auto& [w, h] : {std::pair{160, 90}, std::pair{161, 91}}) {
        const BloomSettings bloom{true, 1.0f, 0.8f};
        renderBoth(w, h, bloom);
        const FloatImage expected = bloomReference(off_, bloom);
        float peak = 0.0f, worst = 0.0f;
        for (std::size_t i = 0; i < expected.pixels.size(); ++i) {
            peak = std::max(peak, expected.pixels[i]);
            worst = std::max(worst, std::abs(on_.pixels[i] - expected.pixels[i]));
        }
        std::printf("%dx%d: bloom GPU vs CPU max %.3g (peak %.3g)\n", w, h, worst, peak);
        EXPECT_LE(worst, 1e-5f * std::max(1.0f, peak)) << w << "x" << h;
        EXPECT_GT(compareImages(on_, off_).maxAbs, 0.05) << "the hot spot should bloom";
    }
}

// Pixels above the threshold brighten; pixels further from every one of them than the kernel
// reaches (2 x (ML_BLOOM_RADIUS + 1) full-resolution pixels with the up- and downsampling)
// keep their exact value; with the threshold above the brightest pixel nothing changes.
TEST_F(Bloom, ChangesOnlyAroundPixelsAboveTheThreshold) {
    const int w = 160, h = 90;
    const float threshold = 2.0f;
    renderBoth(w, h, BloomSettings{true, threshold, 0.5f});
    std::vector<std::pair<int, int>> bright;
    float brightest = 0.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            brightest = std::max(brightest, luminance(off_.at(x, y)));
            if (luminance(off_.at(x, y)) > threshold) bright.emplace_back(x, y);
        }
    ASSERT_FALSE(bright.empty()) << "the hot spot should exceed the threshold";
    ASSERT_LT(bright.size(), std::size_t(w * h / 10)) << "the hot spot should be small";
    const int reach = 2 * (ML_BLOOM_RADIUS + 1) + 1;
    std::size_t far = 0, changedFar = 0, brighter = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* a = off_.at(x, y);
            const float* b = on_.at(x, y);
            const bool changed = a[0] != b[0] || a[1] != b[1] || a[2] != b[2];
            if (luminance(a) > threshold) brighter += luminance(b) > luminance(a);
            const bool near = std::any_of(bright.begin(), bright.end(), [&](const auto& p) {
                return std::abs(p.first - x) <= reach && std::abs(p.second - y) <= reach;
            });
            if (!near) {
                ++far;
                changedFar += changed;
            }
        }
    EXPECT_EQ(brighter, bright.size()) << "every pixel above the threshold should gain bloom";
    EXPECT_GT(far, 0u);
    EXPECT_EQ(changedFar, 0u) << "pixels out of the kernel's reach must not change";

    renderBoth(w, h, BloomSettings{true, brightest * 1.01f, 0.5f});
    EXPECT_EQ(on_.pixels, off_.pixels) << "nothing above the threshold: bloom must add nothing";
}

// Bloom runs after shading, so the methods compare as they do without it.
TEST_F(Bloom, EveryMethodMatchesNaive) {
    const TestScene t = hotSpotScene();
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.bloom = BloomSettings{true, 1.0f, 0.8f};
    FrameRenderer renderer(t.scene, t.lights, s);
    const ReferenceFrame naive = renderReference(renderer, 0);
    for (MethodKind kind : {MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        MethodSettings m;
        m.kind = kind;
        renderer.setMethod(m);
        renderer.render(0);
        expectWithinContract(renderer, naive, "boxes bloom " + methodName(kind));
    }
}

TEST(BloomCommand, TimeShowsTheBloomPasses) {
    std::string output;
    const std::string out = (testOutputDir() / "b.png").string();
    ASSERT_EQ(runManylights("render --scene boxes --size 64x48 --lights 16 --bloom --time --stats --out " + out, output), 0)
        << output;
    for (const char* pass : {"bloom.bright-pass", "bloom.blur-h", "bloom.blur-v", "bloom.composite"})
        EXPECT_NE(output.find(pass), std::string::npos) << pass << " missing in:\n" << output;
    EXPECT_NE(output.find("bloom: threshold"), std::string::npos) << output;
    EXPECT_NE(runManylights("render --bloom --bloom-strength -1 --out " + out, output), 0);
    EXPECT_NE(output.find("--bloom-strength"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
