#include "scenes/scene.h"

#include <algorithm>
#include <cmath>

namespace ml {

void computeBounds(Scene& scene) {
    scene.bounds = Bounds{};
    // The vertices the triangles use: a vertex no index draws is not part of the scene.
    for (std::uint32_t i : scene.indices) scene.bounds.extend(scene.vertices[i].position);
}

CameraPose framingView(const Bounds& bounds) {
    CameraPose pose;
    if (bounds.empty()) return pose;
    const glm::vec3 c = bounds.center();
    const float radius = std::max(0.5f * glm::length(bounds.size()), 1e-3f);
    pose.target = c;
    pose.fovyDegrees = 60.0f;
    // Raised three-quarter view, far enough that the bounding sphere fits the vertical field of view.
    const float distance = radius / std::sin(glm::radians(0.5f * pose.fovyDegrees));
    pose.eye = c + glm::normalize(glm::vec3(0.6f, 0.45f, 0.75f)) * distance;
    return pose;
}

}  // namespace ml
