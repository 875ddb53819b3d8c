#include "renderer/scene/surface_samples.h"

#include <algorithm>
#include <cmath>

namespace ml {
namespace {

bool lexicographicallyLess(const glm::vec3& a, const glm::vec3& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.y != b.y) return a.y < b.y;
    return a.z < b.z;
}

}  // namespace

SurfaceSamples::SurfaceSamples(const Scene& scene) {
    const std::size_t triangles = scene.triangleCount();
    const auto position = [&](std::uint32_t vertex) { return scene.vertices[vertex].position; };
    entries_.resize(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t* i = &scene.indices[3 * t];
        // Read from the lowest corner, turning the triangle rather than reordering its corners.
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (lexicographicallyLess(position(i[k]), position(i[first]))) first = k;
        entries_[t] = {static_cast<std::uint32_t>(t), {i[first], i[(first + 1) % 3], i[(first + 2) % 3]}};
    }
    std::sort(entries_.begin(), entries_.end(), [&](const Entry& a, const Entry& b) {
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 pa = position(a.corners[k]), pb = position(b.corners[k]);
            if (pa != pb) return lexicographicallyLess(pa, pb);
        }
        return false;  // the same triangle in space: either one gives the same points
    });
    cumulative_.resize(triangles);
    for (std::size_t e = 0; e < triangles; ++e) {
        const glm::vec3 a = position(entries_[e].corners[0]), b = position(entries_[e].corners[1]),
                        c = position(entries_[e].corners[2]);
        total_ += 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
        cumulative_[e] = total_;
    }
}

SurfaceSamples::Point SurfaceSamples::at(float pick, float r1, float r2) const {
    const double target = static_cast<double>(pick) * total_;
    const std::size_t e = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin()),
        cumulative_.size() - 1);
    // Uniform on the triangle: u = 1 - sqrt(r1), v = sqrt(r1) (1 - r2), w = sqrt(r1) r2.
    const float s = std::sqrt(r1);
    return {entries_[e].triangle, entries_[e].corners, 1.0f - s, s * (1.0f - r2), s * r2};
}

}  // namespace ml
