// CPU mirror of glsl/include/tonemap.glsl: exposure, Reinhard per channel, sRGB encoding.
#pragma once

#include <glm/glm.hpp>

#include "renderer/image/image.h"

namespace ml {

glm::vec3 tonemapToSrgb(glm::vec3 hdr, float exposure);
// A whole linear image through the same tonemap, rounded to 8 bits (alpha 255): what the GPU's
// tonemap pass writes for a frame without bloom.
RgbaImage tonemapImage(const FloatImage& hdr, float exposure);

}  // namespace ml
