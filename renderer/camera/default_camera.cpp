#include "renderer/camera/default_camera.h"

#include <algorithm>
#include <cmath>

namespace ml {

BoundingSphere boundingSphere(const Scene& scene) {
    BoundingSphere sphere;
    if (scene.bounds.empty()) return sphere;
    sphere.centre = scene.bounds.center();
    float farthestSquared = 0.0f;
    for (const Vertex& v : scene.vertices) {
        const glm::vec3 d = v.position - sphere.centre;
        farthestSquared = std::max(farthestSquared, glm::dot(d, d));
    }
    sphere.radius = std::max(std::sqrt(farthestSquared), 1e-3f);
    return sphere;
}

Camera framingCamera(const BoundingSphere& sphere, float aspect, glm::vec3 direction) {
    Camera c;
    c.fovyDegrees = kFramingFovyDegrees;
    const float halfVertical = 0.5f * glm::radians(c.fovyDegrees);
    // A portrait frame is narrower than it is tall: the horizontal field of view decides.
    const float halfHorizontal = std::atan(std::tan(halfVertical) * std::max(aspect, 1e-3f));
    const float halfAngle = std::min(halfVertical, halfHorizontal);
    // The sphere touches the cone of the narrower field of view: sin(half angle) = r / d.
    const float distance = sphere.radius / std::sin(halfAngle);
    c.target = sphere.centre;
    c.eye = sphere.centre + glm::normalize(direction) * distance;
    return c;
}

Camera frontFramingCamera(const BoundingSphere& sphere, float aspect) {
    const float elevation = glm::radians(kFramingElevationDegrees);
    return framingCamera(sphere, aspect, glm::vec3(0.0f, std::sin(elevation), std::cos(elevation)));
}

DefaultCamera defaultCamera(const Scene& scene, float aspect) {
    DefaultCamera d;
    if (scene.suggestedView) {
        d.camera = cameraFromPose(*scene.suggestedView);
        fitClipPlanes(d.camera, scene.bounds);
        return d;
    }
    if (!scene.cameras.empty()) {
        const SceneCamera& first = scene.cameras.front();
        d.camera = cameraFromSceneCamera(first);
        fitClipPlanes(d.camera, scene.bounds, first);
        const std::size_t n = scene.cameras.size();
        d.choice = "gltf:0" + (first.name.empty() ? std::string() : " '" + first.name + "'") +
                   (n == 1 ? std::string(" (the file's only camera)")
                           : " (the first of the file's " + std::to_string(n) + " cameras; --camera gltf:1.." +
                                 "gltf:" + std::to_string(n - 1) + " for the others)");
        d.fromFile = true;
        return d;
    }
    d.camera = frontFramingCamera(boundingSphere(scene), aspect);
    fitClipPlanes(d.camera, scene.bounds);
    d.choice = "framed from the front (the file has no camera; --camera to choose)";
    return d;
}

}  // namespace ml
