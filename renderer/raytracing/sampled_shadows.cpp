#include "renderer/raytracing/sampled_shadows.h"

#include "glsl/include/bindings.h"

namespace ml {

SampledShadowPass::SampledShadowPass(const SampledShadowSettings& settings)
    : settings_(settings),
      temporalProgram_(gl::Program::compute("shadow_temporal.comp")),
      denoiseProgram_(gl::Program::compute("shadow_denoise.comp")) {}

void SampledShadowPass::prepare(int width, int height) {
    if (light_ && light_.width() == width && light_.height() == height) return;
    light_ = gl::Texture2D("shadows.sampled-light", GL_RGBA32F, width, height);
    // The origin, then each draw's target, a layer of `height` rows each (ML_IMG_SHADOW_RAYS).
    rays_ = gl::Texture2D("shadows.sampled-rays", GL_RGBA32F, width, height * static_cast<int>(1 + settings_.raysPerPixel));
    for (int i = 0; i < 2; ++i) {
        guide_[i] = gl::Texture2D("shadows.sampled-guide", GL_RGBA32F, width, height);
        history_[i] = gl::Texture2D("shadows.sampled-history", GL_RG32F, width, height);
    }
    hasHistory_ = false;
}

void SampledShadowPass::bindForLighting(const FrameTargets& targets) {
    prepare(targets.width(), targets.height());
    current_ ^= 1;
    glBindImageTexture(ML_IMG_SHADOW_LIGHT, light_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(ML_IMG_SHADOW_GUIDE, guide_[current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(ML_IMG_SHADOW_RAYS, rays_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
}

void SampledShadowPass::trace(const FrameTargets& targets, const shaders::Defines& shading, PassTimer& timer) {
    if (!traceProgram_ || traceDefines_ != shading) {
        traceProgram_ = gl::Program::compute("shadow_trace.comp", shading);
        traceDefines_ = shading;
    }
    auto pass = timer.pass("shadows.trace");
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(ML_IMG_SHADOW_RAYS, rays_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(ML_IMG_SHADOW_LIGHT, light_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    traceProgram_.use();
    glDispatchCompute(gl::groupsFor(targets.width(), ML_SCREEN_TILE), gl::groupsFor(targets.height(), ML_SCREEN_TILE), 1);
}

void SampledShadowPass::run(const FrameTargets& targets, const glm::mat4& viewProj, const shaders::Defines& shading, PassTimer& timer) {
    const GLuint groupsX = gl::groupsFor(targets.width(), ML_SCREEN_TILE), groupsY = gl::groupsFor(targets.height(), ML_SCREEN_TILE);
    trace(targets, shading, timer);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindTextureUnit(ML_TEX_SHADOW_LIGHT, light_.id());
    glBindTextureUnit(ML_TEX_SHADOW_GUIDE, guide_[current_].id());
    if (settings_.temporal) {
        auto pass = timer.pass("shadows.temporal");
        const int previous = current_ ^ 1;
        glBindTextureUnit(ML_TEX_SHADOW_GUIDE_PREVIOUS, guide_[previous].id());
        glBindTextureUnit(ML_TEX_SHADOW_HISTORY, history_[previous].id());
        glBindImageTexture(ML_IMG_SHADOW_HISTORY, history_[current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
        temporalProgram_.use();
        temporalProgram_.set("u_previousViewProj", previousViewProj_);
        temporalProgram_.set("u_hasHistory", hasHistory_ ? 1u : 0u);
        temporalProgram_.set("u_maxHistoryFrames", kMaxHistoryFrames);
        glDispatchCompute(groupsX, groupsY, 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        glBindTextureUnit(ML_TEX_SHADOW_HISTORY, history_[current_].id());
        hasHistory_ = true;
    }
    {
        auto pass = timer.pass("shadows.denoise");
        glBindImageTexture(ML_IMG_HDR, targets.hdr().id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        denoiseProgram_.use();
        denoiseProgram_.set("u_reused", settings_.temporal ? 1u : 0u);
        denoiseProgram_.set("u_radius", settings_.denoise ? kFilterRadius : 0);
        glDispatchCompute(groupsX, groupsY, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    previousViewProj_ = viewProj;
}

std::size_t SampledShadowPass::bytes() const {
    if (!light_) return 0;
    const std::size_t pixels = static_cast<std::size_t>(light_.width()) * light_.height();
    return pixels * (16 + 16 * (1 + settings_.raysPerPixel) + 2 * 16 + 2 * 8);
}

}  // namespace ml
