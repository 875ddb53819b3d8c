#include "renderer/clustering/clustered_lighting.h"


#include <algorithm>
#include <bit>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "glsl/include/bindings.h"
#include "renderer/lights/light_buffers.h"
#include "renderer/gbuffer.h"
#include "renderer/scene/transparent_ranges.h"

namespace ml {

namespace {

constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;

// The --cull test is compiled in (ML_CULL), so the per-pair loop has no branch on it.
std::string cullDefine(CullMode mode) {
    switch (mode) {
    case CullMode::Aabb: return "ML_CULL_AABB";
    case CullMode::Sphere: return "ML_CULL_SPHERE";
    case CullMode::Cone: return "ML_CULL_CONE";
    }
    return "ML_CULL_AABB";
}

gl::Program exactProgram(const char* label, const char* phase, const ClusteringSettings& settings) {
    shaders::Defines defines{{phase, "1"},
                             {"ML_WORKGROUP", std::to_string(settings.grid.workgroup)},
                             {"ML_CULL", cullDefine(settings.cull)},
                             spotLightsDefine(settings.spotLights)};
    if (settings.normalCones) defines.emplace_back("ML_NORMAL_CONES", "1");
    return gl::Program(label, {{GL_COMPUTE_SHADER, "assign_exact.comp"}}, defines);
}

// The count and fill passes: per (light, candidate) pair, or per cluster over every light.
gl::Program countProgram(const ClusteringSettings& settings) {
    if (settings.assign == AssignMode::PerCluster) return exactProgram("assign.per-cluster-count", "ML_PER_CLUSTER_COUNT", settings);
    return exactProgram("assign.count", "ML_EXACT_COUNT", settings);
}
gl::Program fillProgram(const ClusteringSettings& settings) {
    if (settings.assign == AssignMode::PerCluster) return exactProgram("assign.per-cluster-fill", "ML_PER_CLUSTER_FILL", settings);
    return exactProgram("assign.fill", "ML_EXACT_FILL", settings);
}

void clearToZero(const gl::Buffer& buffer, std::size_t bytes) {
    if (bytes == 0) return;
    glClearNamedBufferSubData(buffer.id(), GL_R32UI, 0, static_cast<GLsizeiptr>(bytes), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, nullptr);
}

// Marks transparent fragments as samples where a pass learns from samples alone.
RasterProgram transparentSamplesProgram(const ClusteringSettings& settings, std::uint32_t materialFeatures) {
    const bool needed = (settings.activeOnly || settings.normalCones) && settings.assign != AssignMode::ZBin;
    if (!needed) return {};
    shaders::Defines defines;
    if (settings.activeOnly) defines.emplace_back("ML_MARK_ACTIVE", "1");
    if (settings.normalCones) defines.emplace_back("ML_NORMAL_CONES", "1");
    return transparentRangesProgram("cluster.transparent-samples", "cluster_transparent_samples.frag", materialFeatures, defines);
}

std::string mib(std::size_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

ClusteredLighting::ClusteredLighting(const ClusteringSettings& settings, std::uint32_t materialFeatures,
                                     const shaders::Defines& gbufferDefines)
    : settings_(settings),
      depthRange_(gl::Program::compute("cluster_depth_range.comp", {depthSamplesDefine(settings)})),
      bounds_(gl::Program::compute("cluster_bounds.comp")),
      active_(gl::Program::compute("cluster_active.comp", {depthSamplesDefine(settings)})),
      normalBins_(settings.normalCones ? gl::Program::compute("cluster_normal_bins.comp", gbufferDefines) : gl::Program()),
      clear_(exactProgram("assign.clear", "ML_EXACT_CLEAR", settings)),
      ranges_(exactProgram("assign.ranges", "ML_EXACT_RANGES", settings)),
      dispatch_(exactProgram("assign.dispatch", "ML_EXACT_DISPATCH", settings)),
      count_(countProgram(settings)),
      fill_(fillProgram(settings)),
      capped_(gl::Program("assign.capped", {{GL_COMPUTE_SHADER, "assign_lights.comp"}},
                          {{"ML_WORKGROUP", std::to_string(settings.grid.workgroup)},
                           {"ML_CULL", cullDefine(settings.cull)},
                           spotLightsDefine(settings.spotLights)})),
      transparentSamples_(transparentSamplesProgram(settings, materialFeatures)),
      gridBuffer_("clusters.grid", sizeof(ClusterGridGpu)),
      counters_("clusters.counters", 32),
      dispatchArgs_("assign.dispatch-args", 16),
      candidates_("assign.candidates", 2) {
    validateGridConfig(settings.grid);
    if (settings.assign == AssignMode::ZBin) zbin_ = std::make_unique<ZBinAssignment>(settings.spotLights, depthSamplesDefine(settings));
    if (settings.normalCones && settings.assign == AssignMode::Capped)
        throw std::invalid_argument("--normal-cones: needs exact lists (--assign exact or per-cluster), not capped ones");
    // A cone culls the lights behind every normal of its list; a transmissive surface is lit from behind too.
    if (settings.normalCones && (materialFeatures & ML_FEATURE_TRANSMISSION))
        throw std::invalid_argument("--normal-cones: the scene has KHR_materials_transmission surfaces, lit through from behind, "
                                    "which normal cones would cull; leave --normal-cones off");
    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    maxStorageBlock_ = static_cast<std::size_t>(maxBlock);
    dispatch_.set("u_maxGroupsX", gl::maxWorkGroupsX());
    GLint maxInvocations = 0;
    glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &maxInvocations);
    if (settings.grid.workgroup > static_cast<std::uint32_t>(maxInvocations))
        throw std::invalid_argument("--workgroup " + std::to_string(settings.grid.workgroup) +
                                    ": larger than this GPU's GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS (" +
                                    std::to_string(maxInvocations) + ")");
}

void ClusteredLighting::checkListFits(std::size_t bytes, const char* what) const {
    if (bytes <= maxStorageBlock_) return;
    const bool capped = settings_.assign == AssignMode::Capped;
    throw std::runtime_error(std::string(what) + " need " + mib(bytes) +
                             ", more than this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + mib(maxStorageBlock_) + "); lower " +
                             (capped ? "--max-per-cluster, --tiles-x or --slices" : "--lights, --light-radius, --tiles-x or --slices"));
}

std::uint32_t ClusteredLighting::listsPerCluster() const { return settings_.normalCones ? ML_NORMAL_BINS : 1u; }

void ClusteredLighting::ensureStorage(std::uint32_t clusters) {
    const std::size_t perCluster = std::size_t(clusters) * 4;
    const std::size_t perList = perCluster * listsPerCluster();
    checkListFits(std::size_t(clusters) * sizeof(ClusterAabbGpu), "cluster bounds");
    checkListFits(perList, "per-list counts");
    aabbs_.ensure(std::size_t(clusters) * sizeof(ClusterAabbGpu));
    counts_.ensure(perList);
    offsets_.ensure(perList);
    activeFlags_.ensure(perCluster);
    if (settings_.normalCones) {
        checkListFits(perList * 4, "normal cones");
        normalBinMasks_.ensure(perCluster);
        normalCones_.ensure(perList * 4);
    }
}

void ClusteredLighting::uploadGrid(const FrameContext& ctx) {
    grid_ = ClusterGrid::forViewport(settings_.grid, ctx.targets.width(), ctx.targets.height());
    const float cameraNear = ctx.uniforms.depthRange.x, cameraFar = ctx.uniforms.depthRange.y;
    const bool fitted = settings_.grid.slicing == Slicing::Fitted;
    // Fitted slicing starts from the camera's range; cluster.depth-range replaces it on the GPU.
    const DepthSlicing slicing =
        DepthSlicing::make(settings_.grid.slicing != Slicing::Linear, cameraNear, cameraFar, grid_.slices);
    ClusterGridGpu g{};
    g.dims = glm::uvec4(grid_.tilesX, grid_.tilesY, grid_.slices, grid_.clusterCount());
    g.slicing = glm::vec4(slicing.zNear, slicing.zFar, slicing.scale, slicing.bias);
    g.tile = glm::vec4(grid_.tileSizePx, slicing.logarithmic ? 1.0f : 0.0f, cameraNear, cameraFar);
    g.reduction = glm::uvec4(0xFFFFFFFFu, 0u, 0u, 0u);
    // The opaque depth buffer holds no transparent surface. A pane nearer (or farther) than every
    // opaque sample stays exact even so, as the first and last slices reach the camera's planes
    // (clusterDepthExtent), but its fragments would all fall in one deep end slice whose lists
    // hold every light of that depth span. So the reduction starts from the transparent ranges'
    // depth extent, widened by a relative 1e-4 for the fragments' rounding: the slices cover the
    // panes as tightly as the opaque surfaces.
    if (fitted) {
        if (const auto extent = ctx.scene.transparentDepthRange(ctx.uniforms.view, cameraNear, cameraFar)) {
            const float lo = std::max(extent->x * (1.0f - 1e-4f), cameraNear), hi = std::min(extent->y * (1.0f + 1e-4f), cameraFar);
            g.reduction.x = std::bit_cast<std::uint32_t>(lo);
            g.reduction.y = std::bit_cast<std::uint32_t>(hi);
        }
    }
    g.options = glm::uvec4(fitted ? 1u : 0u, settings_.assign == AssignMode::Capped ? settings_.maxPerCluster : 0u,
                           settings_.activeOnly ? 1u : 0u, static_cast<std::uint32_t>(settings_.view));
    gridBuffer_.upload(&g, sizeof(g));
}

void ClusteredLighting::bindForShading() const {
    gridBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_GRID);
    counts_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
    offsets_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_OFFSETS);
    indices_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_INDICES);
    activeFlags_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_ACTIVE);  // Forward+ with --msaa
    if (zbin_) zbin_->bindForShading();
}

void ClusteredLighting::build(const FrameContext& ctx, const GBuffer* gbuffer, const BesideCount* beside) {
    if (beside && !hasCountPass()) throw std::logic_error("ClusteredLighting::build: work beside a count pass, but the assignment has none");
    uploadGrid(ctx);
    const std::uint32_t clusters = grid_.clusterCount();
    ensureStorage(clusters);
    gridBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_GRID);
    glBindTextureUnit(ML_TEX_DEPTH, ctx.targets.opaqueDepth().id());
    const GLuint screenX = gl::groupsFor(ctx.targets.width(), ML_SCREEN_TILE);
    const GLuint screenY = gl::groupsFor(ctx.targets.height(), ML_SCREEN_TILE);

    // Fitted slicing's range: reduced from the depth here, or by the raster as it wrote the depth
    // (its words then joined with the grid's by the pass that slices the range).
    const bool fitted = settings_.grid.slicing == Slicing::Fitted;
    const ViewDepthRange& reduced = ctx.targets.opaqueViewDepthRange();
    const GLuint rasterRangeWord = fitted && reduced.buffer ? reduced.word : ~0u;
    if (rasterRangeWord != ~0u) reduced.buffer->bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_WORK);
    if (fitted && (!reduced.buffer || zbin_)) {
        auto pass = ctx.timer.pass("cluster.depth-range");
        depthRange_.use();
        if (!reduced.buffer) {
            depthRange_.set("u_phase", 0u);
            glDispatchCompute(gl::groupsFor(ctx.targets.width(), ML_SCREEN_TILE * ML_DEPTH_RANGE_BLOCK),
                              gl::groupsFor(ctx.targets.height(), ML_SCREEN_TILE * ML_DEPTH_RANGE_BLOCK), 1);
            glMemoryBarrier(kComputeToCompute);
        }
        // Z-binning has no bounds pass to slice the range: one invocation does.
        if (zbin_) {
            depthRange_.set("u_rasterRangeWord", rasterRangeWord);
            depthRange_.set("u_phase", 1u);
            glDispatchCompute(1, 1, 1);
            glMemoryBarrier(kComputeToCompute);
        }
    }
    if (zbin_) {
        // Z-binning needs only the slicing (for its bins) and the tiles; --active-only does not apply.
        // The per-cluster counts stay zero, so dumps and read-backs see empty lists.
        clearToZero(counts_.buffer(), std::size_t(clusters) * 4);
        zbin_->build(ctx, grid_, maxStorageBlock_);
        return;
    }
    {
        auto pass = ctx.timer.pass("cluster.bounds");
        bounds_.use();
        bounds_.set("u_fitsSlicing", fitted ? 1u : 0u);
        bounds_.set("u_rasterRangeWord", rasterRangeWord);
        aabbs_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_AABBS);
        glDispatchCompute(gl::groupsFor(clusters, ML_CLUSTER_WORKGROUP), 1, 1);
        glMemoryBarrier(kComputeToCompute);
    }
    activeFlags_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_ACTIVE);
    if (settings_.activeOnly) {
        auto pass = ctx.timer.pass("cluster.active");
        clearToZero(activeFlags_.buffer(), std::size_t(clusters) * 4);
        active_.use();
        glDispatchCompute(screenX, screenY, 1);
        glMemoryBarrier(kComputeToCompute);
        // With --normal-cones the transparent samples are marked with the normal bins' phase 0.
        if (!settings_.normalCones) markTransparentSamples(ctx, 0);
    }
    if (settings_.normalCones) {
        if (!gbuffer) throw std::logic_error("--normal-cones: the lists need the G-buffer's normals");
        markNormalBins(ctx, *gbuffer);
    }
    ctx.lights.bindForReading();
    counters_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ASSIGN_STATS);
    if (settings_.assign == AssignMode::Capped) buildCapped(ctx);
    else buildExact(ctx, beside);
    if (settings_.lightSum == LightSum::Float) sortLists(ctx);
}

void ClusteredLighting::sortLists(const FrameContext& ctx) {
    auto pass = ctx.timer.pass("assign.sort");
    // Capped lists are one per cluster; exact ones one per cluster and normal bin.
    const bool capped = settings_.assign == AssignMode::Capped;
    const std::uint32_t lists = grid_.clusterCount() * (capped ? 1u : listsPerCluster());
    checkListFits(ListSort::workBytes(lists, indices_.buffer().size()), "the sort's work lists");
    sort_.sort(counts_.buffer(), offsets_.buffer(), indices_.buffer(), lists, capped ? settings_.maxPerCluster : 0u);
}

void ClusteredLighting::markNormalBins(const FrameContext& ctx, const GBuffer& gbuffer) {
    auto pass = ctx.timer.pass("cluster.normal-bins");
    const std::uint32_t clusters = grid_.clusterCount();
    clearToZero(normalBinMasks_.buffer(), std::size_t(clusters) * 4);
    clearToZero(normalCones_.buffer(), std::size_t(clusters) * ML_NORMAL_BINS * 16);
    glMemoryBarrier(kComputeToCompute);
    normalBinMasks_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_NORMAL_BIN_MASKS);
    normalCones_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_NORMAL_CONES);
    gbuffer.bindForReading();
    // Phase 0: occupied bins and each list's normal sum; phase 1: each list's widest normal. The
    // transparent samples join each phase before the next begins.
    for (unsigned phase : {0u, 1u}) {
        normalBins_.use();
        normalBins_.set("u_phase", phase);
        glDispatchCompute(gl::groupsFor(ctx.targets.width(), ML_SCREEN_TILE), gl::groupsFor(ctx.targets.height(), ML_SCREEN_TILE), 1);
        glMemoryBarrier(kComputeToCompute);
        markTransparentSamples(ctx, phase);
    }
}

void ClusteredLighting::markTransparentSamples(const FrameContext& ctx, unsigned phase) const {
    if (!transparentSamples_.variant(false) || !ctx.scene.hasTransparent()) return;
    auto pass = ctx.timer.pass("cluster.transparent-samples");
    // Depth-tested against the opaque depth, writing nothing but the sample buffers.
    beginTransparentRaster(ctx.targets);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // The depth texture is attached now: take it off the unit the compute passes read it from.
    glBindTextureUnit(ML_TEX_DEPTH, 0);
    transparentSamples_.variant(false).use();
    transparentSamples_.variant(false).set("u_phase", phase);
    gridBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_GRID);
    ctx.scene.drawTransparent(transparentSamples_, glm::vec3(ctx.uniforms.cameraPos));
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glBindTextureUnit(ML_TEX_DEPTH, ctx.targets.opaqueDepth().id());
    glMemoryBarrier(kComputeToCompute);
}

void ClusteredLighting::dispatchAssignment(const gl::Program& program, std::uint32_t lightCount) const {
    program.use();
    if (lightCount > 0) glDispatchCompute(gl::groupsFor(lightCount, settings_.grid.workgroup), 1, 1);
    glMemoryBarrier(kComputeToCompute);
}

// Everything the exact passes read and write, but the lists (the fill and the sort bind those).
void ClusteredLighting::bindAssignmentBuffers(const FrameContext& ctx) const {
    ctx.lights.bindForReading();
    gridBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_GRID);
    aabbs_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_AABBS);
    activeFlags_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_ACTIVE);
    counters_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ASSIGN_STATS);
    lightRanges_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_RANGES);
    lightView_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_VIEW);
    candidateOffsets_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CANDIDATE_OFFSETS);
    dispatchArgs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_DISPATCH);
    candidates_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ASSIGN_CANDIDATES);
    counts_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
    offsets_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_OFFSETS);
    if (settings_.normalCones) {
        normalBinMasks_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_NORMAL_BIN_MASKS);
        normalCones_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_NORMAL_CONES);
    }
}

void ClusteredLighting::buildExact(const FrameContext& ctx, const BesideCount* beside) {
    const std::uint32_t clusters = grid_.clusterCount();
    const std::uint32_t lists = clusters * listsPerCluster();
    const std::uint32_t lights = ctx.lights.count();
    const bool perCluster = settings_.assign == AssignMode::PerCluster;
    lightRanges_.ensure(std::size_t(lights) * 16);
    lightView_.ensure(std::size_t(lights) * 16);
    candidateOffsets_.ensure(std::size_t(lights) * 4);
    bindAssignmentBuffers(ctx);
    // The per-pair passes run one invocation per candidate (indirect) or per cluster.
    const auto dispatchPairs = [&] {
        if (perCluster) glDispatchCompute(gl::groupsFor(clusters, settings_.grid.workgroup), 1, 1);
        else glDispatchComputeIndirect(0);
    };
    {
        // Each light's candidate block; per light, where its candidates start among all of them.
        auto pass = ctx.timer.pass("assign.ranges");
        // The lists' counts and offsets and the totals: one dispatch for every buffer the
        // assignment adds into (glsl/assign_exact.comp says why).
        clear_.use();
        clear_.set("u_lists", lists);
        glDispatchCompute(gl::groupsFor(std::max(lists, 8u), settings_.grid.workgroup), 1, 1);
        glMemoryBarrier(kComputeToCompute);
        dispatchAssignment(ranges_, lights);
        if (!perCluster) {
            // The scan binds only its own points (ML_SSBO_SCAN_*): bindAssignmentBuffers' hold.
            scan_.run(candidateOffsets_.buffer(), lights, counters_, 8);
            glMemoryBarrier(kComputeToCompute);
        }
        // The count's indirect dispatch (unused per cluster), and the candidates and their wrap
        // flag for the CPU to read once the fence passes, while the GPU runs the count and its scan.
        dispatch_.use();
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT | kComputeToCompute);
        candidates_.fence();
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatchArgs_.id());
    {
        const std::string name = perCluster ? "assign.per-cluster-count" : "assign.count";
        auto pass = ctx.timer.pass(beside ? name + "+" + beside->name : name);
        count_.use();
        dispatchPairs();
        if (beside) {
            beside->issue();
            bindAssignmentBuffers(ctx);
            glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatchArgs_.id());
        }
        glMemoryBarrier(kComputeToCompute);
    }
    {
        auto pass = ctx.timer.pass("assign.scan");
        scan_.run(offsets_.buffer(), lists, counters_, 4);
        glMemoryBarrier(kComputeToCompute);
    }
    {
        auto pass = ctx.timer.pass(perCluster ? "assign.per-cluster-fill" : "assign.fill");
        // The lists are sized by the candidates, which bound their total (a candidate passes
        // the cull test once), read behind the fence: the GPU passed it before the count and
        // the scan, which it runs while the CPU reads. Reading the lists' own total instead
        // would drain the pipeline, and the GPU would idle until the fill came (0.1-0.2 ms on
        // an H100: docs/bench/nvidia-h100/list-sync/). That is still done where the bound
        // passes the storage limit, and with --normal-cones (a pair joins up to
        // ML_NORMAL_BINS lists).
        const std::uint32_t* candidates = candidates_.read();
        if (candidates[1] != 0)
            throw std::runtime_error(std::to_string(lights) + " lights name more than 4,294,967,295 (light, cluster) candidate "
                                     "pairs this frame; lower --light-radius, --lights, --tiles-x or --slices");
        std::size_t listBytes = std::size_t(candidates[0]) * 4;
        if (settings_.normalCones || listBytes > maxStorageBlock_) {
            std::uint32_t totals[8] = {};  // layout: glsl/assign_exact.comp's AssignStats
            counters_.download(totals, sizeof(totals), 0);
            listBytes = std::size_t(totals[1]) * 4;
            checkListFits(listBytes, "the light lists");
        }
        indices_.ensure(listBytes);
        counts_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
        offsets_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_OFFSETS);
        indices_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_INDICES);
        counters_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ASSIGN_STATS);
        candidateOffsets_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CANDIDATE_OFFSETS);
        fill_.use();
        dispatchPairs();
        glMemoryBarrier(kComputeToCompute);
        // Submitted now: after the wait the GPU has only the count and the scan left.
        glFlush();
    }
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

void ClusteredLighting::buildCapped(const FrameContext& ctx) {
    const std::uint32_t clusters = grid_.clusterCount();
    const std::size_t listBytes = std::size_t(clusters) * settings_.maxPerCluster * 4;
    checkListFits(listBytes, "capped light lists (clusters x --max-per-cluster x 4 B)");
    indices_.ensure(listBytes);
    auto pass = ctx.timer.pass("assign.capped");
    clearToZero(counts_.buffer(), std::size_t(clusters) * 4);
    clearToZero(counters_, 16);
    counts_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_COUNTS);
    indices_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_INDICES);
    dispatchAssignment(capped_, ctx.lights.count());
}

ClusterGridGpu ClusteredLighting::downloadGrid() const {
    ClusterGridGpu g{};
    gridBuffer_.download(&g, sizeof(g));
    return g;
}

std::vector<std::uint32_t> ClusteredLighting::downloadCounts() const {
    std::vector<std::uint32_t> counts(std::size_t(grid_.clusterCount()) * listsPerCluster());
    counts_.buffer().download(counts.data(), counts.size() * 4);
    return counts;
}

std::vector<ClusterAabbGpu> ClusteredLighting::downloadAabbs() const {
    std::vector<ClusterAabbGpu> boxes(grid_.clusterCount());
    aabbs_.buffer().download(boxes.data(), boxes.size() * sizeof(ClusterAabbGpu));
    return boxes;
}

std::vector<std::vector<std::uint32_t>> ClusteredLighting::downloadLists() const {
    const std::vector<std::uint32_t> counts = downloadCounts();
    const std::uint32_t clusters = static_cast<std::uint32_t>(counts.size());  // lists: clusters, or (cluster, normal bin) keys
    std::vector<std::uint32_t> offsets(clusters);
    const bool capped = settings_.assign == AssignMode::Capped;
    if (!capped) offsets_.buffer().download(offsets.data(), offsets.size() * 4);
    std::vector<std::uint32_t> indices(indices_.buffer().size() / 4);
    indices_.buffer().download(indices.data(), indices.size() * 4);
    std::vector<std::vector<std::uint32_t>> lists(clusters);
    for (std::uint32_t c = 0; c < clusters; ++c) {
        const std::uint32_t first = capped ? c * settings_.maxPerCluster : offsets[c];
        const std::uint32_t n = capped ? std::min(counts[c], settings_.maxPerCluster) : counts[c];
        if (std::uint64_t(first) + n > indices.size())
            throw std::runtime_error("cluster lists read back inconsistent: list " + std::to_string(c) + " holds entries " +
                                     std::to_string(first) + "+" + std::to_string(n) + " of " + std::to_string(indices.size()));
        lists[c].assign(indices.begin() + first, indices.begin() + first + n);
    }
    return lists;
}

ClusterStatistics ClusteredLighting::statistics() const {
    ClusterStatistics s;
    const ClusterGridGpu g = downloadGrid();
    s.tilesX = grid_.tilesX;
    s.tilesY = grid_.tilesY;
    s.slices = grid_.slices;
    s.clusters = grid_.clusterCount();
    s.slicing = slicingName(settings_.grid.slicing);
    s.cull = cullModeName(settings_.cull);
    s.zNear = g.slicing.x;
    s.zFar = g.slicing.y;
    if (zbin_) {
        // No per-cluster lists: what z-binning built instead.
        gridBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_CLUSTER_GRID);
        s.zbin = true;
        s.zbinStats = zbin_->statistics();
        s.listBytes = s.zbinStats.totalBytes;
        s.gridBytes = sizeof(ClusterGridGpu);
        return s;
    }
    const std::vector<std::uint32_t> counts = downloadCounts();
    const bool capped = settings_.assign == AssignMode::Capped;
    // With --normal-cones the shares and means are over (cluster, normal bin) lists.
    const std::uint32_t lists = static_cast<std::uint32_t>(counts.size());
    s.listsPerCluster = listsPerCluster();
    std::uint64_t demand = 0, stored = 0;
    std::uint32_t empty = 0;
    for (std::uint32_t c : counts) {
        demand += c;
        stored += capped ? std::min(c, settings_.maxPerCluster) : c;
        empty += c == 0;
        s.maxLightsPerCluster = std::max(s.maxLightsPerCluster, c);
        if (capped && c > settings_.maxPerCluster) ++s.overflowClusters;
    }
    s.emptyShare = lists ? double(empty) / lists : 0.0;
    s.meanLightsPerCluster = lists ? double(demand) / lists : 0.0;
    s.meanLightsPerNonEmptyCluster = lists > empty ? double(demand) / (lists - empty) : 0.0;
    s.listEntries = stored;
    std::uint32_t counters[8] = {};
    counters_.download(counters, sizeof counters, 0);
    s.droppedReferences = capped ? counters[0] : 0;
    if (settings_.normalCones) {
        s.normalConePairs = counters[3];
        s.normalConePairsKept = counters[4];
    }
    s.activeOnly = settings_.activeOnly;
    if (settings_.activeOnly) {
        std::vector<std::uint32_t> flags(s.clusters);
        activeFlags_.buffer().download(flags.data(), flags.size() * 4);
        s.activeClusters = static_cast<std::uint32_t>(std::count(flags.begin(), flags.end(), 1u));
    }
    s.listBytes = capped ? std::size_t(s.clusters) * settings_.maxPerCluster * 4 : std::size_t(stored) * 4;
    // Per cluster: active flag, AABB (and normal-bin mask); per list: count, offset (and the
    // normal cone).
    s.gridBytes = std::size_t(s.clusters) * (4 + sizeof(ClusterAabbGpu) + (settings_.normalCones ? 4 : 0)) +
                  std::size_t(lists) * (settings_.normalCones ? 24 : 8) + 16;
    return s;
}

nlohmann::json ClusteredLighting::dump(const FrameUniforms& uniforms) const {
    const ClusterGridGpu g = downloadGrid();
    auto matrix = [](const glm::mat4& m) {
        nlohmann::json rows = nlohmann::json::array();
        for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
        return rows;
    };
    nlohmann::json doc;
    doc["grid"] = {{"tiles_x", grid_.tilesX},
                   {"tiles_y", grid_.tilesY},
                   {"slices", grid_.slices},
                   {"tile_size_px", grid_.tileSizePx},
                   {"index", "x + tiles_x * (y + tiles_y * slice); tiles from the bottom-left pixel"}};
    doc["slicing"] = {{"mode", slicingName(settings_.grid.slicing)},
                      {"spacing", g.tile.y > 0.5f ? "log" : "linear"},
                      {"z_near", g.slicing.x},
                      {"z_far", g.slicing.y},
                      {"camera_near", g.tile.z},
                      {"camera_far", g.tile.w}};
    doc["assign"] = assignModeName(settings_.assign);
    doc["cull"] = cullModeName(settings_.cull);
    doc["normal_cones"] = settings_.normalCones;
    if (settings_.assign == AssignMode::Capped) doc["max_per_cluster"] = settings_.maxPerCluster;
    doc["viewport"] = {uniforms.viewport.x, uniforms.viewport.y};
    doc["view_matrix"] = matrix(uniforms.view);
    doc["projection_matrix"] = matrix(uniforms.proj);
    const auto lists = downloadLists();
    const auto counts = downloadCounts();
    nlohmann::json clusters = nlohmann::json::array();
    const std::uint32_t bins = listsPerCluster();
    for (std::uint32_t key = 0; key < lists.size(); ++key) {
        if (counts[key] == 0) continue;
        const std::uint32_t c = key / bins;
        const std::uint32_t x = c % grid_.tilesX, y = (c / grid_.tilesX) % grid_.tilesY, slice = c / (grid_.tilesX * grid_.tilesY);
        nlohmann::json entry = {{"index", c}, {"x", x}, {"y", y}, {"slice", slice}, {"count", counts[key]}, {"lights", lists[key]}};
        if (bins > 1) entry["normal_bin"] = key % bins;
        clusters.push_back(std::move(entry));
    }
    doc["clusters"] = std::move(clusters);
    return doc;
}

AssignMode parseAssignMode(const std::string& text) {
    if (text == "exact") return AssignMode::Exact;
    if (text == "capped") return AssignMode::Capped;
    if (text == "per-cluster") return AssignMode::PerCluster;
    if (text == "zbin") return AssignMode::ZBin;
    throw std::invalid_argument("--assign '" + text + "': expected exact, capped, per-cluster or zbin");
}

const char* assignModeName(AssignMode mode) {
    switch (mode) {
    case AssignMode::Exact: return "exact";
    case AssignMode::Capped: return "capped";
    case AssignMode::PerCluster: return "per-cluster";
    case AssignMode::ZBin: return "zbin";
    }
    return "?";
}

std::pair<std::string, std::string> depthSamplesDefine(const ClusteringSettings& settings) {
    return {"ML_MSAA_SAMPLES", std::to_string(settings.depthSamples)};
}

shaders::Defines lightShadingDefines(const ClusteringSettings& settings) {
    shaders::Defines defines{spotLightsDefine(settings.spotLights), lightSumDefine(settings.lightSum)};
    if (const auto& s = settings.shading) {
        defines.emplace_back("ML_BRDF_GGX", s->brdf == Brdf::Ggx ? "1" : "0");
        defines.emplace_back("ML_SPECULAR", s->specular ? "1" : "0");
        defines.emplace_back("ML_FALLOFF", std::to_string(static_cast<std::uint32_t>(s->falloff)));
        defines.emplace_back("ML_SHADOW_RAYS", s->shadowRays ? "1" : "0");
        if (s->countShadowRays) defines.emplace_back("ML_COUNT_SHADOW_RAYS", "1");
        if (s->shadowRays) defines.emplace_back("ML_SHADOW_BVH_WIDTH", std::to_string(s->shadowBvhWidth));
        // Read by the compute lighting alone (deferred_lighting.comp); every other program traces the exact rays.
        if (s->shadowRays && s->shadowSamples > 0) defines.emplace_back("ML_SHADOW_SAMPLES", std::to_string(s->shadowSamples));
    }
    return defines;
}

shaders::Defines lightListDefines(const ClusteringSettings& settings) {
    shaders::Defines defines = lightShadingDefines(settings);
    defines.push_back(depthSamplesDefine(settings));
    if (settings.assign == AssignMode::ZBin) defines.emplace_back("ML_ZBIN", "1");
    if (settings.normalCones) defines.emplace_back("ML_NORMAL_CONES", "1");
    return defines;
}

}  // namespace ml
