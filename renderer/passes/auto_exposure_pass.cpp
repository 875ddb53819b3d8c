#include "renderer/passes/auto_exposure_pass.h"

#include <array>

#include "glsl/include/bindings.h"

namespace ml {

namespace {
constexpr std::array<float, 4> kUnset{0.0f, 0.0f, 0.0f, 0.0f};
constexpr std::size_t kPartialsHeader = 2 * sizeof(GLuint);  // glsl/exposure_reduce.comp: finished, pad
}  // namespace

// Built on first use: built-in scenes keep a fixed exposure and never run it.
AutoExposurePass::AutoExposurePass() = default;

void AutoExposurePass::reset() {
    if (exposure_) exposure_.upload(kUnset.data(), sizeof(kUnset));
}

void AutoExposurePass::run(const FrameTargets& targets, float adaptation, PassTimer& timer) {
    if (!reduce_) {
        reduce_ = gl::Program::compute("exposure_reduce.comp");
        exposure_ = gl::Buffer("exposure.value", sizeof(kUnset), kUnset.data());
    }
    const int w = targets.outputWidth(), h = targets.outputHeight();
    const GLuint groupsX = gl::groupsFor(static_cast<std::size_t>(w), ML_EXPOSURE_TILE);
    const GLuint groupsY = gl::groupsFor(static_cast<std::size_t>(h), ML_EXPOSURE_TILE);
    const std::size_t tiles = static_cast<std::size_t>(groupsX) * groupsY;
    // The finished-workgroup counter, then a partial per tile; the last workgroup zeroes the counter.
    if (partials_.ensure(kPartialsHeader + tiles * 2 * sizeof(float))) {
        const std::array<GLuint, 2> zero{0, 0};
        partials_.buffer().upload(zero.data(), sizeof(zero));
    }
    auto pass = timer.pass("exposure.reduce");
    reduce_.use();
    reduce_.set("u_pixels", static_cast<float>(w) * static_cast<float>(h));
    reduce_.set("u_key", kAutoExposureKey);
    reduce_.set("u_adaptation", adaptation);
    reduce_.set("u_minLog2Exposure", -kAutoExposureMaxStops);
    reduce_.set("u_maxLog2Exposure", kAutoExposureMaxStops);
    glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    partials_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE_PARTIALS);
    exposure_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE);
    glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void AutoExposurePass::bind() const { exposure_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE); }

AutoExposureReading AutoExposurePass::read() const {
    if (!exposure_) return {};
    std::array<float, 4> v{};
    exposure_.download(v.data(), sizeof(v));
    return AutoExposureReading{v[0], v[1], v[2]};
}

}  // namespace ml
