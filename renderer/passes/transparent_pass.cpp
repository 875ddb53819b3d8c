#include "renderer/passes/transparent_pass.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "glsl/include/bindings.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/scene/material_features.h"
#include "renderer/scene/transparent_ranges.h"

namespace ml {

TransparentPass::TransparentPass(std::string timerName, std::uint32_t materialFeatures, const TransparencySettings& transparency,
                                 const char* forwardShader, const shaders::Defines& defines, bool listRounds)
    : timerName_(std::move(timerName)) {
    if (!(materialFeatures & ML_FEATURE_BLEND)) return;
    const bool allLights = forwardShader == std::string("naive_forward.frag");
    seesThrough_ = (materialFeatures & ML_FEATURE_TRANSMISSION) != 0;
    if (seesThrough_ && transparency.msaa > 1)
        throw std::invalid_argument("--msaa " + std::to_string(transparency.msaa) +
                                    ": the scene has KHR_materials_transmission surfaces, which only the single-sample "
                                    "transparent pass draws; use --msaa 1");
    if (transparency.msaa > 1) {
        // The forward pass's fragment writes its alpha (ML_TRANSPARENT) for blending.
        shaders::Defines forwardDefines = defines;
        forwardDefines.emplace_back("ML_TRANSPARENT", "1");
        forward_ = transparentRangesProgram(allLights ? "transparent.all-lights" : "transparent.cluster-lists", forwardShader,
                                            materialFeatures, std::move(forwardDefines));
        return;
    }
    capture_ = std::make_unique<GlassFragments>(timerName_, materialFeatures, transparency.captureBudget);
    // List rounds (glass_shade.comp's ML_GLASS_LIST_ROUNDS: per-cluster lists) hold a workgroup
    // to its longest chain of rounds; their shading splits deep tiles.
    if (listRounds && transparency.layerGroups > 1) layerGroups_ = std::min<std::uint32_t>(transparency.layerGroups, ML_GLASS_DEEP_MAX_PARTS);
    shaders::Defines shadeDefines = defines;
    shadeDefines.emplace_back("ML_GLASS_ALL_LIGHTS", allLights ? "1" : "0");
    // BLEND ignores alphaCutoff: no alpha-tested paths.
    for (auto& d : materialFeatureDefines(materialFeatures & ~std::uint32_t(ML_FEATURE_ALPHA_TEST))) shadeDefines.push_back(d);
    shade_ = gl::Program(allLights ? "transparent.shade-all-lights" : "transparent.shade-cluster-lists",
                         {{GL_COMPUTE_SHADER, "glass_shade.comp"}}, shadeDefines);
    if (layerGroups_) splitDefines_ = std::move(shadeDefines);  // the split's programs are built by its first frame
}

TransparentPass TransparentPass::overAllLights(std::string timerName, std::uint32_t materialFeatures, const ClusteringSettings& lights,
                                               const TransparencySettings& transparency) {
    return TransparentPass(std::move(timerName), materialFeatures, transparency, "naive_forward.frag", lightShadingDefines(lights), false);
}

TransparentPass TransparentPass::overClusterLists(std::string timerName, std::uint32_t materialFeatures,
                                                  const ClusteringSettings& settings, const TransparencySettings& transparency) {
    return TransparentPass(std::move(timerName), materialFeatures, transparency, "forward_plus.frag", lightListDefines(settings),
                           settings.assign != AssignMode::ZBin);
}

void TransparentPass::countFragments(const FrameContext& ctx, DebugView view) {
    if (!capture_ || !ctx.scene.hasTransparent() || view != DebugView::Shaded) return;
    // The opaque depth may have come from compute passes' image stores.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
    const bool severalSets = ctx.scene.transparentTextureSets().size() > 1;
    capture_->count(ctx, severalSets ? GlassColors::Always : layerGroups_ ? GlassColors::WhereRoom : GlassColors::None, layerGroups_);
}

void TransparentPass::render(const FrameContext& ctx, const ClusteredLighting* lists, OpaqueFrame opaqueFrame) {
    if (!ctx.scene.hasTransparent()) return;
    if (lists && lists->settings().view != DebugView::Shaded) return;
    if (forward_.variant(false)) renderForward(ctx, lists);
    else if (capture_) renderCaptured(ctx, lists, opaqueFrame);
}

void TransparentPass::renderForward(const FrameContext& ctx, const ClusteredLighting* lists) const {
    auto pass = ctx.timer.pass(timerName_);
    // The opaque frame may have come from compute passes' image stores.
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
    beginTransparentRaster(ctx.targets);
    glEnable(GL_BLEND);
    // Colour "over" the frame; the target's alpha stays 1 (the frame is opaque).
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    ctx.bindLightsForShading();
    if (lists) lists->bindForShading();
    ctx.scene.drawTransparent(forward_, glm::vec3(ctx.uniforms.cameraPos));
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

void TransparentPass::renderCaptured(const FrameContext& ctx, const ClusteredLighting* lists, OpaqueFrame opaqueFrame) {
    if (!capture_->counted()) countFragments(ctx);
    const std::vector<int> sets = ctx.scene.transparentTextureSets();
    capture_->fill(ctx);
    if (opaqueFrame == OpaqueFrame::CopyNow) copyOpaqueFrame(ctx);
    else if (seesThrough_) glBindTextureUnit(ML_TEX_REFRACTION_SOURCE, opaqueFrame_.id());
    const bool storesColors = sets.size() > 1;
    const bool splits = !storesColors && capture_->hasDeepTileList();
    auto pass = ctx.timer.pass(timerName_);
    ctx.scene.bindGeometryStorage();
    ctx.bindLightsForShading();
    if (lists) lists->bindForShading();
    capture_->bindForShading();
    glBindImageTexture(ML_IMG_HDR, ctx.targets.hdr().id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    if (splits) {
        shadeSplittingDeepTiles(ctx, sets[0]);
    } else {
        shade_.use();
        shade_.set("u_colorBase", capture_->colorWordOffset());
        shade_.set("u_storesColors", storesColors ? 1u : 0u);
        shade_.set("u_glassWindow", capture_->window());
        for (std::size_t i = 0; i < sets.size(); ++i) {
            ctx.scene.bindTextureSet(sets[i]);
            shade_.set("u_textureSet", sets[i]);
            shade_.set("u_sorts", i == 0 ? 1u : 0u);
            shade_.set("u_blends", i + 1 == sets.size() ? 1u : 0u);
            glDispatchCompute(capture_->windowTiles().x, capture_->windowTiles().y, 1);
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }
    ctx.scene.unbindSamplers();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

void TransparentPass::copyOpaqueFrame(const FrameContext& ctx) {
    if (!seesThrough_ || !capture_ || !ctx.scene.hasTransparent()) return;
    auto pass = ctx.timer.pass(timerName_ + "-behind");
    const gl::Texture2D& hdr = ctx.targets.hdr();
    if (!opaqueFrame_ || opaqueFrame_.width() != hdr.width() || opaqueFrame_.height() != hdr.height()) {
        opaqueFrame_ = gl::Texture2D("transparent.behind", hdr.format(), hdr.width(), hdr.height(), gl::fullMipLevels(hdr.width(), hdr.height()));
        opaqueFrame_.setSampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE);
    }
    // The opaque frame may have come from compute passes' image stores.
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glCopyImageSubData(hdr.id(), GL_TEXTURE_2D, 0, 0, 0, 0, opaqueFrame_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, hdr.width(), hdr.height(), 1);
    glGenerateTextureMipmap(opaqueFrame_.id());
    glBindTextureUnit(ML_TEX_REFRACTION_SOURCE, opaqueFrame_.id());
    glBindSampler(ML_TEX_REFRACTION_SOURCE, 0);
}

void TransparentPass::shadeSplittingDeepTiles(const FrameContext& ctx, int textureSet) {
    // Deep from a pixel of two fragments: each further layer is a further chain of rounds.
    constexpr GLuint kDeepFragments = 2;
    // glass_shade.comp's ML_GLASS_SPLIT values are these plus one.
    enum Step { kList, kParts, kBlend, kShallow };
    if (!splitPrograms_[0]) {
        const char* labels[] = {"transparent.list-tiles", "transparent.shade-parts", "transparent.blend-parts",
                                "transparent.shade-shallow-tiles"};
        for (int i = 0; i < int(splitPrograms_.size()); ++i) {
            shaders::Defines defines = splitDefines_;
            defines.emplace_back("ML_GLASS_SPLIT", std::to_string(i + 1));
            splitPrograms_[i] = gl::Program(labels[i], {{GL_COMPUTE_SHADER, "glass_shade.comp"}}, defines);
        }
    }
    const gl::Buffer& store = capture_->fragmentBuffer();
    const std::uint32_t base = capture_->deepTileWordOffset();
    // Nothing listed yet: every dispatch empty (0 x 0 x 1).
    const GLuint header[ML_GLASS_DEEP_TILES] = {0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0};
    glNamedBufferSubData(store.id(), GLintptr(base) * 4, sizeof(header), header);
    ctx.scene.bindTextureSet(textureSet);
    for (const gl::Program& program : splitPrograms_) {
        program.set("u_colorBase", capture_->colorWordOffset());
        program.set("u_textureSet", textureSet);
        program.set("u_deepBase", base);
        program.set("u_glassWindow", capture_->window());
        program.set("u_windowTiles", capture_->windowTiles().x * capture_->windowTiles().y);
        program.set("u_sorts", 0u);
        program.set("u_blends", 0u);
        program.set("u_storesColors", 0u);
    }
    // Sorts every window tile's pixels, lists the deep tiles and their parts, and the other tiles with glass.
    splitPrograms_[kList].use();
    splitPrograms_[kList].set("u_deepFragments", kDeepFragments);
    splitPrograms_[kList].set("u_maxParts", layerGroups_);
    splitPrograms_[kList].set("u_sorts", 1u);
    glDispatchCompute(capture_->windowTiles().x, capture_->windowTiles().y, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, store.id());
    // Every listed part, its colours stored; beside it (no barrier: other tiles, other words)
    // every other listed tile shaded and blended.
    splitPrograms_[kParts].use();
    splitPrograms_[kParts].set("u_storesColors", 1u);
    glDispatchComputeIndirect(GLintptr(base + ML_GLASS_DEEP_PARTS_DISPATCH) * 4);
    splitPrograms_[kShallow].use();
    splitPrograms_[kShallow].set("u_blends", 1u);
    glDispatchComputeIndirect(GLintptr(base + ML_GLASS_SHALLOW_DISPATCH) * 4);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // Each listed tile's parts blended.
    splitPrograms_[kBlend].use();
    glDispatchComputeIndirect(GLintptr(base + ML_GLASS_DEEP_BLEND_DISPATCH) * 4);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

}  // namespace ml
