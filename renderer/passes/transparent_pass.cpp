#include "renderer/passes/transparent_pass.h"

#include <utility>

#include "glsl/include/bindings.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/scene/material_features.h"
#include "renderer/scene/transparent_ranges.h"

namespace ml {

TransparentPass::TransparentPass(std::string timerName, std::uint32_t materialFeatures, const TransparencySettings& transparency,
                                 const char* forwardShader, const shaders::Defines& defines)
    : timerName_(std::move(timerName)) {
    if (!(materialFeatures & ML_FEATURE_BLEND)) return;
    const bool allLights = forwardShader == std::string("naive_forward.frag");
    if (transparency.msaa > 1) {
        // The forward pass's fragment writes its alpha (ML_TRANSPARENT) for blending.
        shaders::Defines forwardDefines = defines;
        forwardDefines.emplace_back("ML_TRANSPARENT", "1");
        forward_ = transparentRangesProgram(allLights ? "transparent.all-lights" : "transparent.cluster-lists", forwardShader,
                                            materialFeatures, std::move(forwardDefines));
        return;
    }
    capture_ = std::make_unique<GlassFragments>(timerName_, materialFeatures, transparency.captureBudget);
    shaders::Defines shadeDefines = defines;
    shadeDefines.emplace_back("ML_GLASS_ALL_LIGHTS", allLights ? "1" : "0");
    // BLEND ignores alphaCutoff: no alpha-tested paths.
    for (auto& d : materialFeatureDefines(materialFeatures & ~std::uint32_t(ML_FEATURE_ALPHA_TEST))) shadeDefines.push_back(d);
    shade_ = gl::Program(allLights ? "transparent.shade-all-lights" : "transparent.shade-cluster-lists",
                         {{GL_COMPUTE_SHADER, "glass_shade.comp"}}, shadeDefines);
}

TransparentPass TransparentPass::overAllLights(std::string timerName, std::uint32_t materialFeatures, const ClusteringSettings& lights,
                                               const TransparencySettings& transparency) {
    return TransparentPass(std::move(timerName), materialFeatures, transparency, "naive_forward.frag", lightShadingDefines(lights));
}

TransparentPass TransparentPass::overClusterLists(std::string timerName, std::uint32_t materialFeatures,
                                                  const ClusteringSettings& settings, const TransparencySettings& transparency) {
    return TransparentPass(std::move(timerName), materialFeatures, transparency, "forward_plus.frag", lightListDefines(settings));
}

void TransparentPass::countFragments(const FrameContext& ctx, DebugView view) {
    if (!capture_ || !ctx.scene.hasTransparent() || view != DebugView::Shaded) return;
    // The opaque depth may have come from compute passes' image stores.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
    capture_->count(ctx, ctx.scene.transparentTextureSets().size() > 1);
}

void TransparentPass::render(const FrameContext& ctx, const ClusteredLighting* lists) {
    if (!ctx.scene.hasTransparent()) return;
    if (lists && lists->settings().view != DebugView::Shaded) return;
    if (forward_.variant(false)) renderForward(ctx, lists);
    else if (capture_) renderCaptured(ctx, lists);
}

void TransparentPass::renderForward(const FrameContext& ctx, const ClusteredLighting* lists) const {
    auto pass = ctx.timer.pass(timerName_);
    // The opaque frame may have come from compute passes' image stores.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
    beginTransparentRaster(ctx.targets);
    glEnable(GL_BLEND);
    // Colour "over" the frame; the target's alpha stays 1 (the frame is opaque).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    ctx.lights.bindForReading();
    if (lists) lists->bindForShading();
    ctx.scene.drawTransparent(forward_, glm::vec3(ctx.uniforms.cameraPos));
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

void TransparentPass::renderCaptured(const FrameContext& ctx, const ClusteredLighting* lists) {
    if (!capture_->counted()) countFragments(ctx);
    const std::vector<int> sets = ctx.scene.transparentTextureSets();
    const bool storesColors = sets.size() > 1;
    capture_->fill(ctx);
    auto pass = ctx.timer.pass(timerName_);
    ctx.scene.bindGeometryStorage();
    ctx.lights.bindForReading();
    if (lists) lists->bindForShading();
    capture_->bindForShading();
    glBindImageTexture(ML_IMG_HDR, ctx.targets.hdr().id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    shade_.use();
    shade_.set("u_storesColors", storesColors ? 1u : 0u);
    shade_.set("u_colorBase", capture_->colorWordOffset());
    const GLuint groupsX = gl::groupsFor(ctx.targets.width(), ML_SCREEN_TILE);
    const GLuint groupsY = gl::groupsFor(ctx.targets.height(), ML_SCREEN_TILE);
    for (std::size_t i = 0; i < sets.size(); ++i) {
        ctx.scene.bindTextureSet(sets[i]);
        shade_.set("u_textureSet", sets[i]);
        shade_.set("u_sorts", i == 0 ? 1u : 0u);
        shade_.set("u_blends", i + 1 == sets.size() ? 1u : 0u);
        glDispatchCompute(groupsX, groupsY, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    ctx.scene.unbindSamplers();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

}  // namespace ml
