// Stochastic light culling on the GPU: the animation pass draws the ranges its CPU mirror draws;
// a draw is reproducible and the next one differs; the mean of K draws converges to the
// untruncated (physical) reference as 1/sqrt(K), where a hard cut-off's error stays put.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "gpu_test.h"
#include "renderer/frame_accumulation.h"

namespace ml::test {
namespace {

class StochasticCutoff : public GpuTest {};

constexpr float kCutoff = 0.05f;

TestScene stochasticScene() {
    TestScene t = testScene("boxes", 256, 11);
    applyCutoffRadii(t.lights, kCutoff);
    return t;
}

TEST_F(StochasticCutoff, TheAnimationDrawsTheRangesItsCpuMirrorDraws) {
    const TestScene t = stochasticScene();
    FrameSettings s = smallFrame(t.scene, 32, 32);
    s.lightModel = LightModel{Brdf::Ggx, Falloff::Stochastic, kCutoff};
    FrameRenderer renderer(t.scene, t.lights, s);
    for (std::uint32_t draw : {0u, 1u, 7u}) {
        renderer.render(30, draw);
        const std::vector<Light> gpu = renderer.lights().downloadAnimated();
        ASSERT_EQ(gpu.size(), t.lights.size());
        for (std::uint32_t i = 0; i < gpu.size(); ++i) {
            const float want = stochasticRadius(t.lights[i].color, kCutoff, i, stochasticDrawSeed(30, draw));
            EXPECT_NEAR(gpu[i].radius, want, 1e-5f * want) << "light " << i << " draw " << draw;
        }
    }
}

TEST_F(StochasticCutoff, ADrawIsReproducibleAndTheNextDiffers) {
    const TestScene t = stochasticScene();
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.method.kind = MethodKind::Deferred;
    s.lightModel = LightModel{Brdf::Ggx, Falloff::Stochastic, kCutoff};
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(5, 3);
    const FloatImage first = renderer.readHdr();
    renderer.render(5, 4);
    const FloatImage next = renderer.readHdr();
    renderer.render(5, 3);
    EXPECT_EQ(renderer.readHdr().pixels, first.pixels);
    EXPECT_NE(next.pixels, first.pixels);
}

// RMSE of the mean of K draws against naive with no cut-off. The draws are independent per
// light, so the variance of the mean falls as 1/K and its RMSE as 1/sqrt(K): a 4 times longer
// run halves it. Band: each fourfold step must give a ratio in [0.35, 0.65] (0.5 expected; the
// spread is that of a few hundred lights' noise, correlated across the pixels each one reaches).
TEST_F(StochasticCutoff, TheMeanOfManyDrawsConvergesToTheUntruncatedImage) {
    const TestScene t = stochasticScene();
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.lightModel = LightModel{Brdf::Ggx, Falloff::Untruncated, kCutoff};
    FrameRenderer physical(t.scene, t.lights, s);
    physical.render(5);
    const FloatImage reference = physical.readHdr();

    s.method.kind = MethodKind::Deferred;
    s.lightModel.falloff = Falloff::Gltf;
    FrameRenderer hard(t.scene, t.lights, s);
    hard.render(5);
    const double hardRmse = compareImages(hard.readHdr(), reference).rmse;

    s.lightModel.falloff = Falloff::Stochastic;
    FrameRenderer stochastic(t.scene, t.lights, s);
    double previous = 0.0;
    for (std::uint32_t k : {1u, 4u, 16u}) {
        const double rmse = compareImages(renderAccumulated(stochastic, 5, k), reference).rmse;
        std::printf("K = %2u: RMSE %.5f against the untruncated image (hard cut-off: %.5f)\n", k, rmse, hardRmse);
        if (previous > 0.0) {
            EXPECT_GE(rmse / previous, 0.35) << "K = " << k;
            EXPECT_LE(rmse / previous, 0.65) << "K = " << k;
        }
        previous = rmse;
    }
    EXPECT_LT(previous, 0.1 * hardRmse) << "16 draws should be far closer than the hard cut-off's bias";
}

}  // namespace
}  // namespace ml::test

namespace ml::test {
namespace {

std::vector<std::string> csvCells(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) cells.emplace_back();
        else cells.back() += c;
    }
    return cells;
}

// bench --reference physical: hard and stochastic (accumulated) points get the physical_*
// columns; the stochastic mean of four draws is closer to the physical image than one draw,
// and both far closer than the hard cut-off.
TEST(BenchPhysicalReference, AddsItsColumnsAndRanksTheCutoffs) {
    const std::filesystem::path dir = testOutputDir();
    std::string output;
    ASSERT_EQ(runManylights("bench --backend egl --scene boxes --size 96x54 --lights 64 --method deferred --brdf ggx "
                            "--light-cutoff 0.3 --cutoff hard,stochastic --accumulate 1,4 --reference physical "
                            "--warmup 0 --timed-frames 1 --name physical --out " + dir.string(),
                            output),
              0)
        << output;
    std::ifstream csv(dir / "physical.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> header = csvCells(line);
    auto column = [&](const char* name) {
        const auto it = std::find(header.begin(), header.end(), name);
        EXPECT_NE(it, header.end()) << name;
        return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t cutoff = column("cutoff"), accumulate = column("accumulate"), psnr = column("physical_ldr_psnr_db");
    std::map<std::string, double> psnrOf;
    while (std::getline(csv, line)) {
        const std::vector<std::string> cells = csvCells(line);
        ASSERT_GT(cells.size(), psnr) << line;
        psnrOf[cells[cutoff] + " x" + cells[accumulate]] = std::stod(cells[psnr]);
    }
    ASSERT_EQ(psnrOf.size(), 4u) << output;
    EXPECT_GT(psnrOf["stochastic x1"], psnrOf["hard x1"] + 10.0);
    EXPECT_GT(psnrOf["stochastic x4"], psnrOf["stochastic x1"]);
    EXPECT_DOUBLE_EQ(psnrOf["hard x4"], psnrOf["hard x1"]) << "a hard cut-off draws nothing";
}

}  // namespace
}  // namespace ml::test
