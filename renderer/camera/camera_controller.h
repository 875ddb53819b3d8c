// The live view's camera: fly (WASD, mouse look, Q/E down/up) and orbit (drag around a pivot,
// scroll to zoom). Input arrives as plain numbers, not window-system events, so the behaviour is
// unit-tested on the CPU.
//
// Frame-rate independent: movement is speed x elapsed seconds, so holding a key for one second
// moves the same distance at 10 or 240 frames per second. Mouse look is per pixel moved, which
// does not depend on the frame rate either.
#pragma once

#include <glm/glm.hpp>

#include "renderer/camera/camera.h"

namespace ml {

enum class CameraMode { Fly, Orbit };
const char* cameraModeName(CameraMode mode);

struct CameraInput {
    glm::vec3 move{0.0f};   // fly: x right, y up, z forward, each -1..1 (keys held)
    bool fast = false;      // fly: Shift held, kFastFactor times the speed
    glm::vec2 drag{0.0f};   // mouse movement in pixels while the look/orbit button is held (y down)
    float scroll = 0.0f;    // wheel steps; fly: speed, orbit: zoom

    bool idle() const { return move == glm::vec3(0.0f) && drag == glm::vec2(0.0f) && scroll == 0.0f; }
};

class CameraController {
public:
    static constexpr float kFastFactor = 4.0f;
    static constexpr float kRadiansPerPixel = 0.004f;
    static constexpr float kScrollFactor = 1.2f;  // per wheel step, on speed and on orbit distance

    // `sceneSize` (the bounds' diagonal) scales speeds and limits so every scene feels the same.
    CameraController(const Camera& start, float sceneSize);

    void update(const CameraInput& input, float seconds);
    void setMode(CameraMode mode);
    void reset();  // back to the start camera and speed; the mode stays (orbiting the start target)
    // Continues from `camera` (e.g. where a scripted path was when the user took over).
    void jumpTo(const Camera& camera);

    CameraMode mode() const { return mode_; }
    // Eye, target and fovy; the clip planes are the start camera's (the caller refits them).
    // Until the first input it is exactly the start camera, so a still view matches `render`.
    const Camera& camera() const { return camera_; }
    float flySpeed() const { return speed_; }           // scene units per second
    float orbitDistance() const { return distance_; }   // eye to pivot (orbit) or to target (fly)
    glm::vec3 forward() const;

private:
    void rebuildCamera();

    Camera start_;
    float sceneSize_;
    CameraMode mode_ = CameraMode::Fly;
    Camera camera_;
    glm::vec3 eye_{0.0f};
    glm::vec3 pivot_{0.0f};  // orbit centre
    float yaw_ = 0.0f;       // radians; 0 looks down -z, positive turns right
    float pitch_ = 0.0f;     // radians, kept inside +-89 degrees so lookAt stays well defined
    float distance_ = 1.0f;
    float speed_ = 1.0f;
};

}  // namespace ml
