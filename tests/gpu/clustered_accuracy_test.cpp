// Forward+, clustered deferred (both resolves) and the visibility buffer against the naive reference on the same
// frame, over grids and slicings: the accuracy contract of design.md. With exact lists,
// max error <= 1/255 on the 8-bit output and PSNR >= 50 dB on the float output.
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

struct AccuracyCase {
    const char* scene;
    std::uint32_t lights;
    LightModel model = {};  // GGX, the seeds' falloff; a cut-off gives every light its cut-off radius
};

// glTF's BRDF with glTF's falloff at a hard cut-off, and with stochastic ranges (exact against
// naive for the drawn ranges); and the seeds' Blinn-Phong.
constexpr LightModel kBlinnPhong{Brdf::BlinnPhong};
constexpr LightModel kGgxHard{Brdf::Ggx, Falloff::Gltf, 0.2f};
constexpr LightModel kGgxStochastic{Brdf::Ggx, Falloff::Stochastic, 0.2f};

class ClusteredAccuracy : public GpuTest, public ::testing::WithParamInterface<AccuracyCase> {};

TEST_P(ClusteredAccuracy, MatchesNaiveOnEveryGridAndSlicing) {
    const AccuracyCase c = GetParam();
    TestScene t = testScene(c.scene, c.lights, 5, c.lights >= 1024 ? 0.5f : 1.0f);
    if (c.model.cutoff > 0.0f) applyCutoffRadii(t.lights, c.model.cutoff);
    const Scene& scene = t.scene;
    const std::vector<Light>& lights = t.lights;
    const std::uint32_t frame = 45;

    FrameSettings s = smallFrame(scene, 160, 90);
    setLightModel(s, c.model);
    FrameRenderer renderer(scene, lights, s);
    renderer.render(frame);
    const FloatImage referenceHdr = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();

    const ClusterGridConfig grids[] = {{4, 3, Slicing::Fitted, 32}, {16, 12, Slicing::Fitted, 64}, {40, 32, Slicing::Fitted, 128}};
    for (const ClusteredVariant& v : kClusteredVariants) {
        for (ClusterGridConfig grid : grids) {
            for (Slicing slicing : {Slicing::Linear, Slicing::Log, Slicing::Fitted}) {
                grid.slicing = slicing;
                MethodSettings m;
                m.kind = v.kind;
                m.resolve = v.resolve;
                m.clustering.grid = grid;
                renderer.setMethod(m);
                renderer.render(frame);
                const std::string label = std::string(v.name) + " " + std::to_string(grid.tilesX) + "x" +
                                          std::to_string(grid.slices) + " " + slicingName(slicing);
                const ImageDifference hdr = compareImages(renderer.readHdr(), referenceHdr);
                const RgbaImage ldr = renderer.readLdr();
                const ImageDifference ldrDiff = compareImages(ldr, referenceLdr);
                std::printf("%-40s max8 %.4f  psnr %.1f dB  bad %.4f\n", label.c_str(), ldrDiff.maxAbs * 255.0, hdr.psnrDb,
                            ldrDiff.badPixelShare);
                EXPECT_LE(ldrDiff.maxAbs, kMaxAbs8Bit)
                    << label << ": images in " << writeFailureImages(std::string(c.scene) + "-" + label, ldr, referenceLdr);
                EXPECT_GE(hdr.psnrDb, kMinPsnrDb) << label;
                EXPECT_EQ(renderer.method().clustering()->statistics().droppedReferences, 0u) << label;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ClusteredAccuracy,
    ::testing::Values(AccuracyCase{"boxes", 0}, AccuracyCase{"boxes", 1}, AccuracyCase{"boxes", 64}, AccuracyCase{"boxes", 1024},
                      AccuracyCase{"atrium", 0}, AccuracyCase{"atrium", 1}, AccuracyCase{"atrium", 64},
                      AccuracyCase{"atrium", 1024}, AccuracyCase{"atrium", 1024, kBlinnPhong}, AccuracyCase{"boxes", 64, kGgxHard}, AccuracyCase{"atrium", 1024, kGgxHard},
                      AccuracyCase{"atrium", 256, kGgxStochastic}),
    [](const auto& info) {
        const LightModel& m = info.param.model;
        return std::string(info.param.scene) + "_" + std::to_string(info.param.lights) + "_lights" +
               (m.brdf == LightModel{}.brdf && m.falloff == Falloff::Smooth ? "" : "_" + testNameOf(std::string(brdfName(m.brdf)) + "_" + falloffName(m.falloff)));
    });

// The seeds' baseline on a frame built to overflow: many lights, a small cap. The overflow is
// reported, and the error it causes against naive is measured, not hidden.
class CappedOverflow : public GpuTest {};

TEST_F(CappedOverflow, IsReportedAndItsErrorMeasured) {
    std::vector<std::string> warnings;
    const Scene scene = loadScene(SceneRequest{"boxes", 1.0f}, warnings);
    LightGeneration gen;
    gen.count = 512;
    gen.radius = defaultLightRadius(scene.bounds);
    const std::vector<Light> lights = generateLights(lightVolume(scene.bounds), gen);
    FrameSettings s = smallFrame(scene, 160, 90);
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    const FloatImage reference = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();

    MethodSettings m;
    m.kind = MethodKind::Deferred;
    m.clustering.grid = ClusterGridConfig{8, 4, Slicing::Linear, 64};
    m.clustering.assign = AssignMode::Capped;
    m.clustering.maxPerCluster = 16;
    renderer.setMethod(m);
    renderer.render(0);
    const ClusterStatistics stats = renderer.method().clustering()->statistics();
    EXPECT_GT(stats.overflowClusters, 0u);
    EXPECT_GT(stats.droppedReferences, 0u);
    EXPECT_GT(stats.maxLightsPerCluster, 16u) << "the demand before the cap is reported";
    const ImageDifference capped = compareImages(renderer.readHdr(), reference);
    const ImageDifference cappedLdr = compareImages(renderer.readLdr(), referenceLdr);
    std::printf("capped at 16: %u clusters over, %llu references dropped, PSNR %.1f dB, %.1f %% pixels off by > 1/255\n",
                stats.overflowClusters, static_cast<unsigned long long>(stats.droppedReferences), capped.psnrDb,
                100.0 * cappedLdr.badPixelShare);
    EXPECT_LT(capped.psnrDb, kMinPsnrDb) << "dropped lights must show as error";
    EXPECT_GT(cappedLdr.badPixelShare, 0.01);

    // The overflow view paints the over-cap clusters red.
    m.clustering.view = DebugView::Overflow;
    renderer.setMethod(m);
    renderer.render(0);
    const RgbaImage overflowView = renderer.readLdr();
    std::size_t red = 0;
    for (std::size_t i = 0; i < overflowView.pixels.size(); i += 4)
        red += overflowView.pixels[i] == 255 && overflowView.pixels[i + 1] == 0 && overflowView.pixels[i + 2] == 0;
    EXPECT_GT(red, 0u);

    // Exact lists on the same frame lose nothing.
    m.clustering.view = DebugView::Shaded;
    m.clustering.assign = AssignMode::Exact;
    renderer.setMethod(m);
    renderer.render(0);
    EXPECT_GE(compareImages(renderer.readHdr(), reference).psnrDb, kMinPsnrDb);
}

}  // namespace
}  // namespace ml::test
