// The GPU's light lists against a CPU reference built here from the grid maths of
// renderer/clustering/cluster_grid.h and cluster_culling.h, for every --cull test and both exact
// assignments: no light that reaches a cluster (exact sphere-frustum distance) may be missing
// from its list, and no light the CPU's cull test rejects may be listed. False positives
// (listed lights that reach no point of the cluster) are counted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "gpu_test.h"
#include "renderer/clustering/cluster_culling.h"
#include "renderer/clustering/spot_cone.h"
#include "renderer/clustering/clustered_lighting.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

struct AssignmentCase {
    const char* scene;
    std::uint32_t lights;
    std::uint32_t tilesX, slices;
    Slicing slicing;
    bool activeOnly;
    CullMode cull = CullMode::Aabb;
    AssignMode assign = AssignMode::Exact;
    float spotShare = 0.0f;
};

class LightAssignment : public GpuTest, public ::testing::WithParamInterface<AssignmentCase> {};

TEST_P(LightAssignment, ListsMatchTheCpuReference) {
    const AssignmentCase c = GetParam();
    const TestScene t = testScene(c.scene, c.lights, 11, c.spotShare > 0.0f ? 1.0f : 0.5f, c.spotShare);
    const Scene& scene = t.scene;
    FrameSettings s = smallFrame(scene, 200, 120);
    s.method.kind = MethodKind::Deferred;
    s.method.clustering.grid = ClusterGridConfig{c.tilesX, c.slices, c.slicing, 64};
    s.method.clustering.activeOnly = c.activeOnly;
    s.method.clustering.cull = c.cull;
    s.method.clustering.assign = c.assign;
    FrameRenderer renderer(scene, t.lights, s);
    renderer.render(20);
    const ClusteredLighting& clustering = *renderer.method().clustering();
    const ClusterGrid& grid = clustering.grid();
    const ClusterGridGpu g = clustering.downloadGrid();
    const auto aabbs = clustering.downloadAabbs();
    const auto lists = clustering.downloadLists();
    const auto lights = clusteredLights(renderer.lights().downloadAnimated());
    const glm::mat4 view = renderer.uniforms().view, proj = renderer.uniforms().proj;
    const float cameraNear = s.camera.nearPlane, cameraFar = s.camera.farPlane;
    const DepthSlicing slicing{g.tile.y > 0.5f, g.slicing.x, g.slicing.y, g.slicing.z, g.slicing.w};
    if (c.slicing == Slicing::Fitted) {
        EXPECT_GT(slicing.zNear, cameraNear) << "fitted range should start at the nearest visible sample";
        EXPECT_LT(slicing.zFar, cameraFar);
    }

    std::size_t missing = 0, outsideBox = 0, rejectedListed = 0, looseInVolume = 0, references = 0;
    std::vector<glm::vec3> centers;
    std::vector<SpotCone> cones, narrower, wider;  // a spot's sector; shrunk and grown a little against rounding
    for (const Light& l : lights) {
        centers.push_back(glm::vec3(view * glm::vec4(l.position, 1.0f)));
        cones.push_back(spotConeOf(l, view));
        narrower.push_back(cones.back());
        wider.push_back(cones.back());
        narrower.back().radius *= 1.0f - 1e-3f;
        wider.back().radius *= 1.0f + 1e-3f;
        if (l.type == LightType::Spot) {
            narrower.back().cosOuter = std::cos(l.outerConeAngle - 1e-3f);
            wider.back().cosOuter = std::cos(std::min(l.outerConeAngle + 1e-3f, 1.5707963f));
        }
    }
    std::size_t spotReferences = 0, spotsOutsideCone = 0;
    for (std::uint32_t slice = 0; slice < grid.slices; ++slice) {
        for (std::uint32_t y = 0; y < grid.tilesY; ++y) {
            for (std::uint32_t x = 0; x < grid.tilesX; ++x) {
                const std::uint32_t cluster = grid.index(x, y, slice);
                const Aabb box = clusterBounds(grid, slicing, cameraNear, cameraFar, proj, s.width, s.height, x, y, slice);
                // The GPU's box is the CPU's, up to float rounding.
                const float tolerance = 1e-4f * (1.0f + glm::length(box.max - box.min));
                ASSERT_LT(glm::length(glm::vec3(aabbs[cluster].minPoint) - box.min), tolerance) << "cluster " << cluster;
                ASSERT_LT(glm::length(glm::vec3(aabbs[cluster].maxPoint) - box.max), tolerance) << "cluster " << cluster;
                const std::set<std::uint32_t> listed(lists[cluster].begin(), lists[cluster].end());
                EXPECT_EQ(listed.size(), lists[cluster].size()) << "duplicate light in cluster " << cluster;
                // Sorted where the sums need it; with --light-sum fixed the fill's order stands.
                if (renderer.settings().method.clustering.lightSum == LightSum::Float) {
                    EXPECT_TRUE(std::is_sorted(lists[cluster].begin(), lists[cluster].end()))
                        << "cluster " << cluster << ": list not in light-index order";
                }
                references += lists[cluster].size();
                const ClusterFrustum volume = clusterFrustum(grid, slicing, cameraNear, cameraFar, proj, s.width, s.height, x, y, slice);
                for (std::uint32_t i = 0; i < lights.size(); ++i) {
                    const bool isListed = listed.count(i) > 0;
                    if (cones[i].isSpot()) {
                        // A spot: listed only when the CPU's copy of the whole test passes, never
                        // missing where its sector (exact, GJK) lights a point of the volume.
                        rejectedListed += isListed && !passesLightCullTest(c.cull, volume, wider[i]);
                        const bool reaches = lightReachesCluster(volume, narrower[i]);
                        if (reaches && !isListed && !c.activeOnly && ++missing <= 5)
                            ADD_FAILURE() << "spot " << i << " missing from cluster " << x << "," << y << " slice " << slice;
                        spotReferences += isListed;
                        const bool outside = !lightReachesCluster(volume, cones[i]);
                        spotsOutsideCone += isListed && outside;
                        looseInVolume += isListed && outside;
                        continue;
                    }
                    const float r = lights[i].radius;
                    // Listed only when the CPU's copy of the cull test (with a little slack) passes.
                    rejectedListed += isListed && !passesCullTest(c.cull, volume, centers[i], r * (1.0f + 1e-3f));
                    if (distanceSquared(box, centers[i]) > r * r * (1.0f + 1e-3f)) {
                        // The sphere misses the box, so the cluster: never listed by the AABB test; the
                        // others may list it (a false positive).
                        if (c.cull == CullMode::Aabb) outsideBox += isListed;
                        looseInVolume += isListed;
                        continue;
                    }
                    const float distance = distanceToCluster(volume, centers[i]);
                    const bool reaches = distance < r * (1.0f - 1e-3f);
                    if (reaches && !isListed && !c.activeOnly) {
                        if (++missing <= 5)
                            ADD_FAILURE() << "light " << i << " (view centre " << centers[i].x << "," << centers[i].y << ","
                                          << centers[i].z << ", r " << r << ", distance " << distance << ") missing from cluster "
                                          << x << "," << y << " slice " << slice << " (cull " << cullModeName(c.cull) << ")";
                    }
                    looseInVolume += isListed && distance >= r;
                }
            }
        }
    }
    EXPECT_EQ(missing, 0u) << "light-cluster pairs missing from the lists";
    EXPECT_EQ(outsideBox, 0u) << "listed lights whose sphere misses the cluster's box";
    EXPECT_EQ(rejectedListed, 0u) << "listed lights the CPU's " << cullModeName(c.cull) << " test rejects";
    // False positives against the cluster's exact volume: the price of the cull test.
    RecordProperty("references", static_cast<int>(references));
    RecordProperty("false_positives", static_cast<int>(looseInVolume));
    std::printf("cull %s, assign %s: %zu references, %zu (%.1f %%) listed without reaching the cluster\n",
                cullModeName(c.cull), assignModeName(c.assign), references, looseInVolume,
                references ? 100.0 * looseInVolume / references : 0.0);
    if (spotReferences > 0)
        std::printf("  spots: %zu references, %zu (%.1f %%) whose sector reaches no point of the cluster\n", spotReferences,
                    spotsOutsideCone, 100.0 * spotsOutsideCone / spotReferences);
    if (c.lights > 0) {
        EXPECT_GT(references, 0u);
    }
    if (c.spotShare > 0.0f) {
        EXPECT_GT(spotReferences, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(Grids, LightAssignment,
    ::testing::Values(AssignmentCase{"boxes", 64, 16, 8, Slicing::Linear, false},
                      AssignmentCase{"boxes", 64, 7, 5, Slicing::Log, false},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false},
                      AssignmentCase{"atrium", 200, 13, 9, Slicing::Fitted, true},
                      AssignmentCase{"atrium", 0, 8, 4, Slicing::Fitted, false},
                      AssignmentCase{"boxes", 64, 16, 8, Slicing::Linear, false, CullMode::Sphere},
                      AssignmentCase{"boxes", 64, 7, 5, Slicing::Log, false, CullMode::Cone},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Sphere},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Cone},
                      AssignmentCase{"atrium", 200, 13, 9, Slicing::Fitted, true, CullMode::Cone},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Cone, AssignMode::Capped},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Aabb, AssignMode::PerCluster},
                      AssignmentCase{"boxes", 64, 7, 5, Slicing::Log, false, CullMode::Sphere, AssignMode::PerCluster},
                      AssignmentCase{"atrium", 200, 13, 9, Slicing::Fitted, true, CullMode::Cone, AssignMode::PerCluster},
                      // Half the lights spots: every cull test and assignment takes their cones.
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Aabb, AssignMode::Exact, 0.5f},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Sphere, AssignMode::Exact, 0.5f},
                      AssignmentCase{"boxes", 64, 7, 5, Slicing::Log, false, CullMode::Cone, AssignMode::Exact, 0.5f},
                      AssignmentCase{"atrium", 200, 24, 16, Slicing::Fitted, false, CullMode::Aabb, AssignMode::Capped, 0.5f},
                      AssignmentCase{"atrium", 200, 13, 9, Slicing::Fitted, false, CullMode::Cone, AssignMode::PerCluster, 0.5f}),
    [](const auto& info) {
        const AssignmentCase& c = info.param;
        return testNameOf(std::string(c.scene) + "_" + std::to_string(c.lights) + "_lights_" + std::to_string(c.tilesX) + "x" +
                          std::to_string(c.slices) + "_" + slicingName(c.slicing) + "_" + cullModeName(c.cull) + "_" +
                          assignModeName(c.assign) + (c.activeOnly ? "_active_only" : "") + (c.spotShare > 0.0f ? "_spots" : ""));
    });

// The exact count and fill take ML_ASSIGN_CANDIDATE_RUN rounds of candidates a workgroup; an
// invocation finds each later round's light forward from the last, by a doubling bracket and a
// binary search inside it, past lights that reach no cluster (they have no candidates). Lights
// are moved out of view in runs of 1 to 30 so that brackets span such runs and stop inside them;
// the lists must equal the per-cluster assignment's, which walks every light for each cluster.
TEST_F(GpuTest, ExactListsMatchPerClusterListsAcrossRunsOfLightsOutOfView) {
    TestScene t = testScene("atrium", 400, 17, 0.7f, 0.25f);
    const Camera camera = smallFrame(t.scene, 200, 120).camera;
    const glm::vec3 behind = -1.0e3f * glm::normalize(camera.target - camera.eye);
    std::size_t moved = 0;
    for (std::size_t i = 0; i < t.lights.size(); ++i) {
        const std::size_t phase = i % 61;
        if (phase >= 31 || phase % 5 == 2 || phase == 9 || phase == 10) {
            t.lights[i].position = camera.eye + behind;  // behind the camera: no slice, no candidate
            ++moved;
        }
    }
    std::vector<std::vector<std::uint32_t>> lists[2];
    for (const AssignMode assign : {AssignMode::Exact, AssignMode::PerCluster}) {
        FrameSettings s = smallFrame(t.scene, 200, 120);
        s.method.kind = MethodKind::Deferred;
        s.method.clustering.grid = ClusterGridConfig{24, 16, Slicing::Fitted, 64};
        s.method.clustering.assign = assign;
        s.method.clustering.lightSum = LightSum::Float;  // sorted lists: equal sets compare equal
        FrameRenderer renderer(t.scene, t.lights, s);
        renderer.render(0);
        lists[assign == AssignMode::Exact ? 0 : 1] = renderer.method().clustering()->downloadLists();
    }
    std::size_t references = 0;
    for (const auto& list : lists[0]) references += list.size();
    std::printf("%zu of %zu lights out of view; %zu references\n", moved, t.lights.size(), references);
    EXPECT_GT(references, 1000u);
    ASSERT_EQ(lists[0].size(), lists[1].size());
    for (std::size_t cluster = 0; cluster < lists[0].size(); ++cluster)
        ASSERT_EQ(lists[0][cluster], lists[1][cluster]) << "cluster " << cluster;
}

// Work issued beside the count pass (ClusteredLighting::BesideCount: the visibility buffer's
// resolve) may bind anything; the build binds what it needs again. Here the work binds a buffer of
// garbage at every storage-buffer point and as the indirect dispatch buffer: the lists must equal
// those of a build without it, and the count's timer carries the work's name.
TEST_F(GpuTest, WorkBesideTheCountLeavesTheListsAsTheyWere) {
    const TestScene t = testScene("atrium", 3000, 29, 1.0f, 0.25f);
    FrameSettings s = smallFrame(t.scene, 200, 120);
    s.method.kind = MethodKind::Deferred;
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(3);
    const auto rendered = renderer.method().clustering()->downloadLists();

    PassTimer timer(true, TimingClock::GpuQueries);
    const FrameContext ctx = renderer.frameContext(timer);
    ClusteredLighting clustering(renderer.method().clustering()->settings(), renderer.scene().materialFeatures());
    const std::vector<std::uint32_t> garbage(4096, 0xFFFFFF7Fu);
    const gl::Buffer junk = gl::Buffer::fromSpan<std::uint32_t>("test.junk", garbage);
    GLint points = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &points);
    int issued = 0;
    const ClusteredLighting::BesideCount beside{"test.beside", [&] {
        for (GLint point = 0; point < std::min(points, 64); ++point) junk.bindBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(point));
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, junk.id());
        ++issued;
    }};
    timer.beginFrame();
    clustering.build(ctx, nullptr, &beside);
    const std::vector<PassTime> times = timer.endFrame();
    EXPECT_EQ(issued, 1);
    EXPECT_NE(std::find_if(times.begin(), times.end(), [](const PassTime& p) { return p.name == "assign.count+test.beside"; }), times.end());
    const auto withBeside = clustering.downloadLists();
    clustering.build(ctx);
    const auto without = clustering.downloadLists();
    std::size_t references = 0;
    for (const auto& list : without) references += list.size();
    EXPECT_GT(references, 1000u);
    EXPECT_EQ(withBeside, without);
    EXPECT_EQ(without, rendered);
}

// The list sort on each of its paths: short lists by rank sort (up to ML_SORT_RANK_MAX) and
// bitonic (up to ML_SORT_SHORT_MAX), long ones bitonic in shared memory (up to
// ML_SORT_SHARED_CAPACITY) and beyond that in chunks merged by rank (5000 lights: lists of two
// chunks; 9500: three, the last partial); the edges included; exact and capped. Two clusters
// (tile columns), lights covering most of both.
struct LongListCase {
    AssignMode assign;
    std::uint32_t lights;
};

class LongLists : public GpuTest, public ::testing::WithParamInterface<LongListCase> {};

TEST_P(LongLists, AreCompleteAndSorted) {
    const LongListCase c = GetParam();
    const TestScene t = testScene("boxes", c.lights, 5, 3.0f);
    FrameSettings s = smallFrame(t.scene, 128, 64);
    s.method.kind = MethodKind::Deferred;
    s.method.clustering.grid = ClusterGridConfig{2, 1, Slicing::Linear, 64};
    s.method.clustering.assign = c.assign;
    s.method.clustering.maxPerCluster = c.lights + 7;  // capped: room for every light, odd size
    s.method.clustering.lightSum = LightSum::Float;    // the sums that need the sort
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(0);
    const auto lists = renderer.method().clustering()->downloadLists();
    // The same lists unsorted (fixed sums skip the sort), sorted here: what the sort must give.
    s.method.clustering.lightSum = LightSum::Fixed;
    FrameRenderer unsorted(t.scene, t.lights, s);
    unsorted.render(0);
    auto expected = unsorted.method().clustering()->downloadLists();
    ASSERT_EQ(lists.size(), 2u);
    ASSERT_EQ(expected.size(), 2u);
    for (std::size_t i = 0; i < lists.size(); ++i) {
        const auto& list = lists[i];
        std::printf("list of %zu lights\n", list.size());
        if (c.lights > ML_SORT_SHARED_CAPACITY) {
            EXPECT_GT(list.size(), std::size_t(c.lights > 9000 ? 2 * ML_SORT_SHARED_CAPACITY : ML_SORT_SHARED_CAPACITY));
        }
        EXPECT_TRUE(std::is_sorted(list.begin(), list.end()));
        EXPECT_EQ(std::adjacent_find(list.begin(), list.end()), list.end()) << "duplicate light";
        std::sort(expected[i].begin(), expected[i].end());
        EXPECT_EQ(list, expected[i]) << "list " << i << ": not the fill's entries";
    }
}

INSTANTIATE_TEST_SUITE_P(Sort, LongLists,
    ::testing::Values(LongListCase{AssignMode::Exact, 5000}, LongListCase{AssignMode::Exact, 700},
                      LongListCase{AssignMode::Exact, 100}, LongListCase{AssignMode::Exact, ML_SORT_RANK_MAX + 1},
                      LongListCase{AssignMode::Exact, ML_SORT_SHORT_MAX}, LongListCase{AssignMode::Exact, ML_SORT_SHORT_MAX + 1},
                      LongListCase{AssignMode::Exact, ML_SORT_SHARED_CAPACITY},
                      LongListCase{AssignMode::Exact, 9500},
                      LongListCase{AssignMode::Capped, 1500}, LongListCase{AssignMode::Capped, 5000}),
    [](const auto& info) { return std::string(assignModeName(info.param.assign)) + "_" + std::to_string(info.param.lights) + "_lights"; });

}  // namespace
}  // namespace ml::test
