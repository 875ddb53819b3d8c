#include "renderer/camera/default_camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "renderer/hash.h"
#include "renderer/scene/surface_samples.h"

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

FramedSurface framedSurface(const Scene& scene) {
    FramedSurface framed{boundingSphere(scene), scene.bounds, scene.bounds};
    const SurfaceSamples surface(scene);
    if (!(surface.totalArea() > 0.0)) return framed;
    std::vector<glm::vec3> points(kFramingSamples);
    for (std::uint32_t i = 0; i < kFramingSamples; ++i) {
        const std::uint32_t key = pcgHash(i ^ 0xF4A3E5u);
        const SurfaceSamples::Point p = surface.at(hashToUnitFloat(key), hashToUnitFloat(key + 1u), hashToUnitFloat(key + 2u));
        points[i] = p.position(scene);
    }
    // The middle of the area along each axis...
    const std::size_t low = static_cast<std::size_t>(kFramedAreaTail * (kFramingSamples - 1));
    const std::size_t high = kFramingSamples - 1 - low;
    std::vector<float> axis(kFramingSamples);
    for (int a = 0; a < 3; ++a) {
        for (std::uint32_t i = 0; i < kFramingSamples; ++i) axis[i] = points[i][a];
        std::nth_element(axis.begin(), axis.begin() + low, axis.end());
        framed.core.min[a] = axis[low];
        std::nth_element(axis.begin(), axis.begin() + high, axis.end());
        framed.core.max[a] = axis[high];
    }
    // ...widened by kFramedFence of itself: a model's own thin ends stay in, strays fall out.
    const glm::vec3 margin = kFramedFence * glm::max(framed.core.size(), glm::vec3(1e-6f * glm::length(scene.bounds.size())));
    const glm::vec3 fenceMin = framed.core.min - margin, fenceMax = framed.core.max + margin;
    const auto inside = [&](const glm::vec3& p) {
        return glm::all(glm::greaterThanEqual(p, fenceMin)) && glm::all(glm::lessThanEqual(p, fenceMax));
    };
    Bounds kept;
    for (const glm::vec3& p : points)
        if (inside(p)) kept.extend(p);
    for (const Vertex& v : scene.vertices)
        if (inside(v.position)) kept.extend(v.position);
    framed.framed = kept;
    framed.sphere.centre = kept.center();
    float farthestSquared = 0.0f;
    const auto reach = [&](const glm::vec3& p) {
        if (inside(p)) farthestSquared = std::max(farthestSquared, glm::dot(p - framed.sphere.centre, p - framed.sphere.centre));
    };
    for (const glm::vec3& p : points) reach(p);
    for (const Vertex& v : scene.vertices) reach(v.position);
    framed.sphere.radius = std::max(std::sqrt(farthestSquared), 1e-3f);
    return framed;
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
    const FramedSurface framed = framedSurface(scene);
    d.camera = frontFramingCamera(framed.sphere, aspect);
    fitClipPlanes(d.camera, scene.bounds);
    const auto point = [](const glm::vec3& p) {
        char text[96];
        std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", p.x, p.y, p.z);
        return std::string(text);
    };
    const int middle = static_cast<int>(std::lround(100.0 * (1.0 - 2.0 * kFramedAreaTail)));
    d.choice = "framed from the front (the file has no camera; --camera to choose): " + point(framed.framed.min) + " .. " +
               point(framed.framed.max) + ", the surface around the middle " + std::to_string(middle) +
               " % of its area (the bounds: " + point(scene.bounds.min) + " .. " + point(scene.bounds.max) + ")";
    return d;
}

}  // namespace ml
