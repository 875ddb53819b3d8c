// The CPU copies of the --cull tests and the exact sphere-frustum distance they are measured
// against (renderer/clustering/cluster_culling.h): the distance agrees with a brute-force search
// over points of the volume, and no test ever rejects a sphere that reaches the volume.
#include <gtest/gtest.h>

#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/clustering/cluster_culling.h"

namespace ml::test {
namespace {

struct GridSetup {
    ClusterGrid grid;
    DepthSlicing slicing;
    glm::mat4 projection;
    int width = 320, height = 180;
};

GridSetup makeGridSetup() {
    GridSetup s;
    s.grid = ClusterGrid::forViewport(ClusterGridConfig{12, 10, Slicing::Log, 64}, s.width, s.height);
    s.slicing = DepthSlicing::make(true, 0.5f, 40.0f, s.grid.slices);
    s.projection = glm::perspective(glm::radians(60.0f), float(s.width) / float(s.height), 0.5f, 40.0f);
    return s;
}

// A random cluster of the grid, its centre and its diagonal.
struct PickedCluster {
    ClusterFrustum volume;
    glm::vec3 centre;
    float size;
    // A random point in a cube `spread` diagonals wide around the centre.
    glm::vec3 pointAround(float spread, std::mt19937& rng) const {
        std::uniform_real_distribution<float> offset(-0.5f, 0.5f);
        return centre + size * spread * glm::vec3(offset(rng), offset(rng), offset(rng));
    }
};
PickedCluster pickCluster(const GridSetup& s, std::mt19937& rng);

// A point of the volume from (u, v, w) in [0, 1]^3: trilinear over the corners (the volume's
// faces are planar, so this stays inside it).
glm::vec3 pointIn(const ClusterFrustum& f, float u, float v, float w) {
    const glm::vec3 near = glm::mix(glm::mix(f.corners[0], f.corners[1], u), glm::mix(f.corners[2], f.corners[3], u), v);
    const glm::vec3 far = glm::mix(glm::mix(f.corners[4], f.corners[5], u), glm::mix(f.corners[6], f.corners[7], u), v);
    return glm::mix(near, far, w);
}

PickedCluster pickCluster(const GridSetup& s, std::mt19937& rng) {
    const std::uint32_t x = rng() % s.grid.tilesX, y = rng() % s.grid.tilesY, slice = rng() % s.grid.slices;
    PickedCluster p;
    p.volume = clusterFrustum(s.grid, s.slicing, 0.5f, 40.0f, s.projection, s.width, s.height, x, y, slice);
    p.centre = pointIn(p.volume, 0.5f, 0.5f, 0.5f);
    p.size = glm::length(p.volume.corners[7] - p.volume.corners[0]);
    return p;
}

TEST(ClusterCulling, ExactDistanceMatchesBruteForce) {
    const GridSetup s = makeGridSetup();
    std::mt19937 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        const PickedCluster picked = pickCluster(s, rng);
        const ClusterFrustum& f = picked.volume;
        const float size = picked.size;
        const glm::vec3 p = picked.pointAround(2.0f, rng);
        const float exact = distanceToCluster(f, p);
        float brute = std::numeric_limits<float>::max();
        constexpr int n = 24;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                for (int k = 0; k <= n; ++k) brute = std::min(brute, glm::length(p - pointIn(f, i / float(n), j / float(n), k / float(n))));
        EXPECT_LE(exact, brute + 1e-4f * size) << "trial " << trial;      // never farther than a point of the volume
        EXPECT_GE(exact, brute - size / n * 1.5f) << "trial " << trial;   // and as close as the sampling can tell
    }
}

TEST(ClusterCulling, NoTestRejectsASphereThatReachesTheCluster) {
    const GridSetup s = makeGridSetup();
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::size_t reaching = 0, passed[3] = {0, 0, 0}, total = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const PickedCluster picked = pickCluster(s, rng);
        const ClusterFrustum& f = picked.volume;
        const glm::vec3 c = picked.pointAround(6.0f, rng);
        const float r = picked.size * (0.05f + 3.0f * unit(rng));
        const bool reaches = distanceToCluster(f, c) < r;
        reaching += reaches;
        ++total;
        int m = 0;
        for (CullMode mode : {CullMode::Aabb, CullMode::Sphere, CullMode::Cone}) {
            const bool pass = passesCullTest(mode, f, c, r);
            if (reaches) {
                EXPECT_TRUE(pass) << cullModeName(mode) << " rejects a reaching sphere, trial " << trial;
            }
            passed[m++] += pass;
        }
    }
    // Each test admits some spheres that miss (false positives), but far from all of them.
    for (std::size_t p : passed) {
        EXPECT_GT(p, reaching);
        EXPECT_LT(p, total);
    }
    EXPECT_GT(reaching, total / 10);
}

}  // namespace
}  // namespace ml::test
