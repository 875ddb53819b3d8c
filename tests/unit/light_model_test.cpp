// The light model on the CPU: glTF's BRDF against the specification's appendix B at fixed points
// (normal and grazing incidence, roughness 0 and 1, metallic 0 and 1) and its energy bounds; the
// falloffs' windows and the guard at the light; the stochastic cut-off's expectation.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/hash.h"
#include "renderer/reference/shading_reference.h"

namespace ml {
namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec3 direction(float polarDeg, float azimuthDeg) {
    const float t = polarDeg * kPi / 180.0f, p = azimuthDeg * kPi / 180.0f;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Appendix B written another way: D through tan(theta_h), the height-correlated Smith term
// through Lambda (Heitz 2014), G2 / (4 N.L N.V), not the shaders' folded form.
glm::vec3 appendixB(const glm::vec3& base, float metallic, float roughness, const glm::vec3& v, const glm::vec3& l) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const float alpha = std::max(roughness * roughness, static_cast<float>(ML_GGX_MIN_ALPHA));
    const glm::vec3 h = glm::normalize(v + l);
    const float cosH = glm::dot(n, h);
    const float tan2H = (1.0f - cosH * cosH) / (cosH * cosH);
    const float d = alpha * alpha / (kPi * std::pow(cosH, 4.0f) * std::pow(alpha * alpha + tan2H, 2.0f));
    const auto lambda = [&](const glm::vec3& x) {
        const float c = glm::dot(n, x);
        const float tan2 = (1.0f - c * c) / (c * c);
        return (-1.0f + std::sqrt(1.0f + alpha * alpha * tan2)) / 2.0f;
    };
    const float g2 = 1.0f / (1.0f + lambda(v) + lambda(l));
    const float vis = g2 / (4.0f * glm::dot(n, l) * glm::dot(n, v));
    const glm::vec3 f0 = glm::mix(glm::vec3(0.04f), base, metallic);
    const glm::vec3 fresnel = f0 + (1.0f - f0) * std::pow(1.0f - glm::dot(v, h), 5.0f);
    return (1.0f - fresnel) * base * (1.0f - metallic) / kPi + fresnel * d * vis;
}

glm::vec3 brdf(const glm::vec3& base, float metallic, float roughness, const glm::vec3& v, const glm::vec3& l) {
    return ggxBrdf(shadingTerms(base, metallic, roughness), {0.0f, 0.0f, 1.0f}, v, l);
}

void expectNearRelative(const glm::vec3& got, const glm::vec3& want, float relative, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], relative * std::abs(want[c]) + 1e-7f) << what << " channel " << c;
}

TEST(GgxBrdf, AtNormalIncidenceHasTheClosedForm) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    // N.L = N.V = N.H = 1: D = 1 / (pi alpha^2), Vis = 1/4, F = f0.
    const glm::vec3 base(1.0f, 0.5f, 0.25f);
    expectNearRelative(brdf(base, 1.0f, 1.0f, n, n), base / (4.0f * kPi), 1e-5f, "metal, roughness 1");
    expectNearRelative(brdf(glm::vec3(0.5f), 0.0f, 1.0f, n, n), glm::vec3(0.96f * 0.5f / kPi + 0.04f / (4.0f * kPi)), 1e-5f,
                       "dielectric, roughness 1");
    // Roughness 0: alpha at its floor, the mirror's peak finite and large.
    const float a = static_cast<float>(ML_GGX_MIN_ALPHA);
    expectNearRelative(brdf(glm::vec3(1.0f), 1.0f, 0.0f, n, n), glm::vec3(1.0f / (4.0f * kPi * a * a)), 1e-4f, "mirror");
}

TEST(GgxBrdf, RoughnessOneHasAUniformDistribution) {
    // alpha = 1: D = 1/pi everywhere, Vis = 1 / ((N.L + 1)(N.V + 1)).
    const glm::vec3 v = direction(50.0f, 0.0f), l = direction(70.0f, 130.0f);
    const float fresnel = 1.0f;  // white metal: f0 = 1, so F = 1 at every angle
    const float want = fresnel / kPi / ((v.z + 1.0f) * (l.z + 1.0f));
    expectNearRelative(brdf(glm::vec3(1.0f), 1.0f, 1.0f, v, l), glm::vec3(want), 1e-5f, "roughness 1");
}

TEST(GgxBrdf, MatchesAppendixBAtFixedPoints) {
    struct Point {
        float viewDeg, lightDeg, azimuthDeg, roughness, metallic;
    };
    const Point points[] = {
        {0, 0, 0, 0.5f, 0}, {30, 30, 180, 0.5f, 1}, {60, 20, 90, 0.25f, 0}, {45, 45, 180, 0.0f, 1},  // roughness 0 at the mirror
        {10, 40, 0, 0.0f, 0},                                                                        // roughness 0 off it
        {89, 89, 180, 0.5f, 0}, {89, 89, 180, 0.5f, 1}, {88, 5, 180, 1.0f, 0},                       // grazing
        {85, 85, 0, 0.1f, 1}, {70, 80, 45, 1.0f, 1}, {20, 75, 270, 0.7f, 0.5f},
    };
    const glm::vec3 base(0.9f, 0.6f, 0.3f);
    for (const Point& p : points) {
        const glm::vec3 v = direction(p.viewDeg, 0.0f), l = direction(p.lightDeg, p.azimuthDeg);
        const std::string what = "view " + std::to_string(p.viewDeg) + " light " + std::to_string(p.lightDeg) + " azimuth " +
                                 std::to_string(p.azimuthDeg) + " roughness " + std::to_string(p.roughness) + " metallic " +
                                 std::to_string(p.metallic);
        expectNearRelative(brdf(base, p.metallic, p.roughness, v, l), appendixB(base, p.metallic, p.roughness, v, l), 2e-3f, what);
    }
}

// sum of f * N.L over the hemisphere of light directions (midpoint rule in cos theta and phi).
glm::vec3 directionalAlbedo(const glm::vec3& base, float metallic, float roughness, float viewDeg) {
    const glm::vec3 v = direction(viewDeg, 0.0f);
    const int nu = 800, np = 400;
    glm::vec3 sum(0.0f);
    for (int i = 0; i < nu; ++i) {
        const float c = (i + 0.5f) / nu;  // cos theta: dw = d(cos theta) d(phi)
        const float s = std::sqrt(1.0f - c * c);
        for (int j = 0; j < np; ++j) {
            const float phi = 2.0f * kPi * (j + 0.5f) / np;
            const glm::vec3 l(s * std::cos(phi), s * std::sin(phi), c);
            sum += brdf(base, metallic, roughness, v, l) * c;
        }
    }
    return sum * (2.0f * kPi / (static_cast<float>(nu) * np));
}

TEST(GgxBrdf, ReflectsNoMoreThanArrives) {
    for (float metallic : {0.0f, 1.0f}) {
        for (float roughness : {0.3f, 0.6f, 1.0f}) {
            for (float viewDeg : {0.0f, 45.0f, 80.0f}) {
                const float albedo = directionalAlbedo(glm::vec3(1.0f), metallic, roughness, viewDeg).r;
                const std::string what = "metallic " + std::to_string(metallic) + " roughness " + std::to_string(roughness) +
                                         " view " + std::to_string(viewDeg);
                EXPECT_LE(albedo, 1.0f + 1e-3f) << what;
                // Single scattering loses energy at high roughness, never most of it.
                EXPECT_GE(albedo, 0.6f) << what;
            }
        }
    }
    // A black dielectric reflects only its 4 % Fresnel at normal view: well under a tenth.
    EXPECT_LT(directionalAlbedo(glm::vec3(0.0f), 0.0f, 0.5f, 0.0f).r, 0.1f);
}

TEST(LightModelFalloff, GltfWindowsTheInverseSquareToZeroAtTheRange) {
    const LightModel gltf{Brdf::Ggx, Falloff::Gltf, 0.0f};
    EXPECT_EQ(lightFalloff(3.0f, 3.0f, 1.0f, gltf), 0.0f);
    EXPECT_EQ(lightFalloff(4.0f, 3.0f, 1.0f, gltf), 0.0f);
    EXPECT_NEAR(lightFalloff(1.5f, 3.0f, 1.0f, gltf), (1.0f - 1.0f / 16.0f) / (1.5f * 1.5f), 1e-6f);
    EXPECT_NEAR(lightFalloff(0.3f, 100.0f, 1.0f, gltf), 1.0f / 0.09f, 1e-3f);  // far inside: inverse square
}

TEST(LightModelFalloff, TheGuardCapsEveryFalloffButTheSeedsAtTheMinimumDistance) {
    const float dmin = static_cast<float>(ML_LIGHT_MIN_DISTANCE);
    for (Falloff f : {Falloff::Gltf, Falloff::Stochastic, Falloff::Untruncated}) {
        const LightModel m{Brdf::Ggx, f, 0.01f};
        const float cap = 1.0f / (dmin * dmin);
        EXPECT_NEAR(lightFalloff(0.0f, 5.0f, 1.0f, m), cap, cap * 1e-4f) << falloffName(f);
        EXPECT_NEAR(lightFalloff(dmin * 0.5f, 5.0f, 1.0f, m), cap, cap * 1e-4f) << falloffName(f);
        EXPECT_TRUE(std::isfinite(lightFalloff(0.0f, 5.0f, 1.0f, m)));
    }
    EXPECT_FLOAT_EQ(lightFalloff(0.0f, 5.0f), 1.0f);  // the seeds' 1 / (d^2 + 1) needs none
}

TEST(LightModelFalloff, UntruncatedIgnoresTheRadius) {
    const LightModel m{Brdf::Ggx, Falloff::Untruncated, 0.0f};
    EXPECT_NEAR(lightFalloff(50.0f, 1.0f, 1.0f, m), 1.0f / 2500.0f, 1e-9f);
}

TEST(LightModelFalloff, CutoffRadiusIsWhereTheInverseSquareFallsToE) {
    const glm::vec3 color(0.2f, 4.0f, 1.0f);
    const float r = cutoffRadius(color, 0.01f);
    EXPECT_NEAR(4.0f / (r * r), 0.01f, 1e-6f);
    EXPECT_NEAR(radiusWithoutRange(color), std::sqrt(4.0f * 255.0f), 1e-3f);  // the default cut-off: 1/255
}

// Over the draws, a light reaches distance d with probability min(1, (r_E / d)^2) and shows
// E / I there, so the expected falloff is the untruncated 1 / d^2 at every distance.
TEST(StochasticCutoff, ExpectationIsTheUntruncatedInverseSquare) {
    const glm::vec3 color(2.0f, 1.0f, 0.5f);
    const float cutoff = 0.05f;
    const LightModel m{Brdf::Ggx, Falloff::Stochastic, cutoff};
    const float rE = cutoffRadius(color, cutoff);
    for (float d : {0.5f * rE, 0.99f * rE, 1.5f * rE, 3.0f * rE, 10.0f * rE}) {
        // Quadrature over xi in (0, 1] (midpoint rule), then the hash's own draws over 400,000 lights.
        const int steps = 1'000'000;
        double quadrature = 0.0;
        for (int i = 0; i < steps; ++i) {
            const float xi = (i + 0.5f) / steps;
            quadrature += lightFalloff(d, rE / std::sqrt(xi), 2.0f, m);
        }
        quadrature /= steps;
        double drawn = 0.0;
        const int lights = 400'000;
        for (int i = 0; i < lights; ++i) drawn += lightFalloff(d, stochasticRadius(color, cutoff, i, 0x1234u), 2.0f, m);
        drawn /= lights;
        const double want = 1.0 / (d * d);
        EXPECT_NEAR(quadrature, want, 1e-3 * want) << "d = " << d;
        // Relative standard error of the draws: sqrt((d / r_E)^2 - 1) / sqrt(400,000), below 2 % up to 10 r_E.
        EXPECT_NEAR(drawn, want, 0.04 * want) << "d = " << d;
    }
}

TEST(StochasticCutoff, RangesAreAtLeastTheCutoffRadiusAndDeterministicPerDraw) {
    const glm::vec3 color(1.0f);
    const float rE = cutoffRadius(color, 0.1f);
    const std::uint32_t seedA = stochasticDrawSeed(60, 0), seedB = stochasticDrawSeed(60, 1);
    EXPECT_NE(seedA, seedB);
    EXPECT_NE(seedA, stochasticDrawSeed(61, 0));
    int differing = 0;
    for (std::uint32_t i = 0; i < 1000; ++i) {
        const float a = stochasticRadius(color, 0.1f, i, seedA);
        EXPECT_GE(a, rE);
        EXPECT_EQ(a, stochasticRadius(color, 0.1f, i, seedA));
        differing += a != stochasticRadius(color, 0.1f, i, seedB);
    }
    EXPECT_GT(differing, 990);
}

}  // namespace
}  // namespace ml
