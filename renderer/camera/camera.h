// A perspective camera: eye, target, vertical field of view, and clip planes.
#pragma once

#include <cstddef>
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
    glm::mat4 projection(float aspect) const;  // clip depth in [0, 1], reversed: 1 at the near plane
};

// Parses "px,py,pz,tx,ty,tz,fovy_deg"; throws std::invalid_argument naming the fault.
Camera parseCamera(const std::string& text);

// Clip planes that enclose the scene's bounds as seen from `eye`: far just past the farthest
// corner, near a small fraction of it (depth precision), so no geometry is clipped away.
void fitClipPlanes(Camera& camera, const Bounds& bounds);

Camera cameraFromPose(const CameraPose& pose);

// A camera the scene file defines: its pose, up vector and field of view. Clip planes are left
// to fitClipPlanes(camera, bounds, sceneCamera).
Camera cameraFromSceneCamera(const SceneCamera& sceneCamera);

// The file camera's clip planes: its znear, and its zfar where it gives one; where it gives none
// (glTF's infinite far plane) the far plane fitted to the bounds, kept beyond near.
void fitClipPlanes(Camera& camera, const Bounds& bounds, const SceneCamera& sceneCamera);

// "gltf:N" names the scene file's Nth camera (0-based) where --camera takes a camera.
bool namesSceneCamera(const std::string& text);

// N of "gltf:N", checked against the scene's cameras; throws std::invalid_argument with one line
// ("--camera gltf:5: the scene has 2 cameras (gltf:0..gltf:1)").
std::size_t sceneCameraIndex(const std::string& text, std::size_t cameraCount);

}  // namespace ml
