// --shadows sampled (issue 63): exact unshadowed lighting times a sampled, reused and filtered
// visibility ratio (Heitz, Hill and McGuire 2018). The compute lighting (deferred_lighting.comp
// compiled with ML_SHADOW_SAMPLES) sums every light of a pixel's list unshadowed, draws
// raysPerPixel of them in proportion to their unshadowed luminance
// (glsl/include/shadow_sampling.glsl); it writes the unshadowed frame and, here, the lights' part
// of each pixel, where its surface is and the rays it drew. Then, per frame:
//
//   shadows.trace     the drawn rays traced, the share that reach their light the pixel's ratio
//                     (glsl/shadow_trace.comp)
//   shadows.temporal  (--shadow-reuse temporal) the ratio averaged with the pixel's reprojected
//                     history where the same surface was there, the history clamped to the
//                     neighbourhood (glsl/shadow_temporal.comp)
//   shadows.denoise   the ratio filtered over the pixel's neighbours on its surface (unless
//                     --shadow-denoise off) and multiplied into the lights' part of the HDR
//                     frame (glsl/shadow_denoise.comp)
//
// Deterministic: the draws hash the pixel, the light and the frame's seed (FrameUniforms::counts.w,
// stochasticDrawSeed of the frame index), and the history is the frames rendered before. Where
// every light a pixel draws from is seen (or none is), the frame is the unshadowed (or unlit) one
// exactly, whatever the filter: noise lives only in the penumbrae.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "renderer/frame_targets.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/pass_timer.h"
#include "renderer/raytracing/shadow_mode.h"

namespace ml {

class SampledShadowPass {
public:
    explicit SampledShadowPass(const SampledShadowSettings& settings);

    const SampledShadowSettings& settings() const { return settings_; }
    // Binds the images the compute lighting writes beside the HDR target, sized as `targets`.
    void bindForLighting(const FrameTargets& targets);
    // Traces the rays the lighting drew, reuses and filters the ratio they measure and scales the
    // lights' part of targets.hdr() by it; `viewProj` the frame's, kept for the next frame's
    // reprojection; `shading` the lighting program's defines (lightShadingDefines), which the
    // tracing shares (the BVH's width, the draws a pixel, the ray count).
    void run(const FrameTargets& targets, const glm::mat4& viewProj, const shaders::Defines& shading, PassTimer& timer);
    // Forgets the history (the next frame reuses nothing): a cut, or a new light set.
    void resetHistory() { hasHistory_ = false; }
    std::size_t bytes() const;

    // The most frames a pixel's reused ratio averages (1 / weight of the newest at the most).
    static constexpr float kMaxHistoryFrames = 32.0f;
    // The filter's reach in pixels each side.
    static constexpr int kFilterRadius = 2;

private:
    void prepare(int width, int height);
    void trace(const FrameTargets& targets, const shaders::Defines& shading, PassTimer& timer);

    SampledShadowSettings settings_;
    gl::Program traceProgram_, temporalProgram_, denoiseProgram_;
    shaders::Defines traceDefines_;  // traceProgram_'s
    gl::Texture2D light_, rays_;
    std::array<gl::Texture2D, 2> guide_, history_;  // this frame's and the previous frame's, by parity
    int current_ = 0;
    bool hasHistory_ = false;
    glm::mat4 previousViewProj_{1.0f};
};

}  // namespace ml
