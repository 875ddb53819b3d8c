// The raster set-up every pass over the transparent (BLEND) draw ranges shares: the shading
// passes (renderer/passes/transparent_pass.h) and the clustering's transparent samples
// (renderer/clustering/clustered_lighting.h). It sits with the scene so that the clustering
// need not include a pass.
#pragma once

#include <cstdint>
#include <string_view>

#include "renderer/frame_targets.h"
#include "renderer/gl/shader_sources.h"
#include "renderer/scene/raster_program.h"

namespace ml {

// A raster program over the transparent ranges (SceneGpu::drawTransparent) with `fragmentShader`:
// empty where no material is BLEND, so such a scene compiles nothing; no alpha-tested variant
// (BLEND ignores alphaCutoff).
RasterProgram transparentRangesProgram(std::string_view label, const char* fragmentShader, std::uint32_t materialFeatures,
                                       shaders::Defines defines);
// Binds the frame's colour target and depth for rastering transparent ranges: tested against the
// opaque depth, which they do not write (the caller restores glDepthMask).
void beginTransparentRaster(const FrameTargets& targets);

}  // namespace ml
