// --prepass (renderer/passes/depth_prepass.h): with it, Forward+ shades and deferred writes its
// G-buffer once a pixel after depth alone, the frame bit for bit the one-pass frame, ties and
// alpha-tested edges included. Off, Forward+ shades in its one raster pass with LESS, as naive
// does, so it stays exact against naive; its grid cannot use a depth that does not exist before
// shading.
#include <cstring>

#include <gtest/gtest.h>

#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"

namespace ml::test {
namespace {

MethodSettings forwardPlus(bool prepass, Slicing slicing = Slicing::Fitted) {
    MethodSettings m;
    m.kind = MethodKind::ForwardPlus;
    m.prepass = prepass;
    m.clustering.grid.slicing = slicing;
    return m;
}

MethodSettings deferred(bool prepass, GBufferFormat gbuffer = GBufferFormat::Exact) {
    MethodSettings m;
    m.kind = MethodKind::Deferred;
    m.prepass = prepass;
    m.gbuffer = gbuffer;
    return m;
}

class PrepassOff : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(PrepassOff, MatchesNaiveOnEverySlicing) {
    const TestScene t = testScene(GetParam(), 1024, 5, 0.5f);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    FrameRenderer renderer(t.scene, t.lights, s);
    const ReferenceFrame naive = renderReference(renderer, 45);
    for (Slicing slicing : {Slicing::Linear, Slicing::Log, Slicing::Fitted}) {
        renderer.setMethod(forwardPlus(false, slicing));
        renderer.render(45);
        expectWithinContract(renderer, naive, std::string(GetParam()) + " forward-plus no pre-pass " + slicingName(slicing));
        EXPECT_EQ(renderer.method().clustering()->statistics().droppedReferences, 0u);
        // Fitted needs the pre-pass depth: without it the grid is log-sliced over the camera's range.
        if (slicing == Slicing::Fitted) {
            EXPECT_EQ(renderer.method().clustering()->statistics().slicing, "log");
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PrepassOff, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

class DepthPrepass : public GpuTest {};

// Two coplanar quads of different colours, the second drawn over the first: with LESS the first
// drawn keeps every tied pixel, in naive's one pass and in Forward+'s and deferred's one pass
// alike; with the pre-pass, EQUAL alone would let the second overwrite it, and the stencil keeps
// the first. No lights: the ambient term shows the colour.
TEST_F(DepthPrepass, CoplanarTiesResolveAsInNaiveWithAndWithoutThePrepass) {
    const Scene scene = quadScene({{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}},
                                   {{0.5f, 0.5f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 1.0f}}});
    FrameSettings s = smallFrame(scene, CameraPose{{0.7f, 0.4f, 4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f}, 160, 90);
    s.ambient = 1.0f;
    FrameRenderer renderer(scene, {}, s);
    renderer.render(0);
    const RgbaImage naive = renderer.readLdr();
    for (bool prepass : {true, false}) {
        for (const MethodSettings& method : {forwardPlus(prepass), deferred(prepass)}) {
            renderer.setMethod(method);
            renderer.render(0);
            const RgbaImage test = renderer.readLdr();
            const std::string name = methodName(method.kind) + (prepass ? "_with" : "_without");
            EXPECT_EQ(test.pixels, naive.pixels) << name << ": images in " << writeFailureImages(name, test, naive);
        }
    }
}

bool sameBits(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

class DeferredPrepass : public GpuTest, public ::testing::WithParamInterface<const char*> {};

// Deferred's frame with the pre-pass is its one-pass frame to the bit in every layout (the same
// surface wins every pixel). The atrium has alpha-tested (MASK) and glass (BLEND) materials.
TEST_P(DeferredPrepass, FrameIsTheOnePassFrameBitForBitInEveryLayout) {
    const TestScene t = testScene(GetParam(), 256, 5, 0.5f);
    FrameRenderer renderer(t.scene, t.lights, smallFrame(t.scene, 160, 90));
    for (const std::string& name : gbufferFormatNames()) {
        const GBufferFormat gbuffer = parseGBufferFormat(name);
        renderer.setMethod(deferred(false, gbuffer));
        renderer.render(45);
        const FloatImage onePass = renderer.readHdr();
        const RgbaImage onePassLdr = renderer.readLdr();
        renderer.setMethod(deferred(true, gbuffer));
        renderer.render(45);
        EXPECT_TRUE(sameBits(renderer.readHdr(), onePass))
            << GetParam() << " " << name << ": images in "
            << writeFailureImages(std::string(GetParam()) + "_" + name, renderer.readLdr(), onePassLdr);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, DeferredPrepass, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

class ForwardPlusPrepass : public GpuTest {};

TEST_F(ForwardPlusPrepass, ActiveOnlyWithoutThePrepassIsRefused) {
    MethodSettings m = forwardPlus(false);
    m.clustering.activeOnly = true;
    EXPECT_THROW(createMethod(m, 0), std::invalid_argument);
}

TEST(PrepassCommand, TimeShowsOnlyTheShadingPassAndBadValuesAreRefused) {
    std::string output;
    const std::string out = (testOutputDir() / "p.png").string();
    const std::string common = "render --scene boxes --size 64x48 --lights 16 --method forward-plus --out " + out;
    ASSERT_EQ(runManylights(common + " --prepass off --time --stats", output), 0) << output;
    EXPECT_NE(output.find("forward+.shade"), std::string::npos) << output;
    EXPECT_EQ(output.find("forward+.depth-prepass"), std::string::npos) << output;
    EXPECT_NE(output.find("fitted slicing falls back to log"), std::string::npos) << output;
    EXPECT_NE(output.find("depth pre-pass: off"), std::string::npos) << output;
    ASSERT_EQ(runManylights(common + " --time", output), 0) << output;
    EXPECT_NE(output.find("forward+.depth-prepass"), std::string::npos) << output;
    EXPECT_NE(runManylights(common + " --prepass off --active-only", output), 0);
    EXPECT_NE(output.find("--active-only needs the depth pre-pass"), std::string::npos) << output;
    EXPECT_NE(runManylights(common + " --prepass maybe", output), 0);
    EXPECT_NE(output.find("--prepass 'maybe': expected on or off"), std::string::npos) << output;
}

TEST(PrepassCommand, DeferredTimesThePrePassOnlyWhenOn) {
    std::string output;
    const std::string out = (testOutputDir() / "p.png").string();
    for (const std::string prepass : {"on", "off"}) {
        const std::string args = "render --scene boxes --size 64x48 --lights 16 --method deferred --time --stats --prepass " +
                                 prepass + " --out " + out;
        ASSERT_EQ(runManylights(args, output), 0) << output;
        EXPECT_EQ(output.find("deferred.depth-prepass") != std::string::npos, prepass == "on") << output;
        EXPECT_NE(output.find("deferred.gbuffer"), std::string::npos) << output;
        EXPECT_NE(output.find("depth pre-pass: " + prepass), std::string::npos) << output;
    }
}

}  // namespace
}  // namespace ml::test
