#include "renderer/scene/transparent_ranges.h"

#include <utility>

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"

namespace ml {

RasterProgram transparentRangesProgram(std::string_view label, const char* fragmentShader, std::uint32_t materialFeatures,
                                       shaders::Defines defines) {
    if (!(materialFeatures & ML_FEATURE_BLEND)) return {};
    return RasterProgram(label, {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, fragmentShader}},
                         materialFeatures & ~std::uint32_t(ML_FEATURE_ALPHA_TEST), RasterProgram::Reads::Material, std::move(defines));
}

void beginTransparentRaster(const FrameTargets& targets) {
    targets.hdrFramebuffer().bind();
    glViewport(0, 0, targets.width(), targets.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth::kNearer);
    glDepthMask(GL_FALSE);
}

}  // namespace ml
