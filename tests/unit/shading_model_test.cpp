// The falloff and shading formula of docs/lights-and-shading.md, on the CPU.
#include <gtest/gtest.h>

#include "renderer/reference/shading_reference.h"
#include "renderer/reference/tonemap_reference.h"

namespace ml {
namespace {

TEST(Falloff, IsExactlyZeroAtAndBeyondTheRadius) {
    EXPECT_EQ(lightFalloff(2.0f, 2.0f), 0.0f);
    EXPECT_EQ(lightFalloff(2.5f, 2.0f), 0.0f);
    EXPECT_EQ(lightFalloff(1.0f, 0.0f), 0.0f);
    EXPECT_GT(lightFalloff(1.999f, 2.0f), 0.0f);
}

TEST(Falloff, IsOneAtTheCentreAndDecreasing) {
    EXPECT_FLOAT_EQ(lightFalloff(0.0f, 3.0f), 1.0f);
    float previous = 2.0f;
    for (float d = 0.0f; d < 3.0f; d += 0.01f) {
        const float f = lightFalloff(d, 3.0f);
        EXPECT_LE(f, previous) << "at d=" << d;
        previous = f;
    }
}

TEST(Falloff, IsContinuousAtTheRadius) {
    // The window's value and slope both vanish at r: no visible edge where culling cuts off.
    const float r = 4.0f;
    for (float eps : {1e-2f, 1e-3f}) EXPECT_LT(lightFalloff(r - eps, r), 1e-3f) << eps;
    // Largest jump between neighbouring samples stays small everywhere.
    float maxJump = 0.0f;
    for (float d = 0.0f; d < r + 0.1f; d += 1e-3f) maxJump = std::max(maxJump, std::abs(lightFalloff(d + 1e-3f, r) - lightFalloff(d, r)));
    EXPECT_LT(maxJump, 2e-3f);
}

TEST(ShadeReference, LightBehindTheSurfaceAddsNothing) {
    SurfaceSample s{{0, 0, 0}, {0, 1, 0}, {1, 1, 1}};
    const std::vector<Light> below{{{0.0f, -1.0f, 0.0f}, 5.0f, {1, 1, 1}}};
    const glm::vec3 c = shadeReference(s, {0, 5, 5}, below, 0.0f);
    EXPECT_EQ(c, glm::vec3(0.0f));
}

// The seeds' Blinn-Phong mapping (--brdf blinn-phong); glTF's BRDF is held to appendix B in
// light_model_test.cpp.
constexpr LightModel kBlinnPhong{Brdf::BlinnPhong};

TEST(ShadeReference, DiffuseDirectlyAbove) {
    SurfaceSample s{{0, 0, 0}, {0, 1, 0}, {0.5f, 0.5f, 0.5f}, 0.0f, 1.0f};
    const std::vector<Light> above{{{0.0f, 1.0f, 0.0f}, 10.0f, {2, 2, 2}}};
    const glm::vec3 c = shadeReference(s, {0, 5, 0}, above, 0.0f, true, kBlinnPhong);
    // W(1, 10) = (1 - 1e-4)^2 / 2; N.L = 1; roughness 1: shininess 1, N.H = 1, so the specular
    // term is f0 (0.04) times (1 + 8) / 8.
    const float expected = 2.0f * (1.0f - 1e-4f) * (1.0f - 1e-4f) / 2.0f * (0.5f + 0.04f * 9.0f / 8.0f);
    EXPECT_NEAR(c.r, expected, 1e-6f);
}

// --specular off: the highlight's Blinn-Phong term goes, the diffuse term stays exactly.
TEST(ShadeReference, SpecularOffLeavesOnlyTheDiffuseTerm) {
    SurfaceSample shiny{{0, 0, 0}, {0, 1, 0}, {0.5f, 0.5f, 0.5f}, 0.0f, 0.3f};
    const std::vector<Light> above{{{0.0f, 1.0f, 0.0f}, 10.0f, {2, 2, 2}}};
    const glm::vec3 on = shadeReference(shiny, {0, 5, 0}, above, 0.03f, true, kBlinnPhong);
    const glm::vec3 off = shadeReference(shiny, {0, 5, 0}, above, 0.03f, false, kBlinnPhong);
    const ShadingTerms t = shadingTerms(shiny.baseColor, shiny.metallic, shiny.roughness);
    const float w = lightFalloff(1.0f, 10.0f);
    EXPECT_NEAR(off.r, 0.03f * (0.5f + 0.04f) + 2.0f * w * 0.5f, 1e-6f);
    EXPECT_NEAR(on.r - off.r, 2.0f * w * t.specular.r, 1e-4f * on.r);  // the highlight, seen straight on: N.H = 1
    EXPECT_GT(on.r, off.r + 0.5f);
}

// The metallic-roughness mapping: dielectrics keep their colour in the diffuse term and a grey
// 4 % reflectance; metals move all of it into the specular colour.
TEST(ShadingTerms, MetallicRoughnessMapping) {
    const glm::vec3 gold{1.0f, 0.78f, 0.34f};
    const ShadingTerms dielectric = shadingTerms(gold, 0.0f, 0.5f);
    EXPECT_EQ(dielectric.diffuse, gold);
    EXPECT_EQ(dielectric.f0, glm::vec3(0.04f));
    EXPECT_NEAR(dielectric.shininess, 2.0f / 0.0625f - 2.0f, 1e-3f);  // alpha = 0.25
    const ShadingTerms metal = shadingTerms(gold, 1.0f, 0.5f);
    EXPECT_EQ(metal.diffuse, glm::vec3(0.0f));
    EXPECT_EQ(metal.f0, gold);
    EXPECT_EQ(shadingTerms(gold, 0.0f, 1.0f).shininess, 1.0f);     // never pow(0, 0)
    EXPECT_EQ(shadingTerms(gold, 0.0f, 0.0f).shininess, 8192.0f);  // a mirror, bounded
}

TEST(Tonemap, MapsZeroToZeroAndSaturatesBelowOne) {
    EXPECT_EQ(tonemapToSrgb(glm::vec3(0.0f), 1.0f), glm::vec3(0.0f));
    const glm::vec3 big = tonemapToSrgb(glm::vec3(1e6f), 1.0f);
    EXPECT_GT(big.r, 0.99f);
    EXPECT_LE(big.r, 1.0f);
    // Reinhard maps 1 to 0.5, which sRGB encodes as ~0.7354.
    EXPECT_NEAR(tonemapToSrgb(glm::vec3(1.0f), 1.0f).g, 0.7354f, 1e-3f);
}

}  // namespace
}  // namespace ml
