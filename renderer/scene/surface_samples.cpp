#include "renderer/scene/surface_samples.h"

#include <algorithm>
#include <cmath>

namespace ml {

SurfaceSamples::SurfaceSamples(const Scene& scene) {
    const std::size_t triangles = scene.triangleCount();
    cumulative_.resize(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3 a = scene.vertices[scene.indices[3 * t]].position;
        const glm::vec3 b = scene.vertices[scene.indices[3 * t + 1]].position;
        const glm::vec3 c = scene.vertices[scene.indices[3 * t + 2]].position;
        total_ += 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
        cumulative_[t] = total_;
    }
}

SurfaceSamples::Point SurfaceSamples::at(float pick, float r1, float r2) const {
    const double target = static_cast<double>(pick) * total_;
    const std::size_t t = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin()),
        cumulative_.size() - 1);
    // Uniform on the triangle: u = 1 - sqrt(r1), v = sqrt(r1) (1 - r2), w = sqrt(r1) r2.
    const float s = std::sqrt(r1);
    return {t, 1.0f - s, s * (1.0f - r2), s * r2};
}

}  // namespace ml
