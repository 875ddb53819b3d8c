#include "scenes/gltf_lights.h"

#include <cmath>
#include <numbers>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

bool finiteFloat(double v) { return std::isfinite(static_cast<float>(v)); }

SceneLight::Type lightType(const std::string& path, const std::string& what, const std::string& type) {
    if (type == "point") return SceneLight::Type::Point;
    if (type == "spot") return SceneLight::Type::Spot;
    if (type == "directional") return SceneLight::Type::Directional;
    fail(path, what + ": type '" + clip(type, 40) + "' is not point, spot or directional");
}

// The file's numbers, checked as the floats the renderer will use.
SceneLight checkedLight(const std::string& path, const std::string& what, const tinygltf::Light& source) {
    const auto number = [](double v) { return std::to_string(v); };
    SceneLight light;
    light.name = source.name;
    light.type = lightType(path, what, source.type);
    if (!source.color.empty()) {  // absent: white
        if (source.color.size() != 3) fail(path, what + ": color has " + std::to_string(source.color.size()) + " numbers, not 3");
        for (int c = 0; c < 3; ++c) {
            if (!finiteFloat(source.color[c]) || source.color[c] < 0.0)
                fail(path, what + ": color[" + std::to_string(c) + "] " + number(source.color[c]) + " is not a finite number >= 0");
            light.color[c] = static_cast<float>(source.color[c]);
        }
    }
    if (!finiteFloat(source.intensity) || source.intensity < 0.0)
        fail(path, what + ": intensity " + number(source.intensity) + " is not a finite number >= 0");
    light.intensity = static_cast<float>(source.intensity);
    if (!finiteFloat(source.range) || source.range < 0.0)
        fail(path, what + ": range " + number(source.range) + " is not a finite number >= 0");
    light.range = static_cast<float>(source.range);
    if (light.type == SceneLight::Type::Spot) {
        const double outer = source.spot.outerConeAngle, inner = source.spot.innerConeAngle;
        if (!(outer > 0.0 && outer <= std::numbers::pi / 2.0))
            fail(path, what + ": spot.outerConeAngle " + number(outer) + " is outside (0, pi/2]");
        if (!(inner >= 0.0 && inner <= outer))
            fail(path, what + ": spot.innerConeAngle " + number(inner) + " is outside [0, outerConeAngle]");
        light.innerConeAngle = static_cast<float>(inner);
        light.outerConeAngle = static_cast<float>(outer);
    }
    return light;
}

}  // namespace

std::vector<SceneLight> convertLights(const std::string& path, const tinygltf::Model& model,
                                      const std::vector<LightInstance>& instances) {
    std::vector<SceneLight> lights;
    lights.reserve(instances.size());
    for (const LightInstance& instance : instances) {
        const tinygltf::Light& source = model.lights[instance.light];
        const std::string what = named("lights", instance.light, source.name);
        SceneLight light = checkedLight(path, what, source);
        if (light.name.empty()) light.name = model.nodes[instance.node].name;

        // KHR_lights_punctual: a light sits at its node's origin and points down the node's -z.
        const glm::dmat4& world = instance.world;
        const glm::dvec3 position(world[3]);
        const glm::dvec3 along = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
        const double length = glm::length(along);
        const std::string node = named("nodes", instance.node, model.nodes[instance.node].name);
        if (!finiteFloat(position.x) || !finiteFloat(position.y) || !finiteFloat(position.z))
            fail(path, what + ": the transform of " + node + " puts it at a non-finite position");
        if (light.type != SceneLight::Type::Point && !(length > 0.0 && std::isfinite(length)))
            fail(path, what + ": the transform of " + node + " leaves it without a direction (a zero scale?)");
        light.position = glm::vec3(position);
        if (light.type != SceneLight::Type::Point) light.direction = glm::vec3(along / length);
        lights.push_back(light);
    }
    return lights;
}

}  // namespace ml::gltf
