#include "renderer/raytracing/shadow_mode.h"

#include <stdexcept>

namespace ml {

const char* shadowsName(Shadows shadows) { return shadows == Shadows::Rays ? "rays" : "off"; }

Shadows parseShadows(const std::string& text) {
    if (text == "off") return Shadows::Off;
    if (text == "rays") return Shadows::Rays;
    throw std::invalid_argument("--shadows '" + text + "': expected off (lights pass through everything) or rays (an exact shadow ray per point and light)");
}

}  // namespace ml
