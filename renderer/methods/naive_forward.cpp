#include "renderer/methods/naive_forward.h"

#include "glsl/include/bindings.h"

namespace ml {

NaiveForward::NaiveForward(std::uint32_t materialFeatures, bool spotLights, const TransparencySettings& transparency)
    : program_("naive_forward", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "naive_forward.frag"}}, materialFeatures,
               RasterProgram::Reads::Material, {spotLightsDefine(spotLights)}),
      transparent_(TransparentPass::overAllLights("naive.transparent", materialFeatures, spotLights, transparency)) {}

void NaiveForward::render(const FrameContext& ctx) {
    shadeOpaque(ctx);
    transparent_.render(ctx, nullptr);
}

void NaiveForward::shadeOpaque(const FrameContext& ctx) {
    auto pass = ctx.timer.pass("naive.shade");
    ctx.targets.hdrFramebuffer().bind();
    glViewport(0, 0, ctx.targets.width(), ctx.targets.height());
    const float clearColor[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    const float clearDepth = 1.0f;
    glClearNamedFramebufferfv(ctx.targets.hdrFramebuffer().id(), GL_COLOR, 0, clearColor);
    glClearNamedFramebufferfv(ctx.targets.hdrFramebuffer().id(), GL_DEPTH, 0, &clearDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    ctx.lights.bindForReading();
    ctx.scene.draw(program_);
}

}  // namespace ml
