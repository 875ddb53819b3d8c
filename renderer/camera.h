// A perspective camera: eye, target, vertical field of view, and clip planes.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace ml {

struct Camera {
    glm::vec3 eye{0.0f, 1.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovyDegrees = 60.0f;
    float nearPlane = 0.1f;
    float farPlane = 100.0f;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;  // OpenGL clip space (z in [-1, 1])
};

// Parses "px,py,pz,tx,ty,tz,fovy_deg"; throws std::invalid_argument naming the fault.
Camera parseCamera(const std::string& text);

// Clip planes that enclose the scene's bounds as seen from `eye`: far just past the farthest
// corner, near a small fraction of it (depth precision), so no geometry is clipped away.
void fitClipPlanes(Camera& camera, const Bounds& bounds);

Camera cameraFromPose(const CameraPose& pose);

}  // namespace ml
