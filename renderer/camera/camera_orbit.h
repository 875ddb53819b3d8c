// A turntable camera: the eye circles a centre at a fixed distance and elevation, one full turn
// every `frames` animation frames, always looking at the centre. `render --camera orbit:...`
// builds one around the scene's bounds (app/camera_spec.h).
#pragma once

#include <cstdint>

#include "renderer/camera/camera.h"
#include "scenes/scene.h"

namespace ml {

struct CameraOrbit {
    glm::vec3 centre{0.0f};
    float distance = 10.0f;
    float elevationDegrees = 25.0f;  // above the horizontal plane through the centre
    float azimuthDegrees = 0.0f;     // at frame 0, around +y, from +z towards +x
    std::uint32_t frames = 120;      // frames per full turn
    float fovyDegrees = 50.0f;

    // The camera at animation frame `frame` (default clip planes). Periodic: at(frame + frames)
    // equals at(frame) exactly, so a clip of `frames` frames loops without a seam.
    Camera at(std::uint32_t frame) const;
};

// The distance at which a sphere around `bounds` fills the height of a `fovyDegrees` view.
float orbitDistanceToFrame(const Bounds& bounds, float fovyDegrees);

}  // namespace ml
