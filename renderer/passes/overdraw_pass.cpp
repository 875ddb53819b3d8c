#include "renderer/passes/overdraw_pass.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"

namespace ml {

OverdrawStatistics overdrawStatistics(const std::vector<std::uint32_t>& counts) {
    OverdrawStatistics s;
    for (const std::uint32_t c : counts) {
        s.coveredPixels += c > 0;
        s.fragments += c;
        s.maxPerPixel = std::max(s.maxPerPixel, c);
    }
    return s;
}

OverdrawPass::OverdrawPass(std::uint32_t materialFeatures)
    : countProgram_("overdraw.count", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "overdraw_count.frag"}},
                    materialFeatures, RasterProgram::Reads::CoverageOnly),
      colorProgram_(gl::Program::compute("overdraw_colors.comp")) {}

void OverdrawPass::prepareTargets(const FrameTargets& targets) {
    if (!stamp_.update(targets)) return;
    counts_ = gl::Texture2D("overdraw.counts", GL_R32F, stamp_.width(), stamp_.height());
    fbo_ = gl::Framebuffer("overdraw", {&counts_}, &targets.depth());
}

void OverdrawPass::run(const SceneGpu& scene, const FrameTargets& targets, PassTimer& timer) {
    prepareTargets(targets);
    {
        auto pass = timer.pass("overdraw.count");
        fbo_.bind();
        glViewport(0, 0, stamp_.width(), stamp_.height());
        const float zero = 0.0f;
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, &zero);
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &depth::kClear);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(depth::kNearer);
        glDepthMask(GL_TRUE);
        glEnablei(GL_BLEND, 0);
        glBlendEquationi(0, GL_FUNC_ADD);
        glBlendFunci(0, GL_ONE, GL_ONE);
        scene.draw(countProgram_);
        glDisablei(GL_BLEND, 0);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    {
        auto pass = timer.pass("overdraw.colors");
        colorProgram_.use();
        glBindTextureUnit(ML_TEX_OVERDRAW_COUNTS, counts_.id());
        glBindImageTexture(ML_IMG_HDR, targets.hdr().id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glDispatchCompute(gl::groupsFor(stamp_.width(), ML_SCREEN_TILE), gl::groupsFor(stamp_.height(), ML_SCREEN_TILE), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
}

std::vector<std::uint32_t> OverdrawPass::readCounts() const {
    const std::size_t w = static_cast<std::size_t>(stamp_.width()), h = static_cast<std::size_t>(stamp_.height());
    std::vector<float> bottomUp(w * h);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(counts_.id(), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)), bottomUp.data());
    std::vector<std::uint32_t> counts(w * h);
    // GL's first row is the bottom one.
    for (std::size_t y = 0; y < h; ++y)
        for (std::size_t x = 0; x < w; ++x)
            counts[y * w + x] = static_cast<std::uint32_t>(std::lround(bottomUp[(h - 1 - y) * w + x]));
    return counts;
}

}  // namespace ml
