// Clustered deferred: raster into the G-buffer, assign lights to clusters, then light every
// pixel from the G-buffer with its cluster's lights, as a full-screen fragment pass or as a
// compute pass (--resolve). The G-buffer follows a depth pre-pass, so each pixel's surface is
// rebuilt and written once (renderer/passes/depth_prepass.h); with --prepass off it is written
// in one depth-tested pass, once per fragment that passes at its turn (overdraw included).
#pragma once

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/gl/program.h"
#include "renderer/gbuffer.h"
#include "renderer/methods/shading_method.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/transparent_pass.h"
#include "renderer/scene/raster_program.h"

namespace ml {

class ClusteredDeferred final : public ShadingMethod {
public:
    ClusteredDeferred(const ClusteringSettings& settings, Resolve resolve, GBufferFormat gbuffer, bool prepass,
                      std::uint32_t materialFeatures, const TransparencySettings& transparency = {});
    std::string name() const override { return "deferred"; }
    void render(const FrameContext& ctx) override;
    const GlassFragments* transparentCapture() const override { return transparent_.capture(); }
    const ClusteredLighting* clustering() const override { return &clustering_; }
    std::size_t extraTargetBytes() const override { return gbuffer_.bytes(); }
    // The pre-pass path marks each pixel's first nearest fragment in the stencil.
    bool needsStencil() const override { return prepass_; }

private:
    Resolve resolve_;
    bool prepass_;
    GBuffer gbuffer_;
    DepthPrePass depthPrePass_;
    RasterProgram gbufferProgram_;
    gl::Program lightingProgram_;
    gl::Handle<gl::VertexArrayDeleter> emptyVao_;
    ClusteredLighting clustering_;
    TransparentPass transparent_;
};

}  // namespace ml
