#include "renderer/raytracing/shadow_mode.h"

#include <stdexcept>

namespace ml {

const char* shadowsName(Shadows shadows) {
    switch (shadows) {
    case Shadows::Off: return "off";
    case Shadows::Rays: return "rays";
    case Shadows::Sampled: return "sampled";
    }
    return "?";
}

Shadows parseShadows(const std::string& text) {
    if (text == "off") return Shadows::Off;
    if (text == "rays") return Shadows::Rays;
    if (text == "sampled") return Shadows::Sampled;
    throw std::invalid_argument("--shadows '" + text + "': expected off (lights pass through everything), rays (an exact shadow ray per "
                                "point and light) or sampled (a few rays a pixel, the visibility ratio reused and filtered)");
}

std::uint32_t checkShadowRaysPerPixel(int rays) {
    if (rays == 1 || rays == 2 || rays == 4) return static_cast<std::uint32_t>(rays);
    throw std::invalid_argument("--shadow-rays-per-pixel " + std::to_string(rays) + ": expected 1, 2 or 4");
}

}  // namespace ml
