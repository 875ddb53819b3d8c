// Naive forward shading: raster the scene once; every fragment loops over every light.
// O(fragments x lights), and exact: the reference every other method is held to.
#pragma once

#include "renderer/scene/raster_program.h"
#include "renderer/methods/shading_method.h"
#include "renderer/passes/transparent_pass.h"

namespace ml {

class NaiveForward final : public ShadingMethod {
public:
    NaiveForward(std::uint32_t materialFeatures, bool spotLights, const TransparencySettings& transparency = {});
    std::string name() const override { return "naive"; }
    void render(const FrameContext& ctx) override;
    const GlassFragments* transparentCapture() const override { return transparent_.capture(); }

private:
    void shadeOpaque(const FrameContext& ctx);

    RasterProgram program_;
    TransparentPass transparent_;
};

}  // namespace ml
