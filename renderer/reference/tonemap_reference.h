// CPU mirror of glsl/include/tonemap.glsl: exposure, Reinhard per channel, sRGB encoding.
#pragma once

#include <glm/glm.hpp>

namespace ml {

glm::vec3 tonemapToSrgb(glm::vec3 hdr, float exposure);

}  // namespace ml
