// The visibility-buffer path (--method visibility): the raster pass writes only depth and a
// triangle id (4 B per pixel instead of the G-buffer's 24, one cheap fragment shader); compute
// passes rebuild each pixel's surface from its triangle into the G-buffer and light it as
// clustered deferred does. On GPUs where few SMs run graphics work (design.md: an R32UI id
// target + depth took 0.9 ms where three RGBA16F targets took 2.6-7.1 ms) raster work is kept small.
#pragma once

#include <memory>
#include <vector>

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/frame_targets_stamp.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/gbuffer.h"
#include "renderer/methods/shading_method.h"
#include "renderer/scene/raster_program.h"
#include "renderer/passes/compute_raster.h"
#include "renderer/passes/transparent_pass.h"

namespace ml {

class VisibilityBuffer final : public ShadingMethod {
public:
    VisibilityBuffer(const ClusteringSettings& settings, GBufferFormat gbuffer, std::uint32_t materialFeatures,
                     const TransparencySettings& transparency = {}, VisibilityRaster raster = VisibilityRaster::Hardware);
    std::string name() const override { return "visibility"; }
    // Hardware, Compute or ComputeTwoPass (ComputeRaster::resolve has settled Auto).
    VisibilityRaster raster() const { return raster_; }
    const ComputeRaster* computeRaster() const { return computeRaster_.get(); }
    // The last frame's ids: triangle index + 1 per pixel, 0 where nothing was drawn.
    const gl::Texture2D& triangleIds() const { return triangleIds_; }
    void render(const FrameContext& ctx) override;
    const GlassFragments* transparentCapture() const override { return transparent_.capture(); }
    const ClusteredLighting* clustering() const override { return &clustering_; }
    std::size_t extraTargetBytes() const override {
        return gbuffer_.bytes() + std::size_t(stamp_.width()) * stamp_.height() * 4 + resolveTiles_.size() + resolveDispatch_.size();
    }

private:
    void prepareTargets(const FrameTargets& frame);
    void rasterInHardware(const FrameContext& ctx);
    // Lists, per texture-set slot, the screen tiles whose pixels need it, and their indirect
    // dispatches (visibility_classify.comp).
    void classifyTiles(const FrameContext& ctx);
    // The resolve's dispatches, one per texture-set slot, over the classified tiles (or the
    // screen, past ML_RESOLVE_MAX_SLOTS); no barrier.
    void issueResolve(const FrameContext& ctx);
    static std::size_t resolveSlots(const FrameContext& ctx);
    // Whether the resolve runs over classified tiles (at most ML_RESOLVE_MAX_SLOTS slots).
    static bool resolvesByTileLists(const FrameContext& ctx);
    static glm::uvec2 resolveGroups(const FrameContext& ctx);

    VisibilityRaster raster_;
    GBuffer gbuffer_;
    RasterProgram rasterProgram_;
    std::unique_ptr<ComputeRaster> computeRaster_;  // --vis-raster compute
    gl::Program clearIdsProgram_;
    gl::Program classifyProgram_;
    gl::Program resolveProgram_;
    gl::Program lightingProgram_;
    FrameTargetsStamp stamp_;  // the size and depth the id target and framebuffers were made for
    gl::Texture2D triangleIds_;
    gl::Framebuffer fbo_;        // ids and depth: the alpha-tested ranges write ids as colour
    gl::Framebuffer depthFbo_;   // depth alone: the opaque ranges write ids by image atomics
    // The resolve's tile lists per texture-set slot (set + 1; visibility_classify.comp) and
    // their indirect dispatches: 4 B per tile and slot (2560x1440, 10 slots: 2.3 MiB).
    gl::Buffer resolveTiles_;
    gl::Buffer resolveDispatch_;
    std::vector<GLuint> emptyDispatch_;  // {0, 1, 1} per slot, uploaded before each classification
    ClusteredLighting clustering_;
    TransparentPass transparent_;
};

}  // namespace ml
