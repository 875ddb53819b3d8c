#include "renderer/lights/surface_reach.h"

#include <algorithm>
#include <cmath>

namespace ml {

namespace {

// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const float denom = 1.0f / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

// Triangles binned by the grid cells their bounding boxes overlap (a compressed row per cell).
class TriangleGrid {
public:
    explicit TriangleGrid(const Scene& scene) : scene_(scene), bounds_(scene.bounds) {
        const std::size_t triangles = scene.triangleCount();
        // About one triangle per cell, at most 64 cells a side (262,144 cells).
        const int n = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(triangles))), 1, 64);
        cells_ = glm::ivec3(n);
        const glm::vec3 size = glm::max(bounds_.size(), glm::vec3(1e-6f));
        cellSize_ = size / glm::vec3(cells_);
        offsets_.assign(static_cast<std::size_t>(n) * n * n + 1, 0);
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<std::uint32_t> cursor;
            if (pass == 1) {
                for (std::size_t i = 1; i < offsets_.size(); ++i) offsets_[i] += offsets_[i - 1];
                triangles_.resize(offsets_.back());
                cursor.assign(offsets_.begin(), offsets_.end() - 1);
            }
            for (std::size_t t = 0; t < triangles; ++t) {
                Bounds box;
                for (int k = 0; k < 3; ++k) box.extend(vertex(t, k));
                forCells(box.min, box.max, [&](std::size_t cell) {
                    if (pass == 0) ++offsets_[cell + 1];
                    else triangles_[cursor[cell]++] = static_cast<std::uint32_t>(t);
                    return false;
                });
            }
        }
    }

    bool sphereTouches(const glm::vec3& centre, float radius) const {
        const float r2 = radius * radius;
        return forCells(centre - glm::vec3(radius), centre + glm::vec3(radius), [&](std::size_t cell) {
            for (std::uint32_t i = offsets_[cell]; i < offsets_[cell + 1]; ++i) {
                const std::size_t t = triangles_[i];
                const glm::vec3 d = closestPointOnTriangle(centre, vertex(t, 0), vertex(t, 1), vertex(t, 2)) - centre;
                if (glm::dot(d, d) <= r2) return true;
            }
            return false;
        });
    }

private:
    glm::vec3 vertex(std::size_t t, int k) const { return scene_.vertices[scene_.indices[3 * t + k]].position; }

    // Calls visit(cell) for the cells overlapping [lo, hi] until it returns true; false when
    // the box misses the grid.
    template <typename Visit>
    bool forCells(const glm::vec3& lo, const glm::vec3& hi, Visit&& visit) const {
        if (glm::any(glm::lessThan(hi, bounds_.min)) || glm::any(glm::greaterThan(lo, bounds_.max))) return false;
        const glm::ivec3 first = glm::clamp(glm::ivec3(glm::floor((lo - bounds_.min) / cellSize_)), glm::ivec3(0), cells_ - 1);
        const glm::ivec3 last = glm::clamp(glm::ivec3(glm::floor((hi - bounds_.min) / cellSize_)), glm::ivec3(0), cells_ - 1);
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x)
                    if (visit((static_cast<std::size_t>(z) * cells_.y + y) * cells_.x + x)) return true;
        return false;
    }

    const Scene& scene_;
    Bounds bounds_;
    glm::ivec3 cells_{1};
    glm::vec3 cellSize_{1.0f};
    std::vector<std::uint32_t> offsets_;    // cell -> first entry in triangles_, one past the last cell
    std::vector<std::uint32_t> triangles_;  // triangle indices, cell after cell
};

}  // namespace

SurfaceReach measureSurfaceReach(const Scene& scene, const std::vector<Light>& lights) {
    SurfaceReach reach;
    if (scene.bounds.empty() || scene.indices.empty()) return reach;
    const TriangleGrid grid(scene);
    for (const Light& light : lights) {
        if (light.type == LightType::Directional) continue;
        ++reach.lights;
        if (grid.sphereTouches(light.position, light.radius)) ++reach.reaching;
    }
    return reach;
}

}  // namespace ml
