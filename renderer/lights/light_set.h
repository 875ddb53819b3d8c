// The CPU side of the light set: generation from a seed, validation, and JSON files.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace ml {

// docs/lights-and-shading.md. Point and spot lights are clustered; directional lights ("suns")
// reach every point and are shaded outside the clusters.
enum class LightType { Point, Spot, Directional };
const char* lightTypeName(LightType type);

struct Light {
    glm::vec3 position{0.0f};  // point and spot
    float radius = 1.0f;       // point and spot: the falloff reaches exactly zero here
    glm::vec3 color{1.0f};     // linear colour times intensity
    LightType type = LightType::Point;  // after the point light's fields: {position, radius, color} makes one
    // Spot and directional: where the light points (the GPU and the CPU reference normalise it;
    // kept as given so that a light file round-trips exactly).
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    float innerConeAngle = 0.0f;            // spot, radians: full intensity inside
    float outerConeAngle = 0.7853981634f;   // spot, radians, in (0, pi/2]: exactly zero at and beyond
    // Generated lights drift (--drift-speed); a light a file places (a glTF file's
    // KHR_lights_punctual, a --lights-file) stays where the file puts it.
    bool drifts = true;
};

// The lights the clusters hold (points and spots), in order; directional ones left out.
std::vector<Light> clusteredLights(const std::vector<Light>& lights);

struct LightGeneration {
    std::uint32_t count = 1024;
    float radius = 3.0f;
    float intensity = 1.0f;
    std::uint32_t seed = 1;
    float spotShare = 0.0f;      // share of the lights that are spots (--spot-share)
    float spotAngleDeg = 0.0f;   // a spot's outer cone angle (--spot-angle); 0: each in [20, 60] degrees
};
// The inner cone of a generated spot, as a share of its outer cone.
inline constexpr float kGeneratedSpotInnerShare = 0.7f;

// Positions uniform inside the bounds, hues spread over the colour wheel; spots (a share of
// them, chosen per light) point in directions uniform over the sphere. The same seed gives the
// same lights on every machine (integer hashing, no std:: distributions), and the points of a
// set keep their places and colours whatever the spot share.
std::vector<Light> generateLights(const Bounds& bounds, const LightGeneration& generation);

// The volume lights are placed in and drift through: the scene's bounds, with every side at
// least a tenth of the diagonal (a flat scene such as `plane` gets a layer of air above it).
Bounds lightVolume(const Bounds& sceneBounds);

// A file's lights (KHR_lights_punctual) in this renderer's model: colour = the file's linear
// colour times its intensity, used as given (candela for points and spots, lux for directional
// lights, as Khronos' Sample Viewer does); radius = the file's range, or where a light without
// one stops mattering: the distance at which intensity / d^2 of its brightest channel falls to
// `cutoff` (--light-cutoff; by default kUnboundedLightThreshold, 1/255, a step of the 8-bit
// output at exposure 1).
inline constexpr float kUnboundedLightThreshold = 1.0f / 255.0f;
float radiusWithoutRange(const glm::vec3& color, float cutoff = kUnboundedLightThreshold);
std::vector<Light> lightsFromScene(const Scene& scene, float cutoff = kUnboundedLightThreshold);

// A radius that suits the scene when none is given: a tenth of the bounds' diagonal.
float defaultLightRadius(const Bounds& bounds);

// Throws std::invalid_argument naming `source` and the index of the first bad light (NaN or
// infinite values, negative radius, negative colour; a spot or directional light's zero
// direction; a spot's outer cone angle outside (0, pi/2] or inner angle outside [0, outer]).
void validateLights(const std::vector<Light>& lights, const std::string& source);

// {"lights": [{"position": [x,y,z], "radius": r, "color": [r,g,b]}, ...]}: points, as before; a
// light may add "type" ("point", "spot", "directional"), a spot or directional light "direction",
// a spot "innerConeAngle" (default 0) and "outerConeAngle" (radians). A directional light needs
// no position or radius.
std::vector<Light> loadLightsFile(const std::string& path);
void saveLightsFile(const std::string& path, const std::vector<Light>& lights);

// CPU mirror of glsl/animate_lights.comp. A drifting light rises from where it was placed at its
// own speed and, past the top of the wrap range, re-enters at the bottom; at time 0 every light is
// exactly where it was placed.
struct LightAnimation {
    float driftSpeed = 0.5f;  // metres per second, mean over lights
    float wrapMinY = 0.0f;
    float wrapHeight = 0.0f;  // 0: no animation
    // The lights the GPU holds (directional ones left out) before this index stay still: the
    // placed ones, which frameLights puts first (fitDrift sets it).
    std::uint32_t firstDrifting = 0;
};
// Drift within the vertical extent of `volume` (use lightVolume() of the scene's bounds).
LightAnimation verticalDrift(const Bounds& volume, float driftSpeed);

// Which of a light set drift, as the GPU holds them: the placed lights come first (a placed
// light after a drifting one throws std::invalid_argument), and the drifting ones' heights.
struct DriftingLights {
    std::uint32_t first = 0;  // index of the first drifting light among the non-directional ones
    float minY = std::numeric_limits<float>::max();
    float maxY = std::numeric_limits<float>::lowest();
};
DriftingLights driftingLights(const std::vector<Light>& lights);
// `animation` for that set: the placed lights still, and the wrap range widened to hold every
// drifting light (a light placed above the scene, say on a roof, would otherwise jump to the
// floor at time 0).
LightAnimation fitDrift(LightAnimation animation, const DriftingLights& drifting);

Light animateLight(const Light& light, std::uint32_t index, float time, const LightAnimation& animation);

}  // namespace ml
