// --vis-raster: how the visibility buffer rasters its triangle ids (renderer/passes/compute_raster.h).
#pragma once

#include <string>

namespace ml {

// --vis-raster: how the visibility buffer rasters its ids.
enum class VisibilityRaster {
    Auto,            // the default: hardware, for now (ComputeRaster::resolve says why)
    Hardware,        // the graphics pipeline, ids by image atomics behind the depth test
    Compute,         // compute, 64-bit atomics where the GPU has them, else two passes
    ComputeTwoPass,  // compute with two passes of 32-bit atomics, whatever the GPU has
};
VisibilityRaster parseVisibilityRaster(const std::string& text);  // throws std::invalid_argument naming the value
const char* visibilityRasterName(VisibilityRaster raster);

}  // namespace ml
