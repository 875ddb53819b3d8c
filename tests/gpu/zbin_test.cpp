// Z-binning (--assign zbin) against the naive reference: Forward+, clustered deferred (both
// resolves) and the visibility buffer, on the atrium and boxes with 0, 1, 64 and 1024 lights,
// over grids and slicings (the bins follow the slicing). The accuracy contract of design.md:
// max error <= 1/255 on the 8-bit output and PSNR >= 50 dB on the float output. Also: the
// overflow frame where capped lists drop lights stays exact; the bins and the sort are checked
// against a CPU reference; the memory refusal names what to lower.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "glsl/include/bindings.h"
#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

struct ZBinCase {
    const char* scene;
    std::uint32_t lights;
};

MethodSettings zbinMethod(const ClusteredVariant& v, const ClusterGridConfig& grid) {
    MethodSettings m;
    m.kind = v.kind;
    m.resolve = v.resolve;
    m.clustering.grid = grid;
    m.clustering.assign = AssignMode::ZBin;
    return m;
}

class ZBinAccuracy : public GpuTest, public ::testing::WithParamInterface<ZBinCase> {};

TEST_P(ZBinAccuracy, MatchesNaive) {
    const ZBinCase c = GetParam();
    const TestScene t = testScene(c.scene, c.lights, 5, c.lights >= 1024 ? 0.5f : 1.0f);
    const std::uint32_t frame = 45;
    FrameRenderer renderer(t.scene, t.lights, smallFrame(t.scene, 160, 90));
    renderer.render(frame);
    const FloatImage referenceHdr = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();

    // Few tiles (many lights per word), the default grid, and fine tiles with linear slicing.
    const ClusterGridConfig grids[] = {{4, 3, Slicing::Fitted, 64}, {48, 32, Slicing::Fitted, 64}, {40, 16, Slicing::Linear, 64},
                                       {16, 12, Slicing::Log, 64}};
    for (const ClusteredVariant& v : kClusteredVariants) {
        for (const ClusterGridConfig& grid : grids) {
            renderer.setMethod(zbinMethod(v, grid));
            renderer.render(frame);
            const std::string label = std::string(v.name) + " zbin " + std::to_string(grid.tilesX) + "x" +
                                      std::to_string(grid.slices) + " " + slicingName(grid.slicing);
            const ImageDifference hdr = compareImages(renderer.readHdr(), referenceHdr);
            const RgbaImage ldr = renderer.readLdr();
            const ImageDifference ldrDiff = compareImages(ldr, referenceLdr);
            const ClusterStatistics stats = renderer.method().clustering()->statistics();
            std::printf("%-44s max8 %.4f  psnr %.1f dB  walked %.1f shaded %.1f per pixel\n", label.c_str(),
                        ldrDiff.maxAbs * 255.0, hdr.psnrDb, stats.zbinStats.meanWalkedPerPixel,
                        stats.zbinStats.meanPassedPerPixel);
            EXPECT_LE(ldrDiff.maxAbs, kMaxAbs8Bit)
                << label << ": images in " << writeFailureImages(std::string(c.scene) + "-" + label, ldr, referenceLdr);
            EXPECT_GE(hdr.psnrDb, kMinPsnrDb) << label;
            ASSERT_TRUE(stats.zbin) << label;
            EXPECT_EQ(stats.zbinStats.bins, grid.slices * ML_ZBIN_PER_SLICE);
            EXPECT_LE(stats.zbinStats.meanPassedPerPixel, stats.zbinStats.meanWalkedPerPixel + 1e-9) << label;
            EXPECT_LE(stats.zbinStats.listedLights, c.lights);
            EXPECT_EQ(stats.zbinStats.wordsPerTile, (stats.zbinStats.listedLights + 31) / 32);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ZBinAccuracy,
    ::testing::Values(ZBinCase{"boxes", 0}, ZBinCase{"boxes", 1}, ZBinCase{"boxes", 64}, ZBinCase{"boxes", 1024},
                      ZBinCase{"atrium", 0}, ZBinCase{"atrium", 1}, ZBinCase{"atrium", 64}, ZBinCase{"atrium", 1024}),
    [](const auto& info) { return std::string(info.param.scene) + "_" + std::to_string(info.param.lights) + "_lights"; });

class ZBinStructure : public GpuTest {};

// The sort and the bins against the CPU: listed lights in order of their near extent, each
// listed once, and every bin's range holding every light whose depth extent reaches the bin.
TEST_F(ZBinStructure, SortAndBinsMatchTheCpu) {
    const TestScene t = testScene("atrium", 1000, 11);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.setMethod(zbinMethod(kClusteredVariants[1], ClusterGridConfig{16, 8, Slicing::Fitted, 64}));
    renderer.render(0);
    const ClusteredLighting& clustering = *renderer.method().clustering();
    const ZBinAssignment& zbin = *clustering.zbin();
    const std::vector<std::uint32_t> sorted = zbin.downloadSortedLights();
    const std::vector<glm::uvec2> ranges = zbin.downloadBinRanges();
    ASSERT_GT(sorted.size(), 100u) << "most lights are in view";

    const glm::mat4 view = renderer.uniforms().view;
    const std::vector<Light> drawn = renderer.lights().downloadAnimated();
    auto nearExtent = [&](std::uint32_t light, float& zMin, float& zMax) {
        const float z = -(view * glm::vec4(drawn[light].position, 1.0f)).z;
        zMin = z - drawn[light].radius;
        zMax = z + drawn[light].radius;
    };
    std::vector<bool> seen(t.lights.size(), false);
    float previous = -1e30f;
    for (std::uint32_t i = 0; i < sorted.size(); ++i) {
        ASSERT_LT(sorted[i], t.lights.size());
        EXPECT_FALSE(seen[sorted[i]]) << "light " << sorted[i] << " listed twice";
        seen[sorted[i]] = true;
        float zMin, zMax;
        nearExtent(sorted[i], zMin, zMax);
        EXPECT_GE(zMin, previous - 1e-3f - 1e-4f * std::abs(previous)) << "sorted position " << i;
        previous = zMin;
    }
    // Bin boundaries from the grid's slicing as the GPU fitted it.
    const ClusterGridGpu g = clustering.downloadGrid();
    const std::uint32_t bins = g.dims.z * ML_ZBIN_PER_SLICE;
    ASSERT_EQ(ranges.size(), bins);
    auto binOf = [&](float z) {
        const float f = g.tile.y > 0.5f ? std::log(std::max(z, 1e-7f)) : z;
        const float b = std::floor((f * g.slicing.z + g.slicing.w) * float(ML_ZBIN_PER_SLICE));
        return static_cast<std::uint32_t>(std::clamp(b, 0.0f, float(bins - 1)));
    };
    std::uint32_t checked = 0;
    for (std::uint32_t i = 0; i < sorted.size(); ++i) {
        float zMin, zMax;
        nearExtent(sorted[i], zMin, zMax);
        // Bins strictly inside the extent (the ends may round either way).
        for (std::uint32_t b = binOf(zMin) + 1; b + 1 <= binOf(zMax); ++b) {
            EXPECT_LE(ranges[b].x, i) << "bin " << b;
            EXPECT_GE(ranges[b].y, i) << "bin " << b;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100u);
}

// The frame built to overflow: 4096 lights of a large radius packed into a small region, so
// clusters there need more than capped lists' default 2048 entries. Capped lists drop lights;
// z-binning has no cap and stays exact.
class ZBinOverflow : public GpuTest {};

TEST_F(ZBinOverflow, StaysExactWhereCappedListsDrop) {
    std::vector<std::string> warnings;
    const Scene scene = loadScene(SceneRequest{"boxes", 0.25f}, warnings);
    const glm::vec3 centre = 0.5f * (scene.bounds.min + scene.bounds.max);
    const float extent = glm::length(scene.bounds.max - scene.bounds.min);
    Bounds small;
    small.extend(centre - glm::vec3(0.05f * extent));
    small.extend(centre + glm::vec3(0.05f * extent));
    LightGeneration gen;
    gen.count = 4096;
    gen.radius = 0.3f * extent;
    gen.intensity = 0.02f;
    const std::vector<Light> lights = generateLights(small, gen);
    FrameRenderer renderer(scene, lights, smallFrame(scene, 160, 90));
    renderer.render(0);
    const FloatImage reference = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();

    MethodSettings m;
    m.kind = MethodKind::Deferred;
    m.clustering.grid = ClusterGridConfig{16, 16, Slicing::Fitted, 64};
    m.clustering.assign = AssignMode::Capped;
    renderer.setMethod(m);
    renderer.render(0);
    const ClusterStatistics capped = renderer.method().clustering()->statistics();
    const ImageDifference cappedDiff = compareImages(renderer.readHdr(), reference);
    std::printf("capped at %u: %llu references dropped, PSNR %.1f dB\n", m.clustering.maxPerCluster,
                static_cast<unsigned long long>(capped.droppedReferences), cappedDiff.psnrDb);
    ASSERT_GT(capped.droppedReferences, 0u) << "the frame must overflow the cap";
    EXPECT_LT(cappedDiff.psnrDb, kMinPsnrDb);

    for (const ClusteredVariant& v : kClusteredVariants) {
        renderer.setMethod(zbinMethod(v, m.clustering.grid));
        renderer.render(0);
        const ImageDifference hdr = compareImages(renderer.readHdr(), reference);
        const RgbaImage ldr = renderer.readLdr();
        const ImageDifference ldrDiff = compareImages(ldr, referenceLdr);
        std::printf("%-20s zbin: max8 %.4f  psnr %.1f dB\n", v.name, ldrDiff.maxAbs * 255.0, hdr.psnrDb);
        EXPECT_LE(ldrDiff.maxAbs, kMaxAbs8Bit) << v.name << ": images in "
                                               << writeFailureImages(std::string("overflow-") + v.name, ldr, referenceLdr);
        EXPECT_GE(hdr.psnrDb, kMinPsnrDb) << v.name;
    }
}

// The light-count view shows, for z-binning, the lights each pixel shades.
TEST_F(ZBinStructure, LightCountViewShowsShadedLights) {
    const TestScene t = testScene("boxes", 64, 3);
    FrameRenderer renderer(t.scene, t.lights, smallFrame(t.scene, 160, 90));
    MethodSettings m = zbinMethod(kClusteredVariants[0], ClusterGridConfig{16, 16, Slicing::Fitted, 64});
    m.clustering.view = DebugView::LightCount;
    renderer.setMethod(m);
    renderer.render(0);
    const RgbaImage image = renderer.readLdr();
    std::size_t lit = 0;
    for (std::size_t i = 0; i < image.pixels.size(); i += 4) lit += image.pixels[i] + image.pixels[i + 1] + image.pixels[i + 2] > 0;
    EXPECT_GT(lit, image.pixels.size() / 4 / 10) << "pixels with lights show a colour";
}

// Masks beyond the storage-block limit are refused before anything is allocated, with a
// message that says what to lower.
TEST(ZBinCommand, RefusesMasksBeyondTheStorageLimit) {
    std::string output;
    EXPECT_NE(runManylights("render --scene boxes --size 160x90 --method deferred --assign zbin --lights 1048576 "
                            "--light-radius 0.2 --tiles-x 160 --out /dev/null",
                            output),
              0);
    EXPECT_NE(output.find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << output;
    EXPECT_NE(output.find("lower --tiles-x or --lights"), std::string::npos) << output;
}

TEST(ZBinCommand, StatsAndTimeReportZBin) {
    std::string output;
    ASSERT_EQ(runManylights("render --scene boxes --size 96x64 --lights 64 --method forward-plus --assign zbin --stats --time "
                            "--out /dev/null",
                            output),
              0)
        << output;
    for (const char* expected : {"zbin.sort", "zbin.bins", "zbin.tile-masks", "words per tile", "walked", "zbin tile masks"})
        EXPECT_NE(output.find(expected), std::string::npos) << expected << " missing in\n" << output;
}

}  // namespace
}  // namespace ml::test
