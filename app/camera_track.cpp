#include "app/camera_track.h"

#include <stdexcept>

namespace ml::app {

std::optional<CameraPath> CameraTrack::loadPath(const FrameOptions& options, const std::string& cameraPathFile) {
    if (cameraPathFile.empty()) return std::nullopt;
    if (!options.camera.empty())
        throw std::invalid_argument("--camera-path " + cameraPathFile + " and --camera " + options.camera + ": give one of them");
    return CameraPath::load(cameraPathFile);
}

CameraTrack CameraTrack::fromOptions(const FrameOptions& options, const PreparedFrame& frame, std::optional<CameraPath> path) {
    CameraTrack track;
    track.bounds_ = frame.scene.bounds;
    track.nearPlane_ = options.nearPlane;
    track.farPlane_ = options.farPlane;
    if (path) {
        track.source_ = std::move(*path);
    } else if (frame.orbit) {
        track.source_ = *frame.orbit;
    } else {
        track.source_ = frame.settings.camera;  // already fitted by prepareFrame
    }
    return track;
}

Camera CameraTrack::at(std::uint32_t frame) const {
    if (const Camera* fixed = std::get_if<Camera>(&source_)) return *fixed;
    Camera c = std::holds_alternative<CameraPath>(source_) ? std::get<CameraPath>(source_).at(frame)
                                                          : std::get<CameraOrbit>(source_).at(frame);
    fitClipPlanes(c, bounds_);
    if (nearPlane_) c.nearPlane = *nearPlane_;
    if (farPlane_) c.farPlane = *farPlane_;
    return c;
}

}  // namespace ml::app
