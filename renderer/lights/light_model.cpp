#include "renderer/lights/light_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "renderer/hash.h"

namespace ml {

const char* brdfName(Brdf brdf) { return brdf == Brdf::Ggx ? "ggx" : "blinn-phong"; }

Brdf parseBrdf(const std::string& text) {
    if (text == "ggx") return Brdf::Ggx;
    if (text == "blinn-phong") return Brdf::BlinnPhong;
    throw std::invalid_argument("--brdf '" + text + "': expected ggx or blinn-phong");
}

float unitlessLightExposure(Brdf brdf) { return brdf == Brdf::Ggx ? std::numbers::pi_v<float> : 1.0f; }

const char* falloffName(Falloff falloff) {
    switch (falloff) {
    case Falloff::Smooth: return "smooth";
    case Falloff::Gltf: return "gltf";
    case Falloff::Stochastic: return "stochastic";
    case Falloff::Untruncated: return "untruncated";
    }
    return "?";
}

float cutoffRadius(const glm::vec3& color, float cutoff) {
    const float brightest = std::max({color.r, color.g, color.b, 0.0f});
    return std::sqrt(brightest / cutoff);
}

void applyCutoffRadii(std::vector<Light>& lights, float cutoff) {
    for (Light& l : lights)
        if (l.type != LightType::Directional) l.radius = cutoffRadius(l.color, cutoff);
}

float stochasticRadius(const glm::vec3& color, float cutoff, std::uint32_t index, std::uint32_t drawSeed) {
    const float xi = 1.0f - hashToUnitFloat(pcgHash(index) ^ drawSeed);
    return cutoffRadius(color, cutoff) / std::sqrt(xi);
}

std::uint32_t stochasticDrawSeed(std::uint32_t frameIndex, std::uint32_t draw) {
    return pcgHash(frameIndex ^ pcgHash(draw + 0x5851F42Du));
}

}  // namespace ml
