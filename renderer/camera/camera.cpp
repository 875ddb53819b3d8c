#include "renderer/camera/camera.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace ml {

glm::mat4 Camera::view() const {
    // A view straight up or down would make lookAt degenerate: pick another up vector then.
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 safeUp = std::abs(glm::dot(forward, glm::normalize(up))) > 0.999f ? glm::vec3(0, 0, -1) : up;
    return glm::lookAt(eye, target, safeUp);
}

glm::mat4 Camera::projection(float aspect) const {
    // Clip depth in [0, 1] with the planes swapped: reversed depth, 1 at the near plane and 0 at
    // the far one (renderer/gl/depth_convention.h).
    return glm::perspectiveRH_ZO(glm::radians(fovyDegrees), aspect, farPlane, nearPlane);
}

Camera parseCamera(const std::string& text) {
    std::vector<float> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        try {
            std::size_t used = 0;
            const float v = std::stof(item, &used);
            if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument("");
            values.push_back(v);
        } catch (const std::exception&) {
            throw std::invalid_argument("--camera: '" + item + "' is not a finite number");
        }
    }
    if (values.size() != 7) {
        throw std::invalid_argument("--camera expects 7 comma-separated numbers px,py,pz,tx,ty,tz,fovy_deg; got " +
                                    std::to_string(values.size()));
    }
    Camera c;
    c.eye = {values[0], values[1], values[2]};
    c.target = {values[3], values[4], values[5]};
    c.fovyDegrees = values[6];
    if (glm::length(c.target - c.eye) < 1e-6f) throw std::invalid_argument("--camera: eye and target are the same point");
    if (!(c.fovyDegrees > 1.0f && c.fovyDegrees < 179.0f))
        throw std::invalid_argument("--camera: fovy must be between 1 and 179 degrees");
    return c;
}

void fitClipPlanes(Camera& camera, const Bounds& bounds) {
    if (bounds.empty()) return;
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner{(i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z};
        farthest = std::max(farthest, glm::length(corner - camera.eye));
    }
    camera.farPlane = std::max(farthest * 1.01f, 1e-3f);
    camera.nearPlane = std::clamp(camera.farPlane * 2e-3f, 1e-4f, 0.5f);
}

Camera cameraFromPose(const CameraPose& pose) {
    Camera c;
    c.eye = pose.eye;
    c.target = pose.target;
    c.fovyDegrees = pose.fovyDegrees;
    return c;
}

Camera cameraFromSceneCamera(const SceneCamera& sceneCamera) {
    Camera c = cameraFromPose(sceneCamera.pose);
    c.up = sceneCamera.up;
    return c;
}

void fitClipPlanes(Camera& camera, const Bounds& bounds, const SceneCamera& sceneCamera) {
    fitClipPlanes(camera, bounds);
    camera.nearPlane = sceneCamera.nearPlane;
    camera.farPlane = sceneCamera.farPlane > 0.0f ? sceneCamera.farPlane
                                                  : std::max(camera.farPlane, 2.0f * sceneCamera.nearPlane);
}

namespace {
constexpr std::string_view kSceneCameraPrefix = "gltf:";
}  // namespace

bool namesSceneCamera(const std::string& text) { return text.starts_with(kSceneCameraPrefix); }

std::size_t sceneCameraIndex(const std::string& text, std::size_t cameraCount) {
    const std::string digits = text.substr(kSceneCameraPrefix.size());
    const std::string flag = "--camera " + text + ": ";
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument(flag + "expected gltf:N, N a camera number from 0");
    const std::size_t index = std::stoul(digits);
    if (cameraCount == 0) throw std::invalid_argument(flag + "the scene has no cameras");
    if (index >= cameraCount)
        throw std::invalid_argument(flag + "the scene has " + std::to_string(cameraCount) +
                                    (cameraCount == 1 ? " camera" : " cameras") + " (gltf:0..gltf:" +
                                    std::to_string(cameraCount - 1) + ")");
    return index;
}

}  // namespace ml
