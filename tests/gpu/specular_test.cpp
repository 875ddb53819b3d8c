// --specular on|off: the shading model's switch, compiled into every method's shading
// (ShadingSwitches) and read by the CPU reference alike, so every method stays exact against
// naive in both modes; and the switches changed on a live renderer, as the view's panel does.
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test.h"

namespace ml::test {
namespace {

class SpecularOff : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(SpecularOff, EveryMethodMatchesNaive) {
    const TestScene t = testScene(GetParam(), 256, 7, 0.6f);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.specular = false;
    FrameRenderer renderer(t.scene, t.lights, s);
    expectClusteredVariantsMatchNaive(renderer, std::string(GetParam()) + " specular off", 30);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SpecularOff, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

class SpecularSwitch : public GpuTest {};

// Off leaves out a term that is never negative: no pixel gets brighter, and the highlights go.
// Blinn-Phong's: under GGX, off also drops the (1 - F) that weights the diffuse term, so a
// pixel may get brighter (docs/lights-and-shading.md, the BRDF).
TEST_F(SpecularSwitch, OffRemovesTheHighlights) {
    // Full-radius lights: the metallic-roughness mapping gives the atrium's dielectrics a 4 %
    // reflectance, so its highlights need light enough to stand out.
    const TestScene t = testScene("atrium", 256, 7, 1.0f);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    setLightModel(s, LightModel{Brdf::BlinnPhong});
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(30);
    const FloatImage on = renderer.readHdr();
    renderer.setSpecular(false);
    renderer.render(30);
    const FloatImage off = renderer.readHdr();
    double largestDrop = 0.0;
    std::size_t brighter = 0;
    for (std::size_t i = 0; i < on.pixels.size(); ++i) {
        largestDrop = std::max(largestDrop, static_cast<double>(on.pixels[i] - off.pixels[i]));
        brighter += off.pixels[i] > on.pixels[i] * (1.0f + 1e-5f) + 1e-7f;
    }
    EXPECT_EQ(brighter, 0u) << "specular off must never add light";
    EXPECT_GT(largestDrop, 0.01) << "specular on and off gave the same frame";
    EXPECT_LT(compareImages(off, on).psnrDb, 50.0) << "the highlights should be a visible difference";
}

// The view changes --brdf, --specular and --cutoff on a live renderer: the method's programs,
// which compile the switches in, are rebuilt, and the frame is the one a renderer built with the
// new switches draws, bit for bit.
TEST_F(SpecularSwitch, SwitchesChangedLiveRenderAsIfBuiltWithThem) {
    const TestScene t = testScene("atrium", 256, 7, 0.6f);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    s.method.kind = MethodKind::Visibility;
    FrameRenderer live(t.scene, t.lights, s);
    live.render(30);
    ASSERT_TRUE(live.settings().method.clustering.shading.has_value());
    EXPECT_EQ(live.settings().method.clustering.shading->brdf, Brdf::Ggx);

    FrameSettings built = s;
    built.specular = false;
    built.lightModel.brdf = Brdf::BlinnPhong;
    live.setLightModel(built.lightModel);
    live.setSpecular(false);
    EXPECT_EQ(live.settings().method.clustering.shading, (ShadingSwitches{Brdf::BlinnPhong, false, Falloff::Smooth}));
    live.render(30);
    FrameRenderer fresh(t.scene, t.lights, built);
    fresh.render(30);
    const FloatImage a = live.readHdr(), b = fresh.readHdr();
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    EXPECT_TRUE(a.pixels == b.pixels) << "max difference " << compareImages(a, b).maxAbs;
}

}  // namespace
}  // namespace ml::test
