#include "renderer/methods/visibility_buffer.h"

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"
#include "renderer/methods/deferred_lighting.h"

namespace ml {

namespace {

// Pixels a classifying invocation reads along each axis, and tiles a workgroup covers: the pass
// waits on three dependent reads a pixel, so an invocation keeps several pixels' in flight.
constexpr int kClassifyBlock = 2;

}  // namespace

VisibilityBuffer::VisibilityBuffer(const ClusteringSettings& settings, GBufferFormat gbuffer, std::uint32_t materialFeatures,
                                   const TransparencySettings& transparency, VisibilityRaster raster)
    : raster_(raster),
      gbuffer_(gbuffer, materialFeatures),
      rasterProgram_("visibility.raster", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "visibility.frag"}},
                     materialFeatures, RasterProgram::Reads::CoverageOnly),
      clearIdsProgram_(gl::Program::compute("visibility_clear_ids.comp")),
      classifyProgram_(gl::Program::compute("visibility_classify.comp", shaders::withDefine(gbuffer_.defines(), "ML_CLASSIFY_BLOCK", std::to_string(kClassifyBlock)))),
      resolveProgram_(gl::Program::compute("visibility_resolve.comp", gbuffer_.defines())),
      lightingProgram_(gl::Program::compute("deferred_lighting.comp", deferredLightingDefines(settings, gbuffer_))),
      clustering_(settings, materialFeatures, gbuffer_.defines()),
      transparent_(TransparentPass::overClusterLists("visibility.transparent", materialFeatures, settings, transparency)) {
    if (raster_ != VisibilityRaster::Hardware)
        computeRaster_ = std::make_unique<ComputeRaster>(
            materialFeatures, raster_ == VisibilityRaster::Compute,
            ComputeRaster::Extras{.viewDepthRange = settings.grid.slicing == Slicing::Fitted,
                                  .depthUnderGlass = settings.activeOnly || settings.normalCones});
}

void VisibilityBuffer::prepareTargets(const FrameTargets& frame) {
    if (!stamp_.update(frame)) return;
    triangleIds_ = gl::Texture2D("visibility.triangle-ids", GL_R32UI, stamp_.width(), stamp_.height());
    fbo_ = gl::Framebuffer("visibility", {&triangleIds_}, &frame.depth());
    depthFbo_ = gl::Framebuffer("visibility.depth", {}, &frame.depth());
}

void VisibilityBuffer::classifyTiles(const FrameContext& ctx) {
    const std::size_t slots = resolveSlots(ctx);
    const glm::uvec2 groups = resolveGroups(ctx);
    const std::size_t tileBytes = slots * groups.x * groups.y * sizeof(GLuint);
    if (resolveTiles_.size() != tileBytes) {
        resolveTiles_ = gl::Buffer("visibility.resolve-tiles", tileBytes);
        resolveDispatch_ = gl::Buffer("visibility.resolve-dispatch", slots * 3 * sizeof(GLuint));
        emptyDispatch_.assign(slots * 3, 1u);
        for (std::size_t s = 0; s < slots; ++s) emptyDispatch_[3 * s] = 0u;
    }
    resolveDispatch_.upload(emptyDispatch_.data(), emptyDispatch_.size() * sizeof(GLuint));
    ctx.scene.bindGeometryStorage();
    glBindTextureUnit(ML_TEX_VISIBILITY, triangleIds_.id());
    resolveTiles_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RESOLVE_TILES);
    resolveDispatch_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RESOLVE_DISPATCH);
    classifyProgram_.use();
    glDispatchCompute(gl::groupsFor(groups.x, kClassifyBlock), gl::groupsFor(groups.y, kClassifyBlock), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

std::size_t VisibilityBuffer::resolveSlots(const FrameContext& ctx) { return ctx.scene.textureSetCount() + 1; }

bool VisibilityBuffer::resolvesByTileLists(const FrameContext& ctx) { return resolveSlots(ctx) <= ML_RESOLVE_MAX_SLOTS; }

glm::uvec2 VisibilityBuffer::resolveGroups(const FrameContext& ctx) {
    return {gl::groupsFor(ctx.targets.width(), ML_SCREEN_TILE), gl::groupsFor(ctx.targets.height(), ML_SCREEN_TILE)};
}

void VisibilityBuffer::issueResolve(const FrameContext& ctx) {
    const glm::uvec2 groups = resolveGroups(ctx);
    const bool tileLists = resolvesByTileLists(ctx);
    resolveProgram_.use();
    ctx.scene.bindGeometryStorage();
    gbuffer_.bindForWriting();
    glBindTextureUnit(ML_TEX_VISIBILITY, triangleIds_.id());
    resolveProgram_.set("u_tileLists", tileLists ? 1u : 0u);
    resolveProgram_.set("u_tileCount", groups.x * groups.y);
    resolveProgram_.set("u_tilesX", groups.x);
    if (tileLists) {
        resolveTiles_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RESOLVE_TILES);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, resolveDispatch_.id());
    }
    // One dispatch per texture set, and one for untextured materials.
    for (int set = -1; set < static_cast<int>(ctx.scene.textureSetCount()); ++set) {
        ctx.scene.bindTextureSet(set);
        resolveProgram_.set("u_textureSet", set);
        if (tileLists) glDispatchComputeIndirect(static_cast<GLintptr>(std::size_t(set + 1) * 3 * sizeof(GLuint)));
        else glDispatchCompute(groups.x, groups.y, 1);
    }
    if (tileLists) glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    ctx.scene.unbindSamplers();
}

void VisibilityBuffer::rasterInHardware(const FrameContext& ctx) {
    // The ids by compute (the ROPs' clear costs a full-screen layer of writes on an H100);
    // the opaque ranges' atomics keep the largest id (visibility.frag).
    clearIdsProgram_.use();
    glBindImageTexture(ML_IMG_VISIBILITY_IDS, triangleIds_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glDispatchCompute(gl::groupsFor(stamp_.width(), ML_SCREEN_TILE), gl::groupsFor(stamp_.height(), ML_SCREEN_TILE), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    depthFbo_.bind();
    glViewport(0, 0, ctx.targets.width(), ctx.targets.height());
    depth::beginNearestDepth(depthFbo_.id());
    ctx.scene.draw(rasterProgram_, SceneGpu::Ranges::Opaque);
    if (ctx.scene.hasAlphaTestedRanges()) {
        // Drawn last, through the ROPs: their ids overwrite where they pass the depth test.
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
        fbo_.bind();
        ctx.scene.draw(rasterProgram_, SceneGpu::Ranges::AlphaTested);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VisibilityBuffer::render(const FrameContext& ctx) {
    prepareTargets(ctx.targets);
    gbuffer_.prepare(ctx.targets);
    if (computeRaster_) {
        computeRaster_->run(ctx, triangleIds_);  // times its own steps (visibility.raster-*)
    } else {
        auto pass = ctx.timer.pass("visibility.raster");
        rasterInHardware(ctx);
    }
    // The depth is final: the glass is counted now, its total long known when the fill needs it.
    transparent_.countFragments(ctx, clustering_.settings().view);
    // The resolve's shading needs only the classification, so it runs beside the assignment's
    // count (0.005-0.04 ms a frame less on an H200: docs/benchmarks.md), unless the lists read the
    // G-buffer (--normal-cones) or the assignment has no count pass.
    const bool besideCount = clustering_.hasCountPass() && !clustering_.settings().normalCones;
    {
        auto pass = ctx.timer.pass("visibility.resolve");
        if (resolvesByTileLists(ctx)) classifyTiles(ctx);
        if (!besideCount) {
            issueResolve(ctx);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
    const ClusteredLighting::BesideCount resolve{"visibility.resolve", [&] { issueResolve(ctx); }};
    clustering_.build(ctx, &gbuffer_, besideCount ? &resolve : nullptr);
    {
        auto pass = ctx.timer.pass("visibility.lighting");
        if (besideCount) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        bindDeferredLightingInputs(gbuffer_, ctx, clustering_);
        lightingProgram_.use();
        dispatchComputeLighting(ctx);
    }
    applySampledShadows(ctx, clustering_.settings());
    transparent_.render(ctx, &clustering_);
}

}  // namespace ml
