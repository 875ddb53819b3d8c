// The built-in turntable of `--camera` (render, bench; view starts at its first pose):
//
//   --camera orbit[:frames=120][,elevation=25][,distance=D][,azimuth=A][,fovy=50]
//
// The eye circles the centre of the scene's bounds, one turn every `frames` animation frames,
// `elevation` degrees above it, `distance` away (default: the bounding sphere fills the view),
// starting at `azimuth` degrees around +y (default: the side the scene's default view looks
// from). Other `--camera` values go to the existing parser (renderer/camera/camera.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/camera/camera_orbit.h"
#include "scenes/scene.h"

namespace ml::app {

struct OrbitSpec {
    std::uint32_t frames = 120;
    float elevationDegrees = 25.0f;
    std::optional<float> distance;
    std::optional<float> azimuthDegrees;
    float fovyDegrees = 50.0f;
};

// True for "orbit" and "orbit:..." (whether or not the rest is valid).
bool isOrbitSpec(const std::string& cameraText);

// Throws std::invalid_argument naming the flag value and the key at fault.
OrbitSpec parseOrbitSpec(const std::string& cameraText);

// The orbit around `scene`'s bounds, starting (unless azimuth= is given) from the side its
// default camera looks from in an `aspect` (width / height) frame.
CameraOrbit orbitAround(const OrbitSpec& spec, const Scene& scene, float aspect);

}  // namespace ml::app
