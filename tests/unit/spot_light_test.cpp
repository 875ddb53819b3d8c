// Spot lights on the CPU: glTF's angular attenuation (zero at and outside the outer cone, one
// inside the inner, continuous), the shading reference's spots and suns, and the cone tests
// of the clustering (renderer/clustering/spot_cone.h, mirroring glsl/include/spot_cone.glsl):
// none ever rejects a sphere, box or cluster that holds a lit point, on many random cones.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/clustering/cluster_culling.h"
#include "renderer/clustering/spot_cone.h"
#include "renderer/reference/shading_reference.h"

namespace ml::test {
namespace {

constexpr float kPi = 3.14159265358979f;

TEST(SpotAttenuation, IsZeroOutsideTheOuterConeOneInsideTheInnerAndContinuous) {
    for (float outerDeg : {5.0f, 30.0f, 60.0f, 90.0f}) {
        for (float innerShare : {0.0f, 0.5f, 0.9f, 1.0f}) {
            const float cosOuter = std::cos(outerDeg * kPi / 180.0f), cosInner = std::cos(innerShare * outerDeg * kPi / 180.0f);
            float previous = 0.0f;
            for (int i = 0; i <= 20000; ++i) {
                const float angle = kPi * i / 20000.0f;  // 0 to 180 degrees off the axis
                const float c = std::cos(angle);
                const float a = spotAttenuation(c, cosInner, cosOuter);
                if (c <= cosOuter) {
                    EXPECT_EQ(a, 0.0f) << outerDeg << " deg, angle " << angle;
                } else if (c >= cosInner) {
                    EXPECT_EQ(a, 1.0f) << outerDeg << " deg, angle " << angle;
                }
                EXPECT_GE(a, 0.0f);
                EXPECT_LE(a, 1.0f);
                // Continuous: a small step in angle makes a small step in attenuation (a hard
                // edge only where inner equals outer).
                if (i > 0 && innerShare < 1.0f) {
                    EXPECT_LE(std::abs(a - previous), 0.05f) << outerDeg << " deg, angle " << angle;
                }
                previous = a;
            }
        }
    }
    // glTF's example: linear in the cosine, squared.
    EXPECT_FLOAT_EQ(spotAttenuation(0.75f, 1.0f, 0.5f), 0.25f);
}

TEST(SpotShading, ASpotIsAPointLightInsideItsInnerConeAndDarkOutsideItsOuterCone) {
    Light point{{0.0f, 2.0f, 0.0f}, 10.0f, {1.0f, 0.8f, 0.6f}};
    Light spot = point;
    spot.type = LightType::Spot;
    spot.direction = {0.0f, -3.0f, 0.0f};  // not unit: normalised where used
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.5f;
    for (float x = 0.0f; x < 3.0f; x += 0.01f) {
        SurfaceSample s{{x, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.7f, 0.7f, 0.7f}};
        const float angle = std::atan2(x, 2.0f);
        const glm::vec3 lit = shadeReference(s, {0.0f, 5.0f, 5.0f}, {spot}, 0.0f);
        const glm::vec3 full = shadeReference(s, {0.0f, 5.0f, 5.0f}, {point}, 0.0f);
        if (angle < 0.3f - 1e-4f) {
            EXPECT_EQ(lit, full) << x;
        }
        if (angle > 0.5f + 1e-4f) {
            EXPECT_EQ(lit, glm::vec3(0.0f)) << x;
        }
        EXPECT_LE(lit.r, full.r);
    }
}

TEST(SpotShading, ASunLightsEveryPointFacingItAlike) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, -1.0f, 0.0f};
    sun.color = glm::vec3(0.5f);
    for (float x : {-100.0f, 0.0f, 1e4f}) {
        SurfaceSample up{{x, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
        // Blinn-Phong's Lambert has no 1/pi: the sun's colour itself on a white surface.
        EXPECT_NEAR(shadeReference(up, {x, 5.0f, 0.0f}, {sun}, 0.0f, false, LightModel{Brdf::BlinnPhong}).r, 0.5f, 1e-6f);
        SurfaceSample down{{x, 0.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
        EXPECT_EQ(shadeReference(down, {x, -5.0f, 0.0f}, {sun}, 0.0f), glm::vec3(0.0f));
    }
}

// A random spot and a random point its light reaches (inside its cone and radius).
struct LitPoint {
    SpotCone cone;
    glm::vec3 point;
};

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    glm::vec3 v;
    do v = glm::vec3(n(rng), n(rng), n(rng));
    while (glm::dot(v, v) < 1e-6f);
    return glm::normalize(v);
}

SpotCone randomCone(std::mt19937& rng, const glm::vec3& apex) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    SpotCone c;
    c.apex = apex;
    c.axis = randomUnit(rng);
    c.cosOuter = std::cos((1.0f + 89.0f * unit(rng)) * kPi / 180.0f);
    c.radius = 0.1f + 5.0f * unit(rng);
    return c;
}

// A point inside the cone's lit sector: off the axis by less than the outer angle, nearer than r.
glm::vec3 pointInSector(const SpotCone& c, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const glm::vec3 side = glm::normalize(glm::cross(c.axis, std::abs(c.axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(c.axis, side);
    const float off = std::acos(c.cosOuter) * unit(rng) * 0.999f, around = 2.0f * kPi * unit(rng);
    const glm::vec3 dir = std::cos(off) * c.axis + std::sin(off) * (std::cos(around) * side + std::sin(around) * up);
    return c.apex + dir * (c.radius * 0.999f * std::cbrt(unit(rng)));
}

TEST(SpotCone, NoBoundRejectsALitPoint) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 100000; ++trial) {
        const SpotCone c = randomCone(rng, glm::vec3(unit(rng), unit(rng), unit(rng)) * 40.0f - 20.0f);
        const glm::vec3 p = pointInSector(c, rng);
        const glm::vec4 sphere = spotBoundingSphere(c);
        EXPECT_LE(glm::length(p - glm::vec3(sphere)), sphere.w) << "bounding sphere, trial " << trial;
        const Aabb box = spotBounds(c);
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max))) << "box, trial " << trial;
        const glm::vec3 n = randomUnit(rng);
        EXPECT_GE(spotReach(c, n) * (1.0f + 1e-5f) + 1e-5f, glm::dot(p - c.apex, n)) << "support, trial " << trial;
        // Any sphere holding the point, however small, passes Wronski's test.
        const float r = 0.001f + 3.0f * unit(rng) * unit(rng);
        const glm::vec3 centre = p + randomUnit(rng) * (r * unit(rng));
        EXPECT_TRUE(spotMayReachSphere(c, centre, r)) << "cone vs sphere, trial " << trial;
    }
}

TEST(SpotCone, TheBoundsAreTighterThanTheSphereForNarrowCones) {
    SpotCone c;
    c.apex = glm::vec3(0.0f);
    c.axis = {0.0f, 0.0f, -1.0f};
    c.cosOuter = std::cos(20.0f * kPi / 180.0f);
    c.radius = 4.0f;
    EXPECT_LT(spotBoundingSphere(c).w, 0.6f * c.radius);
    const Aabb box = spotBounds(c);
    EXPECT_NEAR(box.min.z, -4.0f, 1e-3f);
    EXPECT_NEAR(box.max.z, 0.0f, 1e-3f);
    EXPECT_NEAR(box.max.x, 4.0f * std::sin(20.0f * kPi / 180.0f), 1e-3f);
    // A sphere behind the apex, or beside the cone, is rejected.
    EXPECT_FALSE(spotMayReachSphere(c, {0.0f, 0.0f, 2.0f}, 1.0f));
    EXPECT_FALSE(spotMayReachSphere(c, {3.0f, 0.0f, -2.0f}, 1.0f));
    EXPECT_TRUE(spotMayReachSphere(c, {0.0f, 0.0f, -2.0f}, 0.1f));
}

struct GridSetup {
    ClusterGrid grid = ClusterGrid::forViewport(ClusterGridConfig{12, 10, Slicing::Log, 64}, 320, 180);
    DepthSlicing slicing = DepthSlicing::make(true, 0.5f, 40.0f, 10);
    glm::mat4 projection = glm::perspective(glm::radians(60.0f), 320.0f / 180.0f, 0.5f, 40.0f);
};

glm::vec3 pointIn(const ClusterFrustum& f, float u, float v, float w) {
    const glm::vec3 near = glm::mix(glm::mix(f.corners[0], f.corners[1], u), glm::mix(f.corners[2], f.corners[3], u), v);
    const glm::vec3 far = glm::mix(glm::mix(f.corners[4], f.corners[5], u), glm::mix(f.corners[6], f.corners[7], u), v);
    return glm::mix(near, far, w);
}

TEST(SpotCone, NoCullTestRejectsASpotThatLightsAPointOfTheCluster) {
    const GridSetup s;
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::size_t passed[3] = {0, 0, 0}, exact = 0;
    const int trials = 20000;
    for (int trial = 0; trial < trials; ++trial) {
        const std::uint32_t x = rng() % s.grid.tilesX, y = rng() % s.grid.tilesY, slice = rng() % s.grid.slices;
        const ClusterFrustum f = clusterFrustum(s.grid, s.slicing, 0.5f, 40.0f, s.projection, 320, 180, x, y, slice);
        // A point of the cluster, and a spot that lights it from somewhere around.
        const glm::vec3 p = pointIn(f, unit(rng), unit(rng), unit(rng));
        SpotCone c = randomCone(rng, glm::vec3(0.0f));
        const float distance = c.radius * (0.05f + 0.9f * unit(rng));
        // The apex on a ray from p inside the cone's reverse: the axis is off the ray by less than the outer angle.
        const glm::vec3 towardsApex = -glm::normalize(pointInSector(SpotCone{glm::vec3(0.0f), c.axis, c.cosOuter, 1.0f}, rng));
        c.apex = p + towardsApex * distance;
        EXPECT_TRUE(lightReachesCluster(f, c)) << "exact (GJK) test, trial " << trial;
        exact += lightReachesCluster(f, c);
        int m = 0;
        for (CullMode mode : {CullMode::Aabb, CullMode::Sphere, CullMode::Cone}) {
            const bool pass = passesLightCullTest(mode, f, c);
            EXPECT_TRUE(pass) << cullModeName(mode) << " rejects a spot lighting the cluster, trial " << trial;
            passed[m++] += pass;
        }
    }
    EXPECT_EQ(exact, std::size_t(trials));
}

TEST(SpotCone, TheExactTestAgreesWithSampledPoints) {
    const GridSetup s;
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::size_t meets = 0, misses = 0, rejectedByCull = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const std::uint32_t x = rng() % s.grid.tilesX, y = rng() % s.grid.tilesY, slice = rng() % s.grid.slices;
        const ClusterFrustum f = clusterFrustum(s.grid, s.slicing, 0.5f, 40.0f, s.projection, 320, 180, x, y, slice);
        const glm::vec3 centre = pointIn(f, 0.5f, 0.5f, 0.5f);
        const float size = glm::length(f.corners[7] - f.corners[0]);
        SpotCone c = randomCone(rng, centre + randomUnit(rng) * size * 2.0f * unit(rng));
        c.radius = size * (0.2f + 2.0f * unit(rng));
        // Sampled points of the volume inside the sector: the exact test must say it meets.
        bool sampledHit = false;
        constexpr int n = 8;
        for (int i = 0; i <= n && !sampledHit; ++i)
            for (int j = 0; j <= n && !sampledHit; ++j)
                for (int k = 0; k <= n && !sampledHit; ++k) {
                    const glm::vec3 q = pointIn(f, i / float(n), j / float(n), k / float(n)) - c.apex;
                    const float d = glm::length(q);
                    sampledHit = d < c.radius && d > 0.0f && glm::dot(q / d, c.axis) > c.cosOuter;
                }
        const bool exact = lightReachesCluster(f, c);
        if (sampledHit) {
            EXPECT_TRUE(exact) << "trial " << trial;
        }
        meets += exact;
        misses += !exact;
        if (exact) {
            EXPECT_TRUE(passesLightCullTest(CullMode::Aabb, f, c)) << "trial " << trial;
        } else {
            rejectedByCull += !passesLightCullTest(CullMode::Aabb, f, c);
        }
    }
    // Both outcomes occur, and the conservative test rejects some of the misses.
    EXPECT_GT(meets, 300u);
    EXPECT_GT(misses, 300u);
    EXPECT_GT(rejectedByCull, misses / 4);
}

}  // namespace
}  // namespace ml::test
