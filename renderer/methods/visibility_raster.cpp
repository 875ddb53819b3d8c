#include "renderer/methods/visibility_raster.h"

#include <stdexcept>

namespace ml {

VisibilityRaster parseVisibilityRaster(const std::string& text) {
    if (text == "auto") return VisibilityRaster::Auto;
    if (text == "hardware") return VisibilityRaster::Hardware;
    if (text == "compute") return VisibilityRaster::Compute;
    if (text == "compute-two-pass") return VisibilityRaster::ComputeTwoPass;
    throw std::invalid_argument("--vis-raster '" + text + "': expected auto, hardware, compute or compute-two-pass");
}

const char* visibilityRasterName(VisibilityRaster raster) {
    switch (raster) {
    case VisibilityRaster::Auto: return "auto";
    case VisibilityRaster::Hardware: return "hardware";
    case VisibilityRaster::Compute: return "compute";
    case VisibilityRaster::ComputeTwoPass: return "compute-two-pass";
    }
    return "?";
}

}  // namespace ml
