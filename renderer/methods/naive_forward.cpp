#include "renderer/methods/naive_forward.h"

#include <algorithm>
#include <cmath>

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"
#include "renderer/gl/scissor_scope.h"

namespace ml {

NaiveForward::NaiveForward(std::uint32_t materialFeatures, const ClusteringSettings& lights, const TransparencySettings& transparency,
                           double pixelLightsPerDraw)
    : pixelLightsPerDraw_(pixelLightsPerDraw),
      program_("naive_forward", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "naive_forward.frag"}}, materialFeatures,
               RasterProgram::Reads::Material, lightShadingDefines(lights)),
      transparent_(TransparentPass::overAllLights("naive.transparent", materialFeatures, lights, transparency)) {}

void NaiveForward::render(const FrameContext& ctx) {
    const int width = ctx.targets.width(), height = ctx.targets.height();
    const double pixelLights = static_cast<double>(width) * height * std::max<std::uint32_t>(ctx.lights.count(), 1u);
    const int bands = std::clamp(static_cast<int>(std::ceil(pixelLights / pixelLightsPerDraw_)), 1, height);
    if (bands == 1) {
        shadeOpaque(ctx);
        transparent_.render(ctx, nullptr);
        return;
    }
    // Every band's opaque frame before any glass: a transmissive surface sees the opaque frame
    // behind it beyond its own band (refracted, blurred), copied once when the last band is drawn.
    const auto inBands = [&](const auto& drawBand) {
        for (int band = 0; band < bands; ++band) {
            const int y0 = height * band / bands, y1 = height * (band + 1) / bands;
            gl::ScissorScope scissor({0, y0, width, y1 - y0});
            drawBand();
            glFinish();  // each band its own submission, finished before the next
        }
    };
    inBands([&] { shadeOpaque(ctx); });
    transparent_.copyOpaqueFrame(ctx);
    inBands([&] { transparent_.render(ctx, nullptr, OpaqueFrame::AlreadyCopied); });
}

void NaiveForward::shadeOpaque(const FrameContext& ctx) {
    auto pass = ctx.timer.pass("naive.shade");
    ctx.targets.hdrFramebuffer().bind();
    glViewport(0, 0, ctx.targets.width(), ctx.targets.height());
    const float clearColor[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(ctx.targets.hdrFramebuffer().id(), GL_COLOR, 0, clearColor);
    depth::beginNearestDepth(ctx.targets.hdrFramebuffer().id());
    ctx.bindLightsForShading();
    ctx.scene.draw(program_);
}

}  // namespace ml
