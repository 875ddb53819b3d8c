#include "app/light_radius.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "renderer/lights/light_set.h"

namespace ml::app {

namespace {

std::optional<double> wholeNumber(const std::string& text) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

std::string formatNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

std::string RadiusSpec::text() const {
    switch (kind) {
    case Kind::SceneDefault: return "default";
    case Kind::Fixed: return formatNumber(value);
    case Kind::Overlap: return "overlap:" + formatNumber(value);
    }
    return "?";
}

std::optional<RadiusSpec> tryParseRadius(const std::string& text) {
    RadiusSpec r;
    if (text == "default") return r;
    constexpr std::string_view kOverlap = "overlap:";
    if (text.starts_with(kOverlap)) {
        const auto k = wholeNumber(text.substr(kOverlap.size()));
        if (!k || !(*k > 0.0)) return std::nullopt;
        r.kind = RadiusSpec::Kind::Overlap;
        r.value = *k;
        return r;
    }
    const auto v = wholeNumber(text);
    if (!v || !(*v >= 0.0)) return std::nullopt;
    r.kind = RadiusSpec::Kind::Fixed;
    r.value = *v;
    return r;
}

RadiusSpec parseRadius(const std::string& text) {
    if (auto r = tryParseRadius(text)) return *r;
    throw std::invalid_argument("--light-radius '" + text + "': " + kRadiusSyntax);
}

double overlapRadius(double volume, std::uint64_t lights, double overlap) {
    if (lights == 0 || !(volume > 0.0)) return 0.0;
    return std::cbrt(3.0 * overlap * volume / (4.0 * std::numbers::pi * static_cast<double>(lights)));
}

float resolveRadius(const RadiusSpec& spec, const Bounds& sceneBounds, long long generatedLights) {
    switch (spec.kind) {
    case RadiusSpec::Kind::Fixed: return static_cast<float>(spec.value);
    case RadiusSpec::Kind::Overlap:
        if (generatedLights > 0) {
            const glm::vec3 size = lightVolume(sceneBounds).size();
            const double volume = static_cast<double>(size.x) * size.y * size.z;
            return static_cast<float>(overlapRadius(volume, static_cast<std::uint64_t>(generatedLights), spec.value));
        }
        break;
    case RadiusSpec::Kind::SceneDefault: break;
    }
    return defaultLightRadius(sceneBounds);
}

}  // namespace ml::app
