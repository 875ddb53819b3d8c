// --assign per-cluster (seed 003: one invocation per cluster over every light) builds the same
// lists as the per-light exact assignment, as sets, for every --cull test; its lists come out in
// light order. (Its images against naive: cull_modes_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>

#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"

namespace ml::test {
namespace {

class PerClusterAssignment : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(PerClusterAssignment, ListsEqualThePerLightListsAsSets) {
    const TestScene t = testScene(GetParam(), 300, 13, 0.6f);
    FrameSettings s = smallFrame(t.scene, 200, 120);
    s.method.kind = MethodKind::Deferred;
    s.method.clustering.grid = ClusterGridConfig{24, 16, Slicing::Fitted, 64};
    FrameRenderer renderer(t.scene, t.lights, s);
    for (bool normalCones : {false, true}) {
        for (CullMode cull : {CullMode::Aabb, CullMode::Sphere, CullMode::Cone}) {
            const std::string label = std::string(cullModeName(cull)) + (normalCones ? " normal cones" : "");
            MethodSettings m = s.method;
            m.clustering.cull = cull;
            m.clustering.normalCones = normalCones;
            m.clustering.assign = AssignMode::Exact;
            renderer.setMethod(m);
            renderer.render(30);
            std::vector<std::vector<std::uint32_t>> perLight = renderer.method().clustering()->downloadLists();
            m.clustering.assign = AssignMode::PerCluster;
            renderer.setMethod(m);
            renderer.render(30);
            const std::vector<std::vector<std::uint32_t>> perCluster = renderer.method().clustering()->downloadLists();
            ASSERT_EQ(perLight.size(), perCluster.size()) << label;
            std::size_t references = 0, differing = 0;
            for (std::size_t c = 0; c < perLight.size(); ++c) {
                EXPECT_TRUE(std::is_sorted(perCluster[c].begin(), perCluster[c].end())) << label << ": list " << c << " not in light order";
                std::sort(perLight[c].begin(), perLight[c].end());
                references += perLight[c].size();
                if (perLight[c] != perCluster[c] && ++differing <= 3) ADD_FAILURE() << label << ": list " << c << " differs";
            }
            EXPECT_EQ(differing, 0u) << label;
            EXPECT_GT(references, 0u) << label;
            std::printf("%-20s %zu references, identical sets\n", label.c_str(), references);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PerClusterAssignment, ::testing::Values("atrium", "boxes"),
                         [](const auto& info) { return testNameOf(info.param); });

}  // namespace
}  // namespace ml::test
