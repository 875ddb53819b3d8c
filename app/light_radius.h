// `--light-radius` as every command takes it (render, view, bench and a sweep's "radius"):
//
//   R          a radius in scene units (>= 0)
//   default    a tenth of the scene's diagonal
//   overlap:K  the radius at which about K generated lights reach any point of the light volume
//
// One parser, so a value one command takes works in all of them, and a bad one is refused when
// the flags are read, before any scene loads.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scenes/scene.h"

namespace ml::app {

struct RadiusSpec {
    enum class Kind { SceneDefault, Fixed, Overlap };
    Kind kind = Kind::SceneDefault;
    double value = 0.0;  // Fixed: the radius; Overlap: K
    std::string text() const;  // "default", "2.5", "overlap:32"
};

inline constexpr const char* kRadiusSyntax =
    "expected a radius >= 0, \"default\" (a tenth of the scene's diagonal) or \"overlap:K\" (K lights reach a point)";

// Nothing where `text` is none of the three forms.
std::optional<RadiusSpec> tryParseRadius(const std::string& text);
// Throws std::invalid_argument: "--light-radius 'x': expected ...".
RadiusSpec parseRadius(const std::string& text);

// n lights uniform in a volume v, each a sphere of radius r, cover a point on average
// n * (4/3) pi r^3 / v times; solving for `overlap` lights per point:
//   r = cbrt(3 * overlap * v / (4 * pi * n))
// so r shrinks as n^(-1/3) and the shading work per pixel stays about constant.
double overlapRadius(double volume, std::uint64_t lights, double overlap);

// The radius in scene units for `generatedLights` lights in the light volume of `sceneBounds`
// (overlap:K with no generated lights: the scene's default).
float resolveRadius(const RadiusSpec& spec, const Bounds& sceneBounds, long long generatedLights);

}  // namespace ml::app
