#include "renderer/passes/tonemap_pass.h"

#include <string>

#include "glsl/include/bindings.h"

namespace ml {

namespace {

// Pixels a tonemapping invocation reads and writes (glsl/tonemap.comp).
constexpr int kTonemapPixels = 4;

shaders::Defines tonemapDefines(bool autoExposure) {
    shaders::Defines defines{{"ML_TONEMAP_PIXELS", std::to_string(kTonemapPixels)}};
    if (autoExposure) defines.emplace_back("ML_AUTO_EXPOSURE", "1");
    return defines;
}

}  // namespace

TonemapPass::TonemapPass() : program_(gl::Program::compute("tonemap.comp", tonemapDefines(false))) {}

void TonemapPass::run(const FrameTargets& targets, float exposure, bool displayColors, const AutoExposurePass* autoExposure) {
    if (autoExposure && !autoExposureProgram_)
        autoExposureProgram_ = gl::Program::compute("tonemap.comp", tonemapDefines(true));
    const gl::Program& program = autoExposure ? autoExposureProgram_ : program_;
    if (autoExposure) autoExposure->bind();
    program.use();
    program.set("u_exposure", exposure);
    program.set("u_displayColors", displayColors ? 1u : 0u);
    glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(ML_IMG_LDR, targets.ldr().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
    glDispatchCompute(gl::groupsFor(targets.outputWidth(), ML_TONEMAP_TILE), gl::groupsFor(targets.outputHeight(), ML_TONEMAP_TILE * kTonemapPixels), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace ml
