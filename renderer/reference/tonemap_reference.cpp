#include "renderer/reference/tonemap_reference.h"

#include <algorithm>
#include <cmath>

namespace ml {

glm::vec3 tonemapToSrgb(glm::vec3 hdr, float exposure) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) {
        const float c = std::max(hdr[i] * exposure, 0.0f);
        const float mapped = std::clamp(c / (1.0f + c), 0.0f, 1.0f);
        out[i] = mapped < 0.0031308f ? 12.92f * mapped : 1.055f * std::pow(mapped, 1.0f / 2.4f) - 0.055f;
    }
    return out;
}

}  // namespace ml
