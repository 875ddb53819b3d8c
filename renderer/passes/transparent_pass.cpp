#include "renderer/passes/transparent_pass.h"

#include <utility>

#include "glsl/include/bindings.h"
#include "renderer/clustering/clustered_lighting.h"

namespace ml {

namespace {
// The shading passes' program: the fragment writes its alpha (ML_TRANSPARENT) for blending.
RasterProgram transparentProgram(const char* label, const char* fragmentShader, std::uint32_t materialFeatures,
                                 shaders::Defines defines) {
    defines.emplace_back("ML_TRANSPARENT", "1");
    return transparentRangesProgram(label, fragmentShader, materialFeatures, std::move(defines));
}
}  // namespace

TransparentPass::TransparentPass(std::string timerName, RasterProgram program)
    : timerName_(std::move(timerName)), program_(std::move(program)) {}

TransparentPass TransparentPass::overAllLights(std::string timerName, std::uint32_t materialFeatures, bool spotLights) {
    return TransparentPass(std::move(timerName),
                           transparentProgram("transparent.all-lights", "naive_forward.frag", materialFeatures, {spotLightsDefine(spotLights)}));
}

TransparentPass TransparentPass::overClusterLists(std::string timerName, std::uint32_t materialFeatures,
                                                  const ClusteringSettings& settings) {
    return TransparentPass(std::move(timerName),
                           transparentProgram("transparent.cluster-lists", "forward_plus.frag", materialFeatures, lightListDefines(settings)));
}

void TransparentPass::render(const FrameContext& ctx, const ClusteredLighting* lists) const {
    if (!program_.variant(false) || !ctx.scene.hasTransparent()) return;
    if (lists && lists->settings().view != DebugView::Shaded) return;
    auto pass = ctx.timer.pass(timerName_);
    // The opaque frame may have come from compute passes' image stores.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
    beginTransparentRaster(ctx.targets);
    glEnable(GL_BLEND);
    // Colour "over" the frame; the target's alpha stays 1 (the frame is opaque).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    ctx.lights.bindForReading();
    if (lists) lists->bindForShading();
    ctx.scene.drawTransparent(program_, glm::vec3(ctx.uniforms.cameraPos));
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace ml
