// Clustered forward (Forward+): a depth pre-pass, light assignment into clusters, then the
// scene is rastered again and each fragment loops over its cluster's lights only. With
// --prepass off the scene is rastered once, shading every fragment that passes LESS (overdraw
// shades hidden fragments too); the grid then cannot be fitted to a depth that does not exist yet.
#pragma once

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/scene/raster_program.h"
#include "renderer/methods/shading_method.h"
#include "renderer/passes/depth_prepass.h"
#include "renderer/passes/transparent_pass.h"

namespace ml {

class ForwardPlus final : public ShadingMethod {
public:
    ForwardPlus(const ClusteringSettings& settings, bool prepass, std::uint32_t materialFeatures,
                const TransparencySettings& transparency = {});
    std::string name() const override { return "forward-plus"; }
    void render(const FrameContext& ctx) override;
    const GlassFragments* transparentCapture() const override { return transparent_.capture(); }
    const ClusteredLighting* clustering() const override { return &clustering_; }
    // The pre-pass path marks each pixel's first nearest fragment in the stencil.
    bool needsStencil() const override { return prepass_; }

private:
    void shadeOpaque(const FrameContext& ctx);

    bool prepass_;
    DepthPrePass depthPrePass_;
    RasterProgram shadeProgram_;
    ClusteredLighting clustering_;
    TransparentPass transparent_;
};

}  // namespace ml
