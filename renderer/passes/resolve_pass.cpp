#include "renderer/passes/resolve_pass.h"

#include <string>

#include "glsl/include/bindings.h"

namespace ml {

const char* ResolvePass::passName(const TargetSampling& sampling) {
    return sampling.msaa > 1 ? "msaa.resolve" : "supersample.resolve";
}

void ResolvePass::run(const FrameTargets& targets) {
    const TargetSampling& sampling = targets.sampling();
    if (!sampling.resolves()) return;
    if (!program_ || !(compiledFor_ == sampling)) {
        program_.emplace(gl::Program::compute("resolve_samples.comp", {{"ML_MSAA_SAMPLES", std::to_string(sampling.msaa)},
                                                                      {"ML_SUPERSAMPLE", std::to_string(sampling.supersample)}}));
        compiledFor_ = sampling;
    }
    program_->use();
    // Deferred and the visibility buffer write the colour as an image (supersampled only).
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindTextureUnit(ML_TEX_RESOLVE_SOURCE, targets.hdr().id());
    glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gl::groupsFor(targets.outputWidth(), ML_TONEMAP_TILE), gl::groupsFor(targets.outputHeight(), ML_TONEMAP_TILE), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

}  // namespace ml
