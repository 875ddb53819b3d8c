#include "renderer/light_set.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "renderer/hash.h"

namespace ml {

namespace {

glm::vec3 hueToRgb(float hue) {
    const glm::vec3 k(5.0f, 3.0f, 1.0f);
    glm::vec3 rgb;
    for (int c = 0; c < 3; ++c) {
        const float t = std::fmod(k[c] + hue * 6.0f, 6.0f);
        rgb[c] = 1.0f - std::max(0.0f, std::min({t, 4.0f - t, 1.0f}));
    }
    // Mix in some white: pure primaries make a scene look like a disco.
    return 0.35f + 0.65f * rgb;
}

}  // namespace

std::vector<PointLight> generateLights(const Bounds& bounds, const LightGeneration& generation) {
    std::vector<PointLight> lights(generation.count);
    const glm::vec3 lo = bounds.empty() ? glm::vec3(-1.0f) : bounds.min;
    const glm::vec3 size = bounds.empty() ? glm::vec3(2.0f) : bounds.size();
    for (std::uint32_t i = 0; i < generation.count; ++i) {
        const std::uint32_t key = pcgHash(i ^ pcgHash(generation.seed));
        const glm::vec3 u(hashToUnitFloat(key), hashToUnitFloat(key + 1u), hashToUnitFloat(key + 2u));
        lights[i].position = lo + u * size;
        lights[i].radius = generation.radius;
        lights[i].color = hueToRgb(hashToUnitFloat(key + 3u)) * generation.intensity;
    }
    return lights;
}

Bounds lightVolume(const Bounds& sceneBounds) {
    if (sceneBounds.empty()) return sceneBounds;
    Bounds v = sceneBounds;
    const float minSide = 0.1f * glm::length(sceneBounds.size());
    for (int axis = 0; axis < 3; ++axis) {
        const float missing = minSide - v.size()[axis];
        if (missing <= 0.0f) continue;
        if (axis == 1) {
            v.max.y += missing;  // up: above a floor, not below it
        } else {
            v.min[axis] -= 0.5f * missing;
            v.max[axis] += 0.5f * missing;
        }
    }
    return v;
}

float defaultLightRadius(const Bounds& bounds) {
    if (bounds.empty()) return 1.0f;
    return std::max(0.1f * glm::length(bounds.size()), 1e-3f);
}

void validateLights(const std::vector<PointLight>& lights, const std::string& source) {
    auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const PointLight& l = lights[i];
        std::string fault;
        if (!finite(l.position)) fault = "position is not finite";
        else if (!std::isfinite(l.radius)) fault = "radius is not finite";
        else if (l.radius < 0.0f) fault = "radius is negative";
        else if (!finite(l.color)) fault = "color is not finite";
        else if (l.color.r < 0.0f || l.color.g < 0.0f || l.color.b < 0.0f) fault = "color is negative";
        if (!fault.empty()) throw std::invalid_argument(source + ": light " + std::to_string(i) + ": " + fault);
    }
}

std::vector<PointLight> loadLightsFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::invalid_argument(path + ": cannot open lights file");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(path + ": not valid JSON (" + std::string(e.what()) + ")");
    }
    if (!doc.is_object() || !doc.contains("lights") || !doc["lights"].is_array())
        throw std::invalid_argument(path + ": expected an object with a \"lights\" array");
    const auto& items = doc["lights"];
    std::vector<PointLight> lights;
    lights.reserve(items.size());
    auto readVec3 = [&](const nlohmann::json& item, const char* key, std::size_t index) {
        const auto it = item.find(key);
        if (it == item.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() ||
            !(*it)[1].is_number() || !(*it)[2].is_number())
            throw std::invalid_argument(path + ": light " + std::to_string(index) + ": \"" + key +
                                        "\" must be an array of 3 numbers");
        return glm::vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
    };
    for (std::size_t i = 0; i < items.size(); ++i) {
        const auto& item = items[i];
        if (!item.is_object()) throw std::invalid_argument(path + ": light " + std::to_string(i) + " is not an object");
        PointLight l;
        l.position = readVec3(item, "position", i);
        l.color = readVec3(item, "color", i);
        const auto r = item.find("radius");
        if (r == item.end() || !r->is_number())
            throw std::invalid_argument(path + ": light " + std::to_string(i) + ": \"radius\" must be a number");
        l.radius = r->get<float>();
        lights.push_back(l);
    }
    validateLights(lights, path);
    return lights;
}

void saveLightsFile(const std::string& path, const std::vector<PointLight>& lights) {
    nlohmann::json items = nlohmann::json::array();
    for (const PointLight& l : lights) {
        items.push_back({{"position", {l.position.x, l.position.y, l.position.z}},
                         {"radius", l.radius},
                         {"color", {l.color.r, l.color.g, l.color.b}}});
    }
    std::ofstream out(path);
    if (!out) throw std::invalid_argument(path + ": cannot write lights file");
    out << nlohmann::json{{"lights", items}}.dump() << "\n";
    if (!out) throw std::invalid_argument(path + ": write failed");
}

LightAnimation verticalDrift(const Bounds& volume, float driftSpeed) {
    if (volume.empty()) return LightAnimation{driftSpeed, 0.0f, 0.0f};
    return LightAnimation{driftSpeed, volume.min.y, volume.size().y};
}

PointLight animateLight(const PointLight& light, std::uint32_t index, float time, const LightAnimation& animation) {
    PointLight out = light;
    if (animation.wrapHeight > 0.0f && animation.driftSpeed != 0.0f) {
        const float speed = animation.driftSpeed * (0.5f + hashToUnitFloat(index));
        const float y = light.position.y - animation.wrapMinY + speed * time;
        // GLSL mod(): x - y * floor(x / y)
        out.position.y = animation.wrapMinY + (y - animation.wrapHeight * std::floor(y / animation.wrapHeight));
    }
    return out;
}

}  // namespace ml
