// Builds this frame's per-cluster light lists on the GPU and binds them for shading; shared by
// Forward+ and clustered deferred, which differ only in how they shade.
//
//   depth ─> [cluster.depth-range]  fitted slicing only: min/max visible depth (held open to the
//                                   transparent ranges' depth extent; none where the raster reduced
//                                   its depth: FrameTargets::opaqueViewDepthRange)
//         ─> [cluster.bounds]       fitted slicing: the range sliced ─> grid.slicing; view-space AABB per cluster
//         ─> [cluster.active]       --active-only: flag clusters holding a visible sample
//         ─> [cluster.normal-bins]  --normal-cones: per cluster, the normal bins its visible samples occupy
//         ─> [cluster.transparent-samples]  with transparent surfaces and --active-only or
//                                   --normal-cones: their visible fragments marked as samples too
//   exact:  [assign.ranges] ─> [assign.count] ─> [assign.scan] ─> [assign.fill]
//           one invocation per (light, candidate cluster); one compact list, no cap, in a
//           buffer sized by the candidates that the ranges counted; a caller's work that needs no
//           list may run beside the count (BesideCount: the visibility resolve)
//   per-cluster: [assign.ranges] ─> [assign.per-cluster-count] ─> [assign.scan] ─> [assign.per-cluster-fill]
//           one invocation per cluster over every light (seed 003); the same lists
//   capped: [assign.capped]    one invocation per light; fixed lists, overflow counted
//   exact, capped: then [assign.sort]  each list in light-index order, so shading sums in a fixed order
//   zbin:   [zbin.keys] ─> [zbin.sort] ─> [zbin.bins] ─> [zbin.tile-masks]   (zbin_assignment.h;
//           no cluster bounds: bins and tile frusta replace the clusters)
//
// Every assignment tests pairs with the --cull test. With --normal-cones a list belongs to a
// (cluster, normal bin) key, cluster * ML_NORMAL_BINS + bin; the per-list buffers (counts and
// offsets: 8 B) grow 24-fold, and each list keeps the cone of its samples' normals (16 B):
// 24 B x 24 per cluster, 15.2 MiB for 32 x 18 x 48 clusters.
//
// Memory per cluster: count, offset, active flag (4 B each) and an AABB (32 B): 44 B, so
// 32 x 18 x 24 clusters take 594 KiB. Exact lists take 4 B per light reference, in a
// buffer sized by the frame's (light, candidate cluster) pairs, which bound the references;
// capped lists take clusters x cap x 4 B whatever the frame needs (42x24x12 x 2048: 99 MiB).
// With float sums the sort (list_sort.h) keeps a scratch buffer as large as the lists.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json_fwd.hpp>  // dump(); its callers include json.hpp

#include "renderer/clustering/cluster_grid.h"
#include "renderer/clustering/cluster_statistics.h"
#include "renderer/clustering/clustering_settings.h"
#include "renderer/clustering/list_sort.h"
#include "renderer/clustering/prefix_sum.h"
#include "renderer/clustering/zbin_assignment.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/mapped_words.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/gpu_types.h"
#include "renderer/frame_context.h"
#include "renderer/scene/raster_program.h"

namespace ml {

class GBuffer;

class ClusteredLighting {
public:
    // materialFeatures: SceneGpu::materialFeatures() (with transparency, the transparent samples'
    // program is built from them). gbufferDefines: the G-buffer's layout (GBuffer::defines()),
    // which --normal-cones decodes its normals from the way the lighting does.
    ClusteredLighting(const ClusteringSettings& settings, std::uint32_t materialFeatures, const shaders::Defines& gbufferDefines = {});

    // Builds the lists from the lights and the depth already in ctx.targets.depth(); with
    // --normal-cones also from the G-buffer's normals (required then).
    // Throws std::runtime_error when the lists cannot fit this GPU's storage-buffer limit.
    //
    // `beside`: work that needs nothing of the lists, issued between the count pass's dispatch and
    // its barrier so that the GPU runs the two together (the visibility buffer's resolve). It may
    // bind any storage buffer, texture, image or indirect dispatch buffer, not the frame's uniform
    // buffer: the build binds what its passes read again after it. Its time is in the count's,
    // whose timer is then named "assign.count+<name>". Only where hasCountPass().
    struct BesideCount {
        std::string name;
        std::function<void()> issue;
    };
    void build(const FrameContext& ctx, const GBuffer* gbuffer = nullptr, const BesideCount* beside = nullptr);
    // Exact and per-cluster lists are counted before they are filled; capped and z-binned are not.
    bool hasCountPass() const { return settings_.assign == AssignMode::Exact || settings_.assign == AssignMode::PerCluster; }
    // Lists per cluster: ML_NORMAL_BINS with --normal-cones, else 1.
    std::uint32_t listsPerCluster() const;
    // Binds the grid, counts, offsets and light indices at their ML_SSBO_* points.
    void bindForShading() const;

    const ClusterGrid& grid() const { return grid_; }
    const ClusteringSettings& settings() const { return settings_; }

    // Reads back the counts and counters of the last build (a GPU sync).
    ClusterStatistics statistics() const;
    // The grid, slicing, camera matrices and, for each non-empty cluster, its light indices.
    nlohmann::json dump(const FrameUniforms& uniforms) const;

    // Read-backs for tests and dumps.
    ClusterGridGpu downloadGrid() const;
    // Per list: per cluster, or per (cluster, normal bin) key with --normal-cones.
    std::vector<std::uint32_t> downloadCounts() const;
    std::vector<ClusterAabbGpu> downloadAabbs() const;
    // Light indices of every list (cluster, or key), in list order.
    std::vector<std::vector<std::uint32_t>> downloadLists() const;
    // The z-binning of the last build (--assign zbin), else null.
    const ZBinAssignment* zbin() const { return zbin_.get(); }

private:
    void uploadGrid(const FrameContext& ctx);
    void ensureStorage(std::uint32_t clusters);
    void checkListFits(std::size_t bytes, const char* what) const;
    void buildExact(const FrameContext& ctx, const BesideCount* beside);
    void bindAssignmentBuffers(const FrameContext& ctx) const;
    void markNormalBins(const FrameContext& ctx, const GBuffer& gbuffer);
    // Rasters the transparent ranges as samples (cluster_transparent_samples.frag), phase 0 or 1.
    void markTransparentSamples(const FrameContext& ctx, unsigned phase) const;
    void buildCapped(const FrameContext& ctx);
    void sortLists(const FrameContext& ctx);
    void dispatchAssignment(const gl::Program& program, std::uint32_t lightCount) const;

    ClusteringSettings settings_;
    ClusterGrid grid_;
    std::size_t maxStorageBlock_ = 0;

    gl::Program depthRange_, bounds_, active_, normalBins_, clear_, ranges_, dispatch_, count_, fill_, capped_;
    PrefixSum scan_;
    ListSort sort_;
    RasterProgram transparentSamples_;  // only with transparency and --active-only or --normal-cones

    gl::Buffer gridBuffer_;
    gl::Buffer counters_;  // [0] dropped references (capped), [1] list entries, [2] candidate pairs (exact), [3..4] normal-cone pairs
    gl::Buffer dispatchArgs_;  // indirect dispatch of the per-candidate passes
    gl::MappedWords candidates_;  // AssignStats [5] and [6] after the ranges: the candidates bound the lists
    gl::GrowableBuffer lightRanges_{"assign.light-ranges"};  // 16 B per light
    gl::GrowableBuffer lightView_{"assign.light-view"};      // 16 B per light
    gl::GrowableBuffer candidateOffsets_{"assign.candidate-offsets"};  // 4 B per light
    gl::GrowableBuffer aabbs_{"clusters.aabbs"};
    gl::GrowableBuffer counts_{"clusters.counts"};
    gl::GrowableBuffer offsets_{"clusters.offsets"};
    gl::GrowableBuffer activeFlags_{"clusters.active"};
    gl::GrowableBuffer normalBinMasks_{"clusters.normal-bin-masks"};  // 4 B per cluster
    gl::GrowableBuffer normalCones_{"clusters.normal-cones"};         // 16 B per (cluster, bin) list
    gl::GrowableBuffer indices_{"clusters.light-indices"};
    std::unique_ptr<ZBinAssignment> zbin_;  // --assign zbin only
};

}  // namespace ml
