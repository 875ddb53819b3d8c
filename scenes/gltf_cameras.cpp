#include "scenes/gltf_cameras.h"

#include <cmath>
#include <numbers>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

// Normalised, or nullopt-like zero where the transform leaves no direction (a zero scale).
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}

void checkPerspective(const std::string& path, const std::string& what, const tinygltf::PerspectiveCamera& p) {
    const auto number = [](double v) { return std::to_string(v); };
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi))
        fail(path, what + ": yfov " + number(p.yfov) + " is outside (0, pi) radians");
    // Checked as the floats the renderer will use: 1e-300 is > 0 as a double but 0 as a float.
    if (!(static_cast<float>(p.znear) > 0.0f) || !std::isfinite(static_cast<float>(p.znear))) fail(path, what + ": znear " + number(p.znear) + " is not > 0");
    // zfar 0 is tinygltf's "absent": an infinite far plane.
    if (p.zfar != 0.0 && (!(static_cast<float>(p.zfar) > static_cast<float>(p.znear)) ||
                          !std::isfinite(static_cast<float>(p.zfar))))
        fail(path, what + ": zfar " + number(p.zfar) + " is not greater than znear " + number(p.znear));
}

}  // namespace

std::vector<SceneCamera> convertCameras(const std::string& path, const tinygltf::Model& model,
                                        const std::vector<CameraInstance>& instances, std::size_t& orthographicSkipped) {
    std::vector<SceneCamera> cameras;
    for (const CameraInstance& instance : instances) {
        const tinygltf::Camera& source = model.cameras[instance.camera];
        const std::string what = named("cameras", instance.camera, source.name);
        if (source.type == "orthographic") {
            ++orthographicSkipped;
            continue;
        }
        if (source.type != "perspective")
            fail(path, what + ": type '" + clip(source.type, 40) + "' is neither perspective nor orthographic");
        checkPerspective(path, what, source.perspective);

        // A glTF camera looks down its node's -z with +y up. Directions are normalised, so a
        // scale in the transform changes nothing; up is made orthogonal to forward, which a
        // non-uniform scale above a rotation could otherwise spoil.
        const glm::dmat4& world = instance.world;
        const glm::dvec3 eye(world[3]);
        const glm::dvec3 forward = unitOrZero(glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0));
        const glm::dvec3 upAlong = glm::dmat3(world) * glm::dvec3(0.0, 1.0, 0.0);
        const glm::dvec3 up = unitOrZero(upAlong - forward * glm::dot(forward, upAlong));
        const std::string node = named("nodes", instance.node, model.nodes[instance.node].name);
        if (!std::isfinite(eye.x) || !std::isfinite(eye.y) || !std::isfinite(eye.z))
            fail(path, what + ": the transform of " + node + " puts it at a non-finite position");
        if (forward == glm::dvec3(0.0) || up == glm::dvec3(0.0))
            fail(path, what + ": the transform of " + node + " leaves it without a view direction (a zero scale?)");

        SceneCamera camera;
        camera.name = !source.name.empty() ? source.name : model.nodes[instance.node].name;
        camera.pose.eye = glm::vec3(eye);
        camera.pose.target = glm::vec3(eye + forward);
        camera.pose.fovyDegrees = static_cast<float>(glm::degrees(source.perspective.yfov));
        camera.up = glm::vec3(up);
        camera.nearPlane = static_cast<float>(source.perspective.znear);
        camera.farPlane = static_cast<float>(source.perspective.zfar);
        cameras.push_back(camera);
    }
    return cameras;
}

}  // namespace ml::gltf
