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

RgbaImage tonemapImage(const FloatImage& hdr, float exposure) {
    RgbaImage out{hdr.width, hdr.height, std::vector<std::uint8_t>(static_cast<std::size_t>(hdr.width) * hdr.height * 4, 255)};
    for (std::size_t p = 0; p < static_cast<std::size_t>(hdr.width) * hdr.height; ++p) {
        const glm::vec3 c = tonemapToSrgb(glm::vec3(hdr.pixels[p * 3], hdr.pixels[p * 3 + 1], hdr.pixels[p * 3 + 2]), exposure);
        for (int i = 0; i < 3; ++i) out.pixels[p * 4 + i] = static_cast<std::uint8_t>(std::lround(c[i] * 255.0f));
    }
    return out;
}

}  // namespace ml
