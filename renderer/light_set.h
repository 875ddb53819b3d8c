// The CPU side of the light set: generation from a seed, validation, and JSON files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace ml {

struct PointLight {
    glm::vec3 position{0.0f};
    float radius = 1.0f;     // the falloff reaches exactly zero here
    glm::vec3 color{1.0f};   // linear colour times intensity
};

struct LightGeneration {
    std::uint32_t count = 1024;
    float radius = 3.0f;
    float intensity = 1.0f;
    std::uint32_t seed = 1;
};

// Positions uniform inside the bounds, hues spread over the colour wheel; the same seed gives
// the same lights on every machine (integer hashing, no std:: distributions).
std::vector<PointLight> generateLights(const Bounds& bounds, const LightGeneration& generation);

// The volume lights are placed in and drift through: the scene's bounds, with every side at
// least a tenth of the diagonal (a flat scene such as `plane` gets a layer of air above it).
Bounds lightVolume(const Bounds& sceneBounds);

// A radius that suits the scene when none is given: a tenth of the bounds' diagonal.
float defaultLightRadius(const Bounds& bounds);

// Throws std::invalid_argument naming `source` and the index of the first bad light
// (NaN or infinite values, negative radius, negative colour).
void validateLights(const std::vector<PointLight>& lights, const std::string& source);

// {"lights": [{"position": [x,y,z], "radius": r, "color": [r,g,b]}, ...]}
std::vector<PointLight> loadLightsFile(const std::string& path);
void saveLightsFile(const std::string& path, const std::vector<PointLight>& lights);

// CPU mirror of glsl/animate_lights.comp.
struct LightAnimation {
    float driftSpeed = 0.5f;  // metres per second, mean over lights
    float wrapMinY = 0.0f;
    float wrapHeight = 0.0f;  // 0: no animation
};
// Drift within the vertical extent of `volume` (use lightVolume() of the scene's bounds).
LightAnimation verticalDrift(const Bounds& volume, float driftSpeed);
PointLight animateLight(const PointLight& light, std::uint32_t index, float time, const LightAnimation& animation);

}  // namespace ml
