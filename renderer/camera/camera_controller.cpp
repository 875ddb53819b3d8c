#include "renderer/camera/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace ml {

namespace {
constexpr float kMaxPitch = glm::radians(89.0f);
constexpr glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};
}  // namespace

const char* cameraModeName(CameraMode mode) { return mode == CameraMode::Fly ? "fly" : "orbit"; }

CameraController::CameraController(const Camera& start, float sceneSize)
    : start_(start), sceneSize_(std::max(sceneSize, 1e-3f)) {
    reset();
}

void CameraController::reset() {
    jumpTo(start_);
    // Crossing the scene in about five seconds.
    speed_ = 0.2f * sceneSize_;
}

void CameraController::jumpTo(const Camera& camera) {
    camera_ = camera;
    eye_ = camera.eye;
    pivot_ = camera.target;
    const glm::vec3 d = camera.target - camera.eye;
    distance_ = std::max(glm::length(d), 1e-4f);
    const glm::vec3 f = d / distance_;
    pitch_ = std::clamp(std::asin(std::clamp(f.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    yaw_ = std::atan2(f.x, -f.z);
}

glm::vec3 CameraController::forward() const {
    return {std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), -std::cos(pitch_) * std::cos(yaw_)};
}

void CameraController::setMode(CameraMode mode) {
    if (mode == mode_) return;
    // Orbit around the point the fly camera looks at, at the same distance: the view does not jump.
    if (mode == CameraMode::Orbit) pivot_ = eye_ + forward() * distance_;
    mode_ = mode;
}

void CameraController::update(const CameraInput& input, float seconds) {
    if (input.idle()) return;
    yaw_ += input.drag.x * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - input.drag.y * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    const float step = std::pow(kScrollFactor, input.scroll);
    if (mode_ == CameraMode::Fly) {
        speed_ = std::clamp(speed_ * step, 1e-3f * sceneSize_, 10.0f * sceneSize_);
        glm::vec3 move = input.move;
        // Diagonals are no faster than straight lines.
        if (glm::length(move) > 1.0f) move = glm::normalize(move);
        const glm::vec3 f = forward();
        const glm::vec3 right = glm::normalize(glm::cross(f, kWorldUp));
        const float distance = speed_ * (input.fast ? kFastFactor : 1.0f) * std::max(seconds, 0.0f);
        eye_ += (right * move.x + kWorldUp * move.y + f * move.z) * distance;
    } else {
        // Scrolling up (positive) moves closer.
        distance_ = std::clamp(distance_ / step, 1e-3f * sceneSize_, 20.0f * sceneSize_);
        eye_ = pivot_ - forward() * distance_;
    }
    rebuildCamera();
}

void CameraController::rebuildCamera() {
    camera_.eye = eye_;
    camera_.target = eye_ + forward() * distance_;
}

}  // namespace ml
