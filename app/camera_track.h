// Where the camera is at each animation frame of a sequence: held (`--camera px,...` or the
// scene's view), keyframed (`--camera-path F.json`, the format `view` follows) or circling
// (`--camera orbit:...`). Moving cameras get their clip planes fitted to the scene every frame,
// as `render --camera` fits them, so frame K of a path equals `render --camera` at its pose.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "app/frame_options.h"
#include "renderer/camera/camera_orbit.h"
#include "renderer/camera/camera_path.h"

namespace ml::app {

class CameraTrack {
public:
    // The path when given (--camera-path), else the prepared frame's orbit or camera.
    static CameraTrack fromOptions(const FrameOptions& options, const PreparedFrame& frame, std::optional<CameraPath> path);

    // Loads --camera-path before any scene is built. Throws std::invalid_argument naming the
    // file (or both flags, when --camera is given too).
    static std::optional<CameraPath> loadPath(const FrameOptions& options, const std::string& cameraPathFile);

    Camera at(std::uint32_t frame) const;
    bool moves() const { return !std::holds_alternative<Camera>(source_); }

private:
    std::variant<Camera, CameraPath, CameraOrbit> source_;
    Bounds bounds_;
    std::optional<float> nearPlane_;
    std::optional<float> farPlane_;
};

}  // namespace ml::app
