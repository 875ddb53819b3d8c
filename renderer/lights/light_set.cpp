#include "renderer/lights/light_set.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "glsl/include/bindings.h"
#include "renderer/hash.h"
#include "renderer/lights/light_model.h"

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

constexpr float kPi = 3.14159265358979f;

// How fast and which way a spot turns, in [-1, 1); glsl/animate_lights.comp has the same.
float spotTurnFactor(std::uint32_t index) { return 2.0f * hashToUnitFloat(index ^ 0x9E3779B9u) - 1.0f; }

// Uniform over the sphere from two unit floats.
glm::vec3 unitDirection(float u, float v) {
    const float y = 2.0f * u - 1.0f;
    const float ring = std::sqrt(std::max(1.0f - y * y, 0.0f));
    const float phi = 2.0f * kPi * v;
    return glm::vec3(ring * std::cos(phi), y, ring * std::sin(phi));
}

LightType parseLightType(const std::string& text, const std::string& where) {
    if (text == "point") return LightType::Point;
    if (text == "spot") return LightType::Spot;
    if (text == "directional") return LightType::Directional;
    throw std::invalid_argument(where + ": \"type\" '" + text + "': expected point, spot or directional");
}

}  // namespace

const char* lightTypeName(LightType type) {
    switch (type) {
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
    case LightType::Directional: return "directional";
    }
    return "?";
}

std::vector<Light> clusteredLights(const std::vector<Light>& lights) {
    std::vector<Light> out;
    out.reserve(lights.size());
    for (const Light& l : lights)
        if (l.type != LightType::Directional) out.push_back(l);
    return out;
}

std::vector<Light> generateLights(const Bounds& bounds, const LightGeneration& generation) {
    std::vector<Light> lights(generation.count);
    const glm::vec3 lo = bounds.empty() ? glm::vec3(-1.0f) : bounds.min;
    const glm::vec3 size = bounds.empty() ? glm::vec3(2.0f) : bounds.size();
    for (std::uint32_t i = 0; i < generation.count; ++i) {
        const std::uint32_t key = pcgHash(i ^ pcgHash(generation.seed));
        const glm::vec3 u(hashToUnitFloat(key), hashToUnitFloat(key + 1u), hashToUnitFloat(key + 2u));
        lights[i].position = lo + u * size;
        lights[i].radius = generation.radius;
        lights[i].color = hueToRgb(hashToUnitFloat(key + 3u)) * generation.intensity;
        if (hashToUnitFloat(key + 4u) < generation.spotShare) {
            Light& spot = lights[i];
            spot.type = LightType::Spot;
            spot.direction = unitDirection(hashToUnitFloat(key + 5u), hashToUnitFloat(key + 6u));
            const float outerDeg = generation.spotAngleDeg > 0.0f ? generation.spotAngleDeg : 20.0f + 40.0f * hashToUnitFloat(key + 7u);
            spot.outerConeAngle = std::min(outerDeg, 90.0f) * (kPi / 180.0f);
            spot.innerConeAngle = kGeneratedSpotInnerShare * spot.outerConeAngle;
        }
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

float radiusWithoutRange(const glm::vec3& color, float cutoff) { return cutoffRadius(color, cutoff); }

std::vector<Light> lightsFromScene(const Scene& scene, float cutoff) {
    std::vector<Light> lights;
    lights.reserve(scene.lights.size());
    for (const SceneLight& s : scene.lights) {
        Light l;
        l.position = s.position;
        l.color = s.color * s.intensity;
        l.radius = s.range > 0.0f ? s.range : radiusWithoutRange(l.color, cutoff);
        l.direction = s.direction;
        switch (s.type) {
        case SceneLight::Type::Point: l.type = LightType::Point; break;
        case SceneLight::Type::Spot: l.type = LightType::Spot; break;
        case SceneLight::Type::Directional: l.type = LightType::Directional; break;
        }
        l.innerConeAngle = s.innerConeAngle;
        l.outerConeAngle = s.outerConeAngle;
        l.drifts = false;
        lights.push_back(l);
    }
    return lights;
}

float defaultLightRadius(const Bounds& bounds) {
    if (bounds.empty()) return 1.0f;
    return std::max(0.1f * glm::length(bounds.size()), 1e-3f);
}

void validateLights(const std::vector<Light>& lights, const std::string& source) {
    auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        const bool positioned = l.type != LightType::Directional;
        std::string fault;
        if (positioned && !finite(l.position)) fault = "position is not finite";
        else if (positioned && !std::isfinite(l.radius)) fault = "radius is not finite";
        else if (positioned && l.radius < 0.0f) fault = "radius is negative";
        else if (!finite(l.color)) fault = "color is not finite";
        else if (l.color.r < 0.0f || l.color.g < 0.0f || l.color.b < 0.0f) fault = "color is negative";
        else if (l.type != LightType::Point && !finite(l.direction)) fault = "direction is not finite";
        else if (l.type != LightType::Point && glm::dot(l.direction, l.direction) == 0.0f) fault = "direction is zero";
        else if (l.type == LightType::Spot && !(l.outerConeAngle > 0.0f && l.outerConeAngle <= kPi / 2.0f))
            fault = "outerConeAngle " + std::to_string(l.outerConeAngle) + " is not in (0, pi/2]";
        else if (l.type == LightType::Spot && !(l.innerConeAngle >= 0.0f && l.innerConeAngle <= l.outerConeAngle))
            fault = "innerConeAngle " + std::to_string(l.innerConeAngle) + " is not in [0, outerConeAngle]";
        if (!fault.empty())
            throw std::invalid_argument(source + ": light " + std::to_string(i) + ": " +
                                        (l.type == LightType::Point ? "" : std::string(lightTypeName(l.type)) + " ") + fault);
    }
}

std::vector<Light> loadLightsFile(const std::string& path) {
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
    std::vector<Light> lights;
    lights.reserve(items.size());
    auto where = [&](std::size_t index) { return path + ": light " + std::to_string(index); };
    auto readVec3 = [&](const nlohmann::json& item, const char* key, std::size_t index) {
        const auto it = item.find(key);
        if (it == item.end() || !it->is_array() || it->size() != 3 || !(*it)[0].is_number() ||
            !(*it)[1].is_number() || !(*it)[2].is_number())
            throw std::invalid_argument(where(index) + ": \"" + key + "\" must be an array of 3 numbers");
        return glm::vec3((*it)[0].get<float>(), (*it)[1].get<float>(), (*it)[2].get<float>());
    };
    auto readNumber = [&](const nlohmann::json& item, const char* key, std::size_t index, std::optional<float> fallback) {
        const auto it = item.find(key);
        if (it == item.end() && fallback) return *fallback;
        if (it == item.end() || !it->is_number())
            throw std::invalid_argument(where(index) + ": \"" + key + "\" must be a number");
        return it->get<float>();
    };
    for (std::size_t i = 0; i < items.size(); ++i) {
        const auto& item = items[i];
        if (!item.is_object()) throw std::invalid_argument(where(i) + " is not an object");
        Light l;
        if (const auto t = item.find("type"); t != item.end()) {
            if (!t->is_string()) throw std::invalid_argument(where(i) + ": \"type\" must be a string");
            l.type = parseLightType(t->get<std::string>(), where(i));
        }
        if (l.type != LightType::Directional) {
            l.position = readVec3(item, "position", i);
            l.radius = readNumber(item, "radius", i, std::nullopt);
        }
        l.color = readVec3(item, "color", i);
        if (l.type != LightType::Point) l.direction = readVec3(item, "direction", i);
        if (l.type == LightType::Spot) {
            l.innerConeAngle = readNumber(item, "innerConeAngle", i, 0.0f);
            l.outerConeAngle = readNumber(item, "outerConeAngle", i, std::nullopt);
        }
        l.drifts = false;  // an exact set: where the file says, at every frame
        lights.push_back(l);
    }
    validateLights(lights, path);
    return lights;
}

void saveLightsFile(const std::string& path, const std::vector<Light>& lights) {
    nlohmann::json items = nlohmann::json::array();
    for (const Light& l : lights) {
        nlohmann::json item;
        if (l.type != LightType::Point) item["type"] = lightTypeName(l.type);
        if (l.type != LightType::Directional) {
            item["position"] = {l.position.x, l.position.y, l.position.z};
            item["radius"] = l.radius;
        }
        item["color"] = {l.color.r, l.color.g, l.color.b};
        if (l.type != LightType::Point) item["direction"] = {l.direction.x, l.direction.y, l.direction.z};
        if (l.type == LightType::Spot) {
            item["innerConeAngle"] = l.innerConeAngle;
            item["outerConeAngle"] = l.outerConeAngle;
        }
        items.push_back(item);
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

DriftingLights driftingLights(const std::vector<Light>& lights) {
    DriftingLights d;
    std::uint32_t index = 0;
    bool drifting = false;
    for (const Light& l : lights) {
        if (l.type == LightType::Directional) continue;
        if (l.drifts) {
            if (!drifting) d.first = index;
            drifting = true;
            d.minY = std::min(d.minY, l.position.y);
            d.maxY = std::max(d.maxY, l.position.y);
        } else if (drifting) {
            throw std::invalid_argument("light " + std::to_string(index) +
                                        ": a placed (still) light after a drifting one; placed lights come first");
        }
        ++index;
    }
    if (!drifting) d.first = index;
    return d;
}

LightAnimation fitDrift(LightAnimation animation, const DriftingLights& drifting) {
    animation.firstDrifting = drifting.first;
    if (animation.wrapHeight > 0.0f && drifting.minY <= drifting.maxY) {
        const float low = std::min(animation.wrapMinY, drifting.minY);
        // Strictly above the highest light: a light at the very top would wrap at time 0.
        const float high = std::max(animation.wrapMinY + animation.wrapHeight,
                                    std::nextafter(drifting.maxY, std::numeric_limits<float>::infinity()));
        animation.wrapMinY = low;
        animation.wrapHeight = high - low;
    }
    return animation;
}

Light animateLight(const Light& light, std::uint32_t index, float time, const LightAnimation& animation) {
    Light out = light;
    if (light.type == LightType::Directional || index < animation.firstDrifting) return out;
    if (animation.wrapHeight > 0.0f && animation.driftSpeed != 0.0f) {
        const float speed = animation.driftSpeed * (0.5f + hashToUnitFloat(index));
        // Risen from the placed height, and past the top back by whole wrap heights: at time 0 the
        // light is exactly where it was placed (no round trip through the bottom of the range).
        float y = light.position.y + speed * time;
        const float top = animation.wrapMinY + animation.wrapHeight;
        if (y >= top) y -= animation.wrapHeight * (std::floor((y - top) / animation.wrapHeight) + 1.0f);
        out.position.y = y;
        if (light.type == LightType::Spot) {
            const glm::vec3 d = glm::normalize(light.direction);
            const float angle = animation.driftSpeed * float(ML_SPOT_TURN_PER_METRE) * spotTurnFactor(index) * time;
            const float c = std::cos(angle), s = std::sin(angle);
            out.direction = glm::vec3(c * d.x + s * d.z, d.y, c * d.z - s * d.x);
        }
    }
    return out;
}

}  // namespace ml
