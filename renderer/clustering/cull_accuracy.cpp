#include "renderer/clustering/cull_accuracy.h"

#include <algorithm>

#include "renderer/clustering/cluster_culling.h"
#include "renderer/clustering/clustered_lighting.h"

namespace ml {

CullAccuracy measureCullAccuracy(const ClusteredLighting& clustering, const std::vector<Light>& drawn,
                                 const FrameUniforms& uniforms, std::uint64_t maxReferences) {
    const std::vector<Light> lights = clusteredLights(drawn);  // what the lists index
    const ClusterGrid& grid = clustering.grid();
    const ClusterGridGpu g = clustering.downloadGrid();
    const DepthSlicing slicing{g.tile.y > 0.5f, g.slicing.x, g.slicing.y, g.slicing.z, g.slicing.w};
    const int width = static_cast<int>(uniforms.viewport.x), height = static_cast<int>(uniforms.viewport.y);
    const std::vector<std::vector<std::uint32_t>> lists = clustering.downloadLists();
    std::uint64_t total = 0;
    for (const auto& list : lists) total += list.size();

    CullAccuracy a;
    a.clusterStride = static_cast<std::uint32_t>(std::max<std::uint64_t>(1, (total + maxReferences - 1) / std::max<std::uint64_t>(maxReferences, 1)));
    std::vector<SpotCone> inView;
    inView.reserve(lights.size());
    for (const Light& l : lights) inView.push_back(spotConeOf(l, uniforms.view));
    // With --normal-cones the lists are per (cluster, normal bin) key; each key is examined.
    const std::uint32_t bins = clustering.listsPerCluster();
    for (std::uint32_t c = 0; c < grid.clusterCount(); c += a.clusterStride) {
        ++a.clustersExamined;
        const std::uint32_t x = c % grid.tilesX, y = (c / grid.tilesX) % grid.tilesY, slice = c / (grid.tilesX * grid.tilesY);
        const ClusterFrustum f = clusterFrustum(grid, slicing, g.tile.z, g.tile.w, uniforms.proj, width, height, x, y, slice);
        for (std::uint32_t key = c * bins; key < (c + 1) * bins; ++key) {
            for (std::uint32_t light : lists[key]) {
                if (light >= lights.size()) continue;
                const bool spot = inView[light].isSpot();
                const bool reaches = lightReachesCluster(f, inView[light]);
                ++a.references;
                if (!reaches) ++a.falsePositives;
                if (spot) {
                    ++a.spotReferences;
                    if (!reaches) ++a.spotFalsePositives;
                }
            }
        }
    }
    return a;
}

}  // namespace ml
