// Naive forward shading: raster the scene once; every fragment loops over every light.
// O(fragments x lights), and exact: the reference every other method is held to. A frame of more
// than kNaivePixelLightsPerDraw pixel-lights is drawn in horizontal bands, one scissored draw
// each, waited for before the next (a flush alone still met the watchdog on an H100), so no
// submission runs into the driver's watchdog (seconds on NVIDIA): the physical reference at tens
// of thousands of lights and more is such a frame. A pass inside a band that scissors its own
// raster keeps to the band (gl::ScissorScope). Every band's opaque frame is drawn before any
// band's glass: a transmissive surface sees the opaque frame beyond its band.
#pragma once

#include "renderer/scene/raster_program.h"
#include "renderer/methods/shading_method.h"
#include "renderer/passes/transparent_pass.h"

namespace ml {

// About 0.1 s of naive fragment shading on an H100 (1.2e10 pixel-lights a second measured).
inline constexpr double kNaivePixelLightsPerDraw = 1e9;

class NaiveForward final : public ShadingMethod {
public:
    NaiveForward(std::uint32_t materialFeatures, const ClusteringSettings& lights, const TransparencySettings& transparency = {},
                 double pixelLightsPerDraw = kNaivePixelLightsPerDraw);
    std::string name() const override { return "naive"; }
    void render(const FrameContext& ctx) override;
    const GlassFragments* transparentCapture() const override { return transparent_.capture(); }

private:
    void shadeOpaque(const FrameContext& ctx);

    double pixelLightsPerDraw_;
    RasterProgram program_;
    TransparentPass transparent_;
};

}  // namespace ml
