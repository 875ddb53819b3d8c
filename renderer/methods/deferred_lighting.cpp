#include "renderer/methods/deferred_lighting.h"

#include "glsl/include/bindings.h"

namespace ml {

shaders::Defines deferredLightingDefines(const ClusteringSettings& clustering, const GBuffer& gbuffer) {
    shaders::Defines defines = lightListDefines(clustering);
    for (const auto& define : gbuffer.defines()) defines.push_back(define);
    return defines;
}

void bindDeferredLightingInputs(const GBuffer& gbuffer, const FrameContext& ctx, const ClusteredLighting& clustering) {
    gbuffer.bindForReading();
    glBindTextureUnit(ML_TEX_DEPTH, ctx.targets.opaqueDepth().id());
    ctx.bindLightsForShading();
    clustering.bindForShading();
}

void dispatchComputeLighting(const FrameContext& ctx) {
    const FrameTargets& targets = ctx.targets;
    if (ctx.sampledShadows) ctx.sampledShadows->bindForLighting(targets);
    glBindImageTexture(ML_IMG_HDR, targets.hdr().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gl::groupsFor(targets.width(), ML_SCREEN_TILE), gl::groupsFor(targets.height(), ML_SCREEN_TILE), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void applySampledShadows(const FrameContext& ctx, const ClusteringSettings& clustering) {
    if (ctx.sampledShadows) ctx.sampledShadows->run(ctx.targets, ctx.uniforms.viewProj, lightShadingDefines(clustering), ctx.timer);
}

}  // namespace ml
