// --shadows: whether a light stops at what stands between it and the point it lights.
//   off   lights reach every point in their range (the model before issue 62)
//   rays  an exact shadow ray for every (point, light) pair that adds light, in every method,
//         naive tracing the same rays (glsl/include/shadow_rays.glsl)
#pragma once

#include <string>

namespace ml {

enum class Shadows { Off, Rays };

const char* shadowsName(Shadows shadows);
// "off" or "rays"; anything else throws std::invalid_argument naming --shadows.
Shadows parseShadows(const std::string& text);

}  // namespace ml
