#include "renderer/passes/auto_exposure_pass.h"

#include <array>

#include "glsl/include/bindings.h"

namespace ml {

namespace {
constexpr std::array<float, 4> kUnset{0.0f, 0.0f, 0.0f, 0.0f};
}  // namespace

// Built on first use: built-in scenes keep a fixed exposure and never run it.
AutoExposurePass::AutoExposurePass() = default;

void AutoExposurePass::reset() {
    if (exposure_) exposure_.upload(kUnset.data(), sizeof(kUnset));
}

void AutoExposurePass::run(const FrameTargets& targets, float adaptation, PassTimer& timer) {
    if (!reduce_) {
        reduce_ = gl::Program::compute("exposure_reduce.comp");
        adapt_ = gl::Program::compute("exposure_adapt.comp");
        exposure_ = gl::Buffer("exposure.value", sizeof(kUnset), kUnset.data());
    }
    const int w = targets.outputWidth(), h = targets.outputHeight();
    const GLuint groupsX = gl::groupsFor(static_cast<std::size_t>(w), ML_EXPOSURE_TILE);
    const GLuint groupsY = gl::groupsFor(static_cast<std::size_t>(h), ML_EXPOSURE_TILE);
    const std::size_t tiles = static_cast<std::size_t>(groupsX) * groupsY;
    partials_.ensure(tiles * 2 * sizeof(float));
    {
        auto pass = timer.pass("exposure.reduce");
        reduce_.use();
        glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        partials_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE_PARTIALS);
        glDispatchCompute(groupsX, groupsY, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    {
        auto pass = timer.pass("exposure.adapt");
        adapt_.use();
        adapt_.set("u_partials", static_cast<unsigned>(tiles));
        adapt_.set("u_pixels", static_cast<float>(w) * static_cast<float>(h));
        adapt_.set("u_key", kAutoExposureKey);
        adapt_.set("u_adaptation", adaptation);
        adapt_.set("u_minLog2Exposure", -kAutoExposureMaxStops);
        adapt_.set("u_maxLog2Exposure", kAutoExposureMaxStops);
        partials_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE_PARTIALS);
        exposure_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE);
        glDispatchCompute(1, 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
}

void AutoExposurePass::bind() const { exposure_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_EXPOSURE); }

AutoExposureReading AutoExposurePass::read() const {
    if (!exposure_) return {};
    std::array<float, 4> v{};
    exposure_.download(v.data(), sizeof(v));
    return AutoExposureReading{v[0], v[1], v[2]};
}

}  // namespace ml
