// A scripted camera for `manylights view --camera-path F.json`: keyframes of eye, target and
// vertical field of view at animation frame indices, interpolated linearly between keyframes
// and held before the first and after the last.
//
//   {
//     "keyframes": [
//       {"frame": 0,  "eye": [0, 4, 12], "target": [0, 1, 0], "fovy": 50},
//       {"frame": 60, "eye": [8, 3, 8],  "target": [0, 1, 0]}
//     ]
//   }
//
// "frame" is a whole number, strictly increasing from one keyframe to the next. "fovy" is in
// degrees and optional: the previous keyframe's, 60 for the first. Clip planes are not part of
// the path; they are fitted to the scene as for `render --camera`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/camera/camera.h"

namespace ml {

struct CameraKeyframe {
    std::uint32_t frame = 0;
    glm::vec3 eye{0.0f};
    glm::vec3 target{0.0f};
    float fovyDegrees = 60.0f;
};

class CameraPath {
public:
    // Throw std::invalid_argument naming `source` (the file) and the keyframe at fault.
    static CameraPath load(const std::string& path);
    static CameraPath fromJson(const nlohmann::json& doc, const std::string& source);

    // The camera at `frame` (eye, target, fovy; default clip planes).
    Camera at(std::uint32_t frame) const;
    const std::vector<CameraKeyframe>& keyframes() const { return keyframes_; }

private:
    std::vector<CameraKeyframe> keyframes_;
};

}  // namespace ml
