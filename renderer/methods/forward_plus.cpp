#include "renderer/methods/forward_plus.h"

#include <stdexcept>

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"

namespace ml {

namespace {
// Without the pre-pass no depth exists when the light lists are built: fitted slicing (a
// reduction of that depth) falls back to log slicing over the camera's near..far, and
// active-only clusters (found from that depth) cannot be had at all.
ClusteringSettings clusteringFor(ClusteringSettings settings, bool prepass) {
    if (prepass) return settings;
    if (settings.activeOnly)
        throw std::invalid_argument("--active-only needs the depth pre-pass of forward-plus (drop --prepass off)");
    if (settings.grid.slicing == Slicing::Fitted) settings.grid.slicing = Slicing::Log;
    return settings;
}
}  // namespace

ForwardPlus::ForwardPlus(const ClusteringSettings& settings, bool prepass, std::uint32_t materialFeatures,
                         const TransparencySettings& transparency)
    : prepass_(prepass),
      depthPrePass_("forward-plus.depth", materialFeatures),
      shadeProgram_("forward-plus.shade", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "forward_plus.frag"}},
                    materialFeatures, RasterProgram::Reads::Material, lightListDefines(settings)),
      clustering_(clusteringFor(settings, prepass), materialFeatures),
      transparent_(TransparentPass::overClusterLists("forward+.transparent", materialFeatures, clusteringFor(settings, prepass), transparency)) {}

void ForwardPlus::render(const FrameContext& ctx) {
    shadeOpaque(ctx);
    transparent_.render(ctx, &clustering_);
}

void ForwardPlus::shadeOpaque(const FrameContext& ctx) {
    const gl::Framebuffer& fbo = ctx.targets.hdrFramebuffer();
    auto clearColour = [&] {
        fbo.bind();
        glViewport(0, 0, ctx.targets.width(), ctx.targets.height());
        const float clearColor[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clearColor);
    };
    if (!prepass_) {
        // One raster pass, as naive's: LESS, first drawn wins a coplanar tie, and every fragment
        // that passes is shaded (the overdraw the pre-pass exists to avoid).
        clustering_.build(ctx);
        auto pass = ctx.timer.pass("forward+.shade");
        clearColour();
        depth::beginNearestDepth(fbo.id());
        ctx.bindLightsForShading();
        clustering_.bindForShading();
        ctx.scene.draw(shadeProgram_);
        return;
    }
    {
        auto pass = ctx.timer.pass("forward+.depth-prepass");
        clearColour();
        depthPrePass_.drawDepth(ctx.scene, fbo);
    }
    clustering_.build(ctx);
    {
        auto pass = ctx.timer.pass("forward+.shade");
        fbo.bind();
        ctx.bindLightsForShading();
        clustering_.bindForShading();
        DepthPrePass::drawNearestOnce(ctx.scene, shadeProgram_);
    }
}

}  // namespace ml
