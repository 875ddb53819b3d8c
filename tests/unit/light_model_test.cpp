// The light model on the CPU: glTF's BRDF against the specification's appendix B at fixed points
// (normal and grazing incidence, roughness 0 and 1, metallic 0 and 1) and its energy bounds; the
// falloffs' windows and the guard at the light; the stochastic cut-off's expectation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "renderer/hash.h"
#include "renderer/reference/shading_reference.h"

namespace ml {
namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec3 direction(float polarDeg, float azimuthDeg) {
    const float t = polarDeg * kPi / 180.0f, p = azimuthDeg * kPi / 180.0f;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Appendix B written another way, in double precision: D through tan(theta_h), the
// height-correlated Smith term through Lambda (Heitz 2014), G2 / (4 N.L N.V), not the shaders'
// folded form.
glm::vec3 appendixB(const glm::vec3& base, float metallic, float roughness, const glm::vec3& vf, const glm::vec3& lf) {
    const glm::dvec3 n(0.0, 0.0, 1.0), v(vf), l(lf);
    const double alpha = std::max(double(roughness) * roughness, ML_GGX_MIN_ALPHA);
    const glm::dvec3 h = glm::normalize(v + l);
    const double cosH = glm::dot(n, h);
    const double tan2H = (h.x * h.x + h.y * h.y) / (cosH * cosH);
    const double d = alpha * alpha / (3.14159265358979323846 * std::pow(cosH, 4.0) * std::pow(alpha * alpha + tan2H, 2.0));
    const auto lambda = [&](const glm::dvec3& x) {
        const double c = glm::dot(n, x);
        const double tan2 = (x.x * x.x + x.y * x.y) / (c * c);
        return (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2)) / 2.0;
    };
    const double g2 = 1.0 / (1.0 + lambda(v) + lambda(l));
    const double vis = g2 / (4.0 * glm::dot(n, l) * glm::dot(n, v));
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), glm::dvec3(base), double(metallic));
    const glm::dvec3 fresnel = f0 + (1.0 - f0) * std::pow(1.0 - glm::dot(v, h), 5.0);
    return glm::vec3((1.0 - fresnel) * glm::dvec3(base) * (1.0 - metallic) / 3.14159265358979323846 + fresnel * d * vis);
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
    // alpha = 1: D = 1/pi everywhere, Vis = 0.5 / (N.L + N.V).
    const glm::vec3 v = direction(50.0f, 0.0f), l = direction(70.0f, 130.0f);
    const float fresnel = 1.0f;  // white metal: f0 = 1, so F = 1 at every angle
    const float want = fresnel / kPi * 0.5f / (v.z + l.z);
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

// A white metal's lobe is single scattering: it never reflects more than arrives, and loses up
// to about 70 % at roughness 1 (the energy of light bouncing between microfacets, which no term
// models). A white dielectric stays within 0.2 % of 1 up to a 45-degree view; at grazing views
// glTF's layering gains energy (up to 22 % at roughness 0.3 and 80 degrees): it weights the
// diffuse by 1 - F(V.H) per light direction, not by the specular lobe's directional albedo.
TEST(GgxBrdf, ReflectsNoMoreThanArrivesSaveGltfsLayeringAtGrazingViews) {
    for (float roughness : {0.3f, 0.6f, 1.0f}) {
        for (float viewDeg : {0.0f, 45.0f, 80.0f}) {
            const std::string what = "roughness " + std::to_string(roughness) + " view " + std::to_string(viewDeg);
            const float metal = directionalAlbedo(glm::vec3(1.0f), 1.0f, roughness, viewDeg).r;
            const float dielectric = directionalAlbedo(glm::vec3(1.0f), 0.0f, roughness, viewDeg).r;
            std::printf("%s: white metal %.4f, white dielectric %.4f\n", what.c_str(), metal, dielectric);
            EXPECT_LE(metal, 1.002f) << what;
            EXPECT_GE(metal, 0.25f) << what;
            EXPECT_LE(dielectric, viewDeg <= 45.0f ? 1.002f : 1.25f) << what;
            EXPECT_GE(dielectric, 0.95f) << what;
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
