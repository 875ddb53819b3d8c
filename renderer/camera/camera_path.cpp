#include "renderer/camera/camera_path.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace ml {

namespace {

glm::vec3 readVec3(const nlohmann::json& value, const std::string& where) {
    if (!value.is_array() || value.size() != 3)
        throw std::invalid_argument(where + ": expected an array of 3 numbers");
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
        if (!value[i].is_number()) throw std::invalid_argument(where + ": expected an array of 3 numbers");
        v[i] = value[i].get<float>();
        if (!std::isfinite(v[i])) throw std::invalid_argument(where + ": not a finite number");
    }
    return v;
}

}  // namespace

CameraPath CameraPath::load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::invalid_argument(path + ": cannot open the camera path");
    nlohmann::json doc;
    try {
        in >> doc;
    } catch (const nlohmann::json::parse_error& e) {
        throw std::invalid_argument(path + ": not valid JSON (" + e.what() + ")");
    }
    return fromJson(doc, path);
}

CameraPath CameraPath::fromJson(const nlohmann::json& doc, const std::string& source) {
    if (!doc.is_object() || !doc.contains("keyframes") || !doc["keyframes"].is_array() || doc["keyframes"].empty())
        throw std::invalid_argument(source + ": expected {\"keyframes\": [...]} with at least one keyframe");
    CameraPath path;
    float fovy = 60.0f;
    for (std::size_t i = 0; i < doc["keyframes"].size(); ++i) {
        const nlohmann::json& k = doc["keyframes"][i];
        const std::string where = source + ": keyframe " + std::to_string(i);
        if (!k.is_object()) throw std::invalid_argument(where + ": expected an object");
        for (const char* key : {"frame", "eye", "target"})
            if (!k.contains(key)) throw std::invalid_argument(where + ": missing \"" + key + "\"");
        if (!k["frame"].is_number_unsigned()) throw std::invalid_argument(where + ": \"frame\" must be a whole number >= 0");
        CameraKeyframe key;
        const auto frame = k["frame"].get<std::uint64_t>();
        if (frame > 0xffffffffull) throw std::invalid_argument(where + ": \"frame\" is too large");
        key.frame = static_cast<std::uint32_t>(frame);
        key.eye = readVec3(k["eye"], where + ": \"eye\"");
        key.target = readVec3(k["target"], where + ": \"target\"");
        if (k.contains("fovy")) {
            if (!k["fovy"].is_number()) throw std::invalid_argument(where + ": \"fovy\" must be a number");
            fovy = k["fovy"].get<float>();
            if (!(fovy > 1.0f && fovy < 179.0f)) throw std::invalid_argument(where + ": \"fovy\" must be between 1 and 179 degrees");
        }
        key.fovyDegrees = fovy;
        if (glm::length(key.target - key.eye) < 1e-6f) throw std::invalid_argument(where + ": eye and target are the same point");
        if (!path.keyframes_.empty() && key.frame <= path.keyframes_.back().frame)
            throw std::invalid_argument(where + ": frames must increase (" + std::to_string(key.frame) + " after " +
                                        std::to_string(path.keyframes_.back().frame) + ")");
        path.keyframes_.push_back(key);
    }
    return path;
}

Camera CameraPath::at(std::uint32_t frame) const {
    // The first keyframe at or after `frame`.
    const auto next = std::lower_bound(keyframes_.begin(), keyframes_.end(), frame,
                                       [](const CameraKeyframe& k, std::uint32_t f) { return k.frame < f; });
    CameraKeyframe k;
    if (next == keyframes_.begin()) k = keyframes_.front();
    else if (next == keyframes_.end()) k = keyframes_.back();
    else if (next->frame == frame) k = *next;
    else {
        const CameraKeyframe& a = *(next - 1);
        const CameraKeyframe& b = *next;
        const float t = static_cast<float>(frame - a.frame) / static_cast<float>(b.frame - a.frame);
        k.eye = glm::mix(a.eye, b.eye, t);
        k.target = glm::mix(a.target, b.target, t);
        k.fovyDegrees = a.fovyDegrees + (b.fovyDegrees - a.fovyDegrees) * t;
    }
    Camera c;
    c.eye = k.eye;
    c.target = k.target;
    c.fovyDegrees = k.fovyDegrees;
    // Interpolating two valid keyframes can still pass eye through target: nudge it.
    if (glm::length(c.target - c.eye) < 1e-6f) c.target = c.eye + glm::vec3(0.0f, 0.0f, -1e-3f);
    return c;
}

}  // namespace ml
