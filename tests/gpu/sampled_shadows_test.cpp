// --shadows sampled (issue 63): the exact unshadowed frame times a sampled visibility ratio.
// Held to the exact shadows (--shadows rays, which naive traces alike): where nothing is in the
// way the frame is the unshadowed one to the bit; the raw estimate is unbiased (the mean over
// many draws matches the exact frame within its standard error) and its error falls as draws
// accumulate; temporal reuse converges on a still view; frames repeat; and the methods that do not
// sample trace the exact rays.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gpu_test.h"
#include "renderer/camera/camera.h"

namespace ml::test {
namespace {

class SampledShadowsTest : public GpuTest {};

constexpr int kWidth = 160, kHeight = 90;

// A 12 x 12 floor and a wall 4 wide and 2 tall standing on it (as in shadow_rays_test.cpp).
Scene wallOnFloor() {
    return quadScene({{{0, 0, 0}, {6, 0, 0}, {0, 0, -6}, glm::vec3(0.7f)}, {{0, 1, 0}, {2, 0, 0}, {0, 1, 0}, glm::vec3(0.5f, 0.6f, 0.7f)}});
}
const CameraPose kWallView{{0.0f, 7.0f, 7.0f}, {0.0f, 0.0f, 0.5f}, 60.0f};

// Lights behind, beside and in front of the wall, of several colours: most floor points see some
// and not others, so their ratio is strictly between 0 and 1.
std::vector<Light> penumbraLights() {
    return {Light{{0.0f, 1.0f, -3.0f}, 20.0f, glm::vec3(8.0f)}, Light{{-2.5f, 1.5f, -2.0f}, 20.0f, glm::vec3(6.0f, 3.0f, 1.0f)},
            Light{{2.5f, 0.6f, -1.0f}, 20.0f, glm::vec3(1.0f, 4.0f, 6.0f)}, Light{{1.0f, 3.0f, 2.0f}, 20.0f, glm::vec3(3.0f)},
            Light{{-3.0f, 0.4f, 1.5f}, 20.0f, glm::vec3(5.0f, 5.0f, 2.0f)}};
}

FrameSettings frameOf(const Scene& scene, Shadows shadows, MethodKind kind = MethodKind::Visibility) {
    FrameSettings s = smallFrame(scene, kWallView, kWidth, kHeight);
    s.shadows = shadows;
    s.method.kind = kind;
    return s;
}

// --shadows sampled with the raw estimate (no reuse, no filter): unbiased, noisy.
FrameSettings rawEstimate(const Scene& scene, std::uint32_t rays = 2) {
    FrameSettings s = frameOf(scene, Shadows::Sampled);
    s.sampledShadows = SampledShadowSettings{rays, false, false};
    return s;
}

float luminanceAt(const FloatImage& image, std::size_t pixel) {
    const float* p = image.pixels.data() + 3 * pixel;
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

FloatImage render(FrameRenderer& renderer, std::uint32_t frame, std::uint32_t draw = 0) {
    renderer.render(frame, draw);
    return renderer.readHdr();
}

// RMS of the luminance difference.
double luminanceRmse(const FloatImage& a, const FloatImage& b) {
    double sum = 0.0;
    const std::size_t n = a.pixels.size() / 3;
    for (std::size_t i = 0; i < n; ++i) sum += std::pow(double(luminanceAt(a, i)) - double(luminanceAt(b, i)), 2.0);
    return std::sqrt(sum / double(n));
}

// A floor alone under lights at grazing heights and a wall whose lights all stand in front of it:
// every ray reaches its light, so the sampled frame is the unshadowed one to the bit (the ratio is
// exactly 1 through the reuse and the filter), frame after frame, with every option.
TEST_F(SampledShadowsTest, NothingInTheWayIsTheUnshadowedFrameToTheBit) {
    const Scene floor = quadScene({{{0, 0, 0}, {6, 0, 0}, {0, 0, -6}, glm::vec3(0.8f)}});
    std::vector<Light> lights;
    for (int i = 0; i < 12; ++i) {
        const float angle = 0.5236f * float(i);
        lights.push_back(Light{{7.0f * std::cos(angle), i % 2 == 0 ? 0.05f : 1.5f, 7.0f * std::sin(angle)}, 16.0f, glm::vec3(30.0f)});
    }
    for (MethodKind kind : {MethodKind::Visibility, MethodKind::Deferred}) {
        SCOPED_TRACE(methodName(kind));
        FrameRenderer off(floor, lights, frameOf(floor, Shadows::Off, kind));
        FrameSettings s = frameOf(floor, Shadows::Sampled, kind);
        for (const SampledShadowSettings& options : {SampledShadowSettings{1, true, true}, SampledShadowSettings{4, false, true}}) {
            s.sampledShadows = options;
            FrameRenderer sampled(floor, lights, s);
            for (std::uint32_t frame = 0; frame < 3; ++frame)
                EXPECT_EQ(compareImages(render(sampled, frame), render(off, frame)).maxAbs, 0.0) << "frame " << frame;
        }
    }
}

// The raw estimate's mean over 64 draws of one frame matches the exact shadows in luminance (the
// estimator's promise: the ratio times the unshadowed light has the shadowed light's luminance in
// expectation), to within four standard errors over the frame; and the error of the mean falls as
// the draws accumulate, about as 1 / sqrt(draws).
TEST_F(SampledShadowsTest, TheRawEstimateIsUnbiasedAndConverges) {
    const Scene scene = wallOnFloor();
    const std::vector<Light> lights = penumbraLights();
    FrameRenderer exact(scene, lights, frameOf(scene, Shadows::Rays));
    const FloatImage reference = render(exact, 0);
    FrameRenderer sampled(scene, lights, rawEstimate(scene));
    const std::size_t n = reference.pixels.size() / 3;
    constexpr std::uint32_t kDraws = 64;
    std::vector<double> sum(n, 0.0), sumSquares(n, 0.0);
    FloatImage mean4, mean16;
    for (std::uint32_t draw = 0; draw < kDraws; ++draw) {
        const FloatImage frame = render(sampled, 0, draw);
        for (std::size_t i = 0; i < n; ++i) {
            const double l = luminanceAt(frame, i);
            sum[i] += l;
            sumSquares[i] += l * l;
        }
        if (draw + 1 == 4 || draw + 1 == 16) {
            FloatImage& mean = draw + 1 == 4 ? mean4 : mean16;
            mean = reference;
            for (std::size_t i = 0; i < n; ++i) mean.pixels[3 * i] = mean.pixels[3 * i + 1] = mean.pixels[3 * i + 2] = float(sum[i] / double(draw + 1));
        }
    }
    // The frame's total: the sum of the per-pixel differences against its standard error.
    double bias = 0.0, variance = 0.0, rmse64 = 0.0;
    std::size_t penumbra = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double m = sum[i] / kDraws, v = std::max(sumSquares[i] / kDraws - m * m, 0.0) * kDraws / (kDraws - 1);
        bias += m - luminanceAt(reference, i);
        variance += v / kDraws;
        rmse64 += std::pow(m - luminanceAt(reference, i), 2.0);
        if (v > 0.0) ++penumbra;
    }
    rmse64 = std::sqrt(rmse64 / double(n));
    EXPECT_GT(penumbra, n / 10) << "too few pixels in a penumbra for the test to mean anything";
    EXPECT_LE(std::abs(bias), 4.0 * std::sqrt(variance) + 1e-3) << "the mean drifts from the exact shadows: biased";
    // Grey means of luminance against the reference's luminance (luminanceAt of a grey is itself).
    auto greyRmse = [&](const FloatImage& mean) {
        double s = 0.0;
        for (std::size_t i = 0; i < n; ++i) s += std::pow(double(mean.pixels[3 * i]) - double(luminanceAt(reference, i)), 2.0);
        return std::sqrt(s / double(n));
    };
    const double rmse4 = greyRmse(mean4), rmse16 = greyRmse(mean16);
    EXPECT_GT(rmse4, 0.0) << "no noise: the estimate never missed";
    EXPECT_LT(rmse16, 0.65 * rmse4) << "16 draws no better than 4";
    EXPECT_LT(rmse64, 0.65 * rmse16) << "64 draws no better than 16";
}

// With the view and the lights still, temporal reuse averages each pixel's ratio over the frames
// before: the error against the exact shadows falls well below a single frame's, and the frame's
// mean stays on the exact one.
TEST_F(SampledShadowsTest, TemporalReuseConvergesOnAStillView) {
    const Scene scene = wallOnFloor();
    const std::vector<Light> lights = penumbraLights();
    FrameRenderer exact(scene, lights, frameOf(scene, Shadows::Rays));
    const FloatImage reference = render(exact, 0);
    FrameSettings s = frameOf(scene, Shadows::Sampled);
    s.sampledShadows = SampledShadowSettings{2, true, false};
    FrameRenderer reused(scene, lights, s);
    FrameRenderer single(scene, lights, rawEstimate(scene));
    const double first = luminanceRmse(render(single, 0), reference);
    FloatImage last;
    for (std::uint32_t frame = 0; frame < 32; ++frame) last = render(reused, 0, frame);  // the frame held still, its draws anew
    const double converged = luminanceRmse(last, reference);
    EXPECT_LT(converged, 0.35 * first) << "32 frames of reuse: " << converged << " against one frame's " << first;
    double bias = 0.0;
    for (std::size_t i = 0; i < reference.pixels.size() / 3; ++i) bias += luminanceAt(last, i) - luminanceAt(reference, i);
    EXPECT_LT(std::abs(bias) / double(reference.pixels.size() / 3), 0.1 * first) << "the reused frame drifted off the exact one";
}

// The draws hash the pixel, the light and the frame's seed: two renderers give the same frames,
// bit for bit, history and filter included; another frame's draws differ.
TEST_F(SampledShadowsTest, FramesRepeatBitForBit) {
    const Scene scene = wallOnFloor();
    const std::vector<Light> lights = penumbraLights();
    const FrameSettings s = frameOf(scene, Shadows::Sampled);
    FrameRenderer a(scene, lights, s), b(scene, lights, s);
    FloatImage previous;
    for (std::uint32_t frame = 0; frame < 3; ++frame) {
        const FloatImage imageA = render(a, frame), imageB = render(b, frame);
        EXPECT_EQ(compareImages(imageA, imageB).maxAbs, 0.0) << "frame " << frame;
        if (frame == 1) {
            FrameRenderer raw1(scene, lights, rawEstimate(scene)), raw0(scene, lights, rawEstimate(scene));
            EXPECT_GT(compareImages(render(raw1, 1), render(raw0, 0)).maxAbs, 0.0) << "frame 1 drew what frame 0 drew";
        }
    }
}

// Naive, Forward+ and deferred's fragment resolve do not sample: with --shadows sampled they
// trace the exact rays, the frame --shadows rays gives, to the bit.
TEST_F(SampledShadowsTest, TheMethodsThatDoNotSampleTraceTheExactRays) {
    const Scene scene = wallOnFloor();
    const std::vector<Light> lights = penumbraLights();
    for (auto [kind, resolve] : {std::pair{MethodKind::Naive, Resolve::Compute}, std::pair{MethodKind::ForwardPlus, Resolve::Compute},
                                 std::pair{MethodKind::Deferred, Resolve::Fragment}}) {
        SCOPED_TRACE(methodName(kind));
        FrameSettings rays = frameOf(scene, Shadows::Rays, kind), sampled = frameOf(scene, Shadows::Sampled, kind);
        rays.method.resolve = sampled.method.resolve = resolve;
        FrameRenderer a(scene, lights, rays), b(scene, lights, sampled);
        EXPECT_EQ(compareImages(render(b, 0), render(a, 0)).maxAbs, 0.0);
    }
}

TEST(SampledShadowsFlags, BadValuesAreOneLine) {
    std::string output;
    EXPECT_NE(runManylights("render --size 32x18 --shadows sampled --shadow-rays-per-pixel 3 --out /dev/null", output), 0);
    EXPECT_NE(output.find("--shadow-rays-per-pixel 3: expected 1, 2 or 4"), std::string::npos) << output;
    EXPECT_NE(runManylights("render --size 32x18 --shadows sampled --shadow-reuse spatial --out /dev/null", output), 0);
    EXPECT_NE(output.find("--shadow-reuse 'spatial': expected temporal or none"), std::string::npos) << output;
    EXPECT_NE(runManylights("render --size 32x18 --shadows sampled --shadow-denoise maybe --out /dev/null", output), 0);
    EXPECT_NE(output.find("--shadow-denoise 'maybe': expected on or off"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
