#include "renderer/camera/camera_orbit.h"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace ml {

Camera CameraOrbit::at(std::uint32_t frame) const {
    // The angle from the frame's place within the turn, not frame * step: no drift over long
    // clips, and the frame after the last of a turn is bit for bit the first.
    const float turn = static_cast<float>(frame % frames) / static_cast<float>(frames);
    const float azimuth = glm::radians(azimuthDegrees) + turn * glm::two_pi<float>();
    const float elevation = glm::radians(elevationDegrees);
    Camera c;
    c.target = centre;
    c.eye = centre + distance * glm::vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                          std::cos(elevation) * std::cos(azimuth));
    c.fovyDegrees = fovyDegrees;
    return c;
}

float orbitDistanceToFrame(const Bounds& bounds, float fovyDegrees) {
    const float radius = bounds.empty() ? 1.0f : 0.5f * glm::length(bounds.size());
    return radius / std::sin(0.5f * glm::radians(fovyDegrees));
}

}  // namespace ml
