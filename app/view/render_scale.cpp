#include "app/view/render_scale.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ml::app {

float softwareRenderScale(int width, int height) {
    const double pixels = static_cast<double>(width) * height;
    if (pixels <= kSoftwarePixelBudget) return 1.0f;
    const double scale = std::floor(std::sqrt(kSoftwarePixelBudget / pixels) * 20.0) / 20.0;
    return std::max(kMinRenderScale, static_cast<float>(scale));
}

int scaledSide(int side, float scale) { return std::max(1, static_cast<int>(std::lround(side * static_cast<double>(scale)))); }

void validateRenderScale(float scale) {
    if (!(std::isfinite(scale) && scale >= kMinRenderScale && scale <= 1.0f))
        throw std::invalid_argument("--render-scale " + std::to_string(scale) + ": must be between 0.1 and 1");
}

}  // namespace ml::app
