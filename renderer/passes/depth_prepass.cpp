#include "renderer/passes/depth_prepass.h"

#include "renderer/gl/depth_convention.h"

namespace ml {

DepthPrePass::DepthPrePass(std::string_view label, std::uint32_t materialFeatures)
    : depthProgram_(label, {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "depth_only.frag"}}, materialFeatures,
                    RasterProgram::Reads::CoverageOnly) {}

void DepthPrePass::drawDepth(const SceneGpu& scene, const gl::Framebuffer& fbo) const {
    fbo.bind();
    const GLint clearStencil = 0;
    glClearNamedFramebufferiv(fbo.id(), GL_STENCIL, 0, &clearStencil);
    depth::beginNearestDepth(fbo.id());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    scene.draw(depthProgram_);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the light assignment may read this depth next
}

void DepthPrePass::drawNearestOnce(const SceneGpu& scene, const RasterProgram& program) {
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    scene.draw(program);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(depth::kNearer);
    glDepthMask(GL_TRUE);
}

}  // namespace ml
