#include "app/camera_spec.h"

#include <cmath>
#include <stdexcept>

#include "renderer/camera/default_camera.h"

namespace ml::app {

namespace {

constexpr const char* kOrbitSyntax = "orbit[:frames=N][,elevation=DEG][,distance=D][,azimuth=DEG][,fovy=DEG]";

double parseNumber(const std::string& flagValue, const std::string& key, const std::string& text) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (text.empty() || used != text.size() || !std::isfinite(v))
        throw std::invalid_argument("--camera '" + flagValue + "': " + key + "=" + text + " is not a number");
    return v;
}

}  // namespace

bool isOrbitSpec(const std::string& cameraText) {
    return cameraText == "orbit" || cameraText.rfind("orbit:", 0) == 0;
}

OrbitSpec parseOrbitSpec(const std::string& text) {
    OrbitSpec spec;
    const std::string body = text.size() > 6 ? text.substr(6) : "";
    std::size_t start = 0;
    while (start < body.size()) {
        const std::size_t comma = body.find(',', start);
        const std::string item = body.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        start = comma == std::string::npos ? body.size() : comma + 1;
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw std::invalid_argument("--camera '" + text + "': '" + item + "' is not key=value (" + kOrbitSyntax + ")");
        const std::string key = item.substr(0, eq);
        const double v = parseNumber(text, key, item.substr(eq + 1));
        auto fail = [&](const char* why) { throw std::invalid_argument("--camera '" + text + "': " + key + " " + why); };
        if (key == "frames") {
            if (v < 1 || v > 1e8 || v != std::floor(v)) fail("must be a whole number of frames per turn, 1 to 100000000");
            spec.frames = static_cast<std::uint32_t>(v);
        } else if (key == "elevation") {
            if (!(v > -90.0 && v < 90.0)) fail("must be between -90 and 90 degrees (exclusive: the view would look straight down)");
            spec.elevationDegrees = static_cast<float>(v);
        } else if (key == "distance") {
            if (!(v > 0.0)) fail("must be > 0");
            spec.distance = static_cast<float>(v);
        } else if (key == "azimuth") {
            spec.azimuthDegrees = static_cast<float>(v);
        } else if (key == "fovy") {
            if (!(v > 1.0 && v < 179.0)) fail("must be between 1 and 179 degrees");
            spec.fovyDegrees = static_cast<float>(v);
        } else {
            throw std::invalid_argument("--camera '" + text + "': unknown key '" + key + "' (" + kOrbitSyntax + ")");
        }
    }
    return spec;
}

CameraOrbit orbitAround(const OrbitSpec& spec, const Scene& scene, float aspect) {
    CameraOrbit orbit;
    orbit.centre = scene.bounds.empty() ? glm::vec3(0.0f) : scene.bounds.center();
    orbit.frames = spec.frames;
    orbit.elevationDegrees = spec.elevationDegrees;
    orbit.fovyDegrees = spec.fovyDegrees;
    orbit.distance = spec.distance.value_or(orbitDistanceToFrame(scene.bounds, spec.fovyDegrees));
    if (spec.azimuthDegrees) {
        orbit.azimuthDegrees = *spec.azimuthDegrees;
    } else {
        // Start from the side the scene is usually seen from, so frame 0 looks familiar.
        const glm::vec3 from = defaultCamera(scene, aspect).camera.eye - orbit.centre;
        orbit.azimuthDegrees = (from.x == 0.0f && from.z == 0.0f) ? 0.0f : glm::degrees(std::atan2(from.x, from.z));
    }
    return orbit;
}

}  // namespace ml::app
