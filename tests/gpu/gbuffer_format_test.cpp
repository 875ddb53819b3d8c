// --gbuffer exact|standard|packed|two-component: exact (the default) loses nothing naive's
// shading sees, so deferred and the visibility buffer shade naive's surface; packed holds the
// accuracy contract at this size (against the standard layout and against naive); two-component
// is the documented failure case, shown on surfaces whose stored (world-space) normal has z < 0.
#include <gtest/gtest.h>

#include "glsl/include/bindings.h"
#include "gpu_test.h"

namespace ml::test {
namespace {

MethodSettings withGBuffer(MethodKind kind, GBufferFormat format, Resolve resolve = Resolve::Compute) {
    MethodSettings m;
    m.kind = kind;
    m.resolve = resolve;
    m.gbuffer = format;
    return m;
}

class PackedGBuffer : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(PackedGBuffer, MatchesStandardAndNaive) {
    const TestScene t = testScene(GetParam(), 1024, 5, 0.5f);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    FrameRenderer renderer(t.scene, t.lights, s);
    const ReferenceFrame naive = renderReference(renderer, 45);
    const std::string scene = GetParam();
    struct Case {
        MethodKind kind;
        Resolve resolve;
        const char* name;
    };
    for (const Case c : {Case{MethodKind::Deferred, Resolve::Compute, "deferred/compute"},
                         Case{MethodKind::Deferred, Resolve::Fragment, "deferred/fragment"},
                         Case{MethodKind::Visibility, Resolve::Compute, "visibility"}}) {
        renderer.setMethod(withGBuffer(c.kind, GBufferFormat::Standard, c.resolve));
        renderer.render(45);
        const FloatImage standard = renderer.readHdr();
        renderer.setMethod(withGBuffer(c.kind, GBufferFormat::Packed, c.resolve));
        renderer.render(45);
        const ImageDifference againstStandard = compareImages(renderer.readHdr(), standard);
        std::printf("%s packed vs standard, %s: psnr %.1f dB\n", scene.c_str(), c.name, againstStandard.psnrDb);
        EXPECT_GE(againstStandard.psnrDb, 50.0) << c.name;
        expectWithinContract(renderer, naive, scene + " packed " + c.name + " vs naive");
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PackedGBuffer, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

class ExactGBuffer : public GpuTest, public ::testing::WithParamInterface<const char*> {};

// The exact layout stores the surface as shaded and its position along the pixel's ray: its
// float output is far closer to naive's than the lossy layouts' (their error is what breaks the
// contract at full size, tests/fullsize), and deferred and the visibility buffer, which shade
// the same rebuilt surface (glsl/include/triangle_surface.glsl), agree with each other as closely.
TEST_P(ExactGBuffer, ShadesNaivesSurfaceWhereThePackedLayoutDoesNot) {
    NaiveReferenceScene run(GetParam(), 1024);
    FrameRenderer& renderer = run.renderer;
    const ReferenceFrame& naive = run.reference;
    const std::string scene = GetParam();
    for (MethodKind kind : {MethodKind::Deferred, MethodKind::Visibility}) {
        renderer.setMethod(withGBuffer(kind, GBufferFormat::Packed));
        renderer.render(run.frame);
        const double packed = compareImages(renderer.readHdr(), naive.hdr).psnrDb;
        renderer.setMethod(withGBuffer(kind, GBufferFormat::Exact));
        renderer.render(run.frame);
        const double exact = compareImages(renderer.readHdr(), naive.hdr).psnrDb;
        std::printf("%s %s against naive: exact %.1f dB, packed %.1f dB\n", scene.c_str(), methodName(kind).c_str(), exact, packed);
        EXPECT_GE(exact, packed + 10.0) << methodName(kind);
        expectWithinContract(renderer, naive, scene + " exact " + methodName(kind) + " vs naive");
    }
    renderer.setMethod(withGBuffer(MethodKind::Deferred, GBufferFormat::Exact));
    renderer.render(run.frame);
    const FloatImage deferred = renderer.readHdr();
    renderer.setMethod(withGBuffer(MethodKind::Visibility, GBufferFormat::Exact));
    renderer.render(run.frame);
    EXPECT_GE(compareImages(renderer.readHdr(), deferred).psnrDb, 80.0) << "deferred against visibility, both exact";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ExactGBuffer, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

class GBufferLayouts : public GpuTest {};

// A wall facing -z (world space, the space the G-buffer stores normals in) seen from the -z
// side and lit from there. two-component rebuilds z as +sqrt(1 - x^2 - y^2): the normal flips to
// +z, away from every light, and the wall goes dark but for the ambient term. packed keeps it.
TEST_F(GBufferLayouts, TwoComponentLosesTheSignOfZWherePackedDoesNot) {
    const Scene scene = quadScene({
        {{0.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.8f, 0.7f, 0.6f}},    // normal -z
        {{0.0f, -2.0f, -2.0f}, {0.0f, 0.0f, 2.0f}, {2.0f, 0.0f, 0.0f}, {0.5f, 0.6f, 0.7f}},  // floor, normal +y
    });
    std::vector<Light> lights;
    for (int i = 0; i < 16; ++i)
        lights.push_back(Light{{-1.5f + 0.2f * i, -1.0f + 0.13f * i, -0.7f - 0.05f * i}, 3.0f, {1.0f, 0.9f, 0.8f}});
    FrameRenderer renderer(scene, lights, smallFrame(scene, CameraPose{{0.5f, 0.3f, -5.0f}, {0.0f, 0.0f, 0.0f}, 50.0f}, 160, 90));
    const ReferenceFrame naive = renderReference(renderer, 0);

    for (MethodKind kind : {MethodKind::Deferred, MethodKind::Visibility}) {
        const std::string name = methodName(kind);
        renderer.setMethod(withGBuffer(kind, GBufferFormat::Packed));
        renderer.render(0);
        expectWithinContract(renderer, naive, "-z wall, packed " + name);

        renderer.setMethod(withGBuffer(kind, GBufferFormat::TwoComponent));
        renderer.render(0);
        const FloatImage twoComponent = renderer.readHdr();
        const ImageDifference d = compareImages(twoComponent, naive.hdr);
        std::printf("-z wall, two-component %s: max %.3f, psnr %.1f dB, bad %.3f\n", name.c_str(), d.maxAbs, d.psnrDb,
                    d.badPixelShare);
        EXPECT_LT(d.psnrDb, 30.0) << name << ": the lost sign of z should show";
        EXPECT_GT(d.badPixelShare, 0.2) << name << ": the whole wall should be wrong";
        // The wall's centre pixel: lit in naive, ambient only in two-component: ambient x (diffuse + f0),
        // a dielectric's f0 being 0.04 (docs/lights-and-shading.md).
        const float* lit = naive.hdr.at(80, 45);
        const float* dark = twoComponent.at(80, 45);
        EXPECT_GT(lit[0], 0.2f) << name;
        EXPECT_NEAR(dark[0], renderer.settings().ambient * (0.8f + 0.04f), 1e-3f) << name;
    }
}

// Normals with z >= 0 survive two-component: its error is confined to z < 0, so a wall facing +z
// is exact.
TEST_F(GBufferLayouts, TwoComponentIsExactWhereZIsNotNegative) {
    const Scene scene = quadScene({{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.8f, 0.7f, 0.6f}}});  // normal +z
    std::vector<Light> lights;
    for (int i = 0; i < 16; ++i)
        lights.push_back(Light{{-1.5f + 0.2f * i, -1.0f + 0.13f * i, 0.7f + 0.05f * i}, 3.0f, {1.0f, 0.9f, 0.8f}});
    FrameRenderer renderer(scene, lights, smallFrame(scene, CameraPose{{0.5f, 0.3f, 5.0f}, {0.0f, 0.0f, 0.0f}, 50.0f}, 160, 90));
    const ReferenceFrame naive = renderReference(renderer, 0);
    renderer.setMethod(withGBuffer(MethodKind::Deferred, GBufferFormat::TwoComponent));
    renderer.render(0);
    expectWithinContract(renderer, naive, "+z wall, two-component deferred");
}

TEST_F(GBufferLayouts, BytesOfEveryLayoutFollowTheFormat) {
    const TestScene t = testScene("boxes", 4, 1);
    FrameSettings s = smallFrame(t.scene, 64, 48);
    FrameRenderer renderer(t.scene, t.lights, s);
    for (GBufferFormat f : {GBufferFormat::Exact, GBufferFormat::Standard, GBufferFormat::Packed, GBufferFormat::TwoComponent}) {
        renderer.setMethod(withGBuffer(MethodKind::Deferred, f));
        renderer.render(0);
        EXPECT_EQ(renderer.method().extraTargetBytes(), 64u * 48u * gbufferBytesPerPixel(f, renderer.scene().materialFeatures()))
            << gbufferFormatName(f);
    }
    // The exact layout's third target (emissive, occlusion) only for scenes that have either.
    EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Exact, 0), 32u);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Exact, ML_FEATURE_NORMAL_MAP | ML_FEATURE_METALLIC_ROUGHNESS_MAP), 32u);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Exact, ML_FEATURE_EMISSIVE), 48u);
    EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Exact, ML_FEATURE_OCCLUSION_MAP), 48u);
    for (std::uint32_t features : {0u, std::uint32_t(ML_FEATURE_EMISSIVE)}) {
        EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Standard, features), 24u);
        EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::Packed, features), 16u);
        EXPECT_EQ(gbufferBytesPerPixel(GBufferFormat::TwoComponent, features), 16u);
    }
}

TEST(GBufferCommand, StatsPrintTheLayoutAndBadValuesAreRefused) {
    std::string output;
    const std::string out = (testOutputDir() / "g.png").string();
    ASSERT_EQ(runManylights("render --scene boxes --size 64x48 --lights 8 --gbuffer packed --stats --out " + out, output), 0)
        << output;
    EXPECT_NE(output.find("G-buffer: packed, 16 B per pixel"), std::string::npos) << output;
    // boxes has no emissive material nor occlusion map: the exact layout stores two targets.
    ASSERT_EQ(runManylights("render --scene boxes --size 64x48 --lights 8 --gbuffer exact --stats --out " + out, output), 0)
        << output;
    EXPECT_NE(output.find("G-buffer: exact, 32 B per pixel"), std::string::npos) << output;
    ASSERT_EQ(runManylights("render --scene boxes --size 64x48 --lights 8 --method forward-plus --gbuffer packed --stats --out " + out,
                            output), 0) << output;
    EXPECT_NE(output.find("--gbuffer is ignored"), std::string::npos) << output;
    EXPECT_NE(runManylights("render --gbuffer octahedral --out " + out, output), 0);
    EXPECT_NE(output.find("--gbuffer 'octahedral'"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
