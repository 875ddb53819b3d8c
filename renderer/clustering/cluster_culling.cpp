#include "renderer/clustering/cluster_culling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ml {

namespace {

constexpr float kRadiusSlack = 1.0f + 1e-5f;  // as kCullRadiusSlack in the shader

// The six faces as corner indices around each face.
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};

bool reachesAabb(const ClusterFrustum& f, const glm::vec3& c, float r) { return distanceSquared(boundsOf(f), c) <= r * r; }

bool reachesFrustumPlanes(const ClusterFrustum& f, const glm::vec3& c, float r) {
    if (-c.z + r < f.zNear || -c.z - r > f.zFar) return false;
    const glm::vec2 xy(c.x, c.y);
    const glm::vec2 lower = (xy + f.slopeLo * c.z) / glm::sqrt(1.0f + f.slopeLo * f.slopeLo);
    const glm::vec2 upper = (-xy - f.slopeHi * c.z) / glm::sqrt(1.0f + f.slopeHi * f.slopeHi);
    return lower.x >= -r && lower.y >= -r && upper.x >= -r && upper.y >= -r;
}

bool reachesSlicedCone(const ClusterFrustum& f, const glm::vec3& c, float r) {
    const glm::vec3 corner[4] = {glm::normalize(glm::vec3(f.slopeLo.x, f.slopeLo.y, -1.0f)),
                                 glm::normalize(glm::vec3(f.slopeHi.x, f.slopeLo.y, -1.0f)),
                                 glm::normalize(glm::vec3(f.slopeLo.x, f.slopeHi.y, -1.0f)),
                                 glm::normalize(glm::vec3(f.slopeHi.x, f.slopeHi.y, -1.0f))};
    const glm::vec3 axis = glm::normalize(corner[0] + corner[1] + corner[2] + corner[3]);
    float tileCos = 1.0f, minDepth = 1.0f;
    for (const glm::vec3& d : corner) {
        tileCos = std::min(tileCos, glm::dot(axis, d));
        minDepth = std::min(minDepth, -d.z);
    }
    tileCos = std::clamp(tileCos - 1e-6f, 0.0f, 1.0f);
    const float tileSin = std::sqrt(1.0f - tileCos * tileCos);
    const float shellNear = f.zNear, shellFar = f.zFar / minDepth;
    const float dist = glm::length(c);
    if (dist <= r) return dist + r >= shellNear;
    const float lightSin = r / dist, lightCos = std::sqrt(std::max(1.0f - lightSin * lightSin, 0.0f));
    const float cosToAxis = std::clamp(glm::dot(c / dist, axis), -1.0f, 1.0f);
    const float sinToAxis = std::sqrt(1.0f - cosToAxis * cosToAxis);
    if (cosToAxis < tileCos * lightCos - tileSin * lightSin) return false;
    const float sinDiff = std::clamp(sinToAxis * tileCos - cosToAxis * tileSin, 0.0f, 1.0f);
    const float cosDiff = sinDiff == 0.0f ? 1.0f : cosToAxis * tileCos + sinToAxis * tileSin;
    const float base = dist * cosDiff;
    const float chord = std::sqrt(std::max(r * r - dist * dist * sinDiff * sinDiff, 0.0f));
    return base - chord <= shellFar && base + chord >= shellNear;
}

float distanceToSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

}  // namespace

CullMode parseCullMode(const std::string& text) {
    if (text == "aabb") return CullMode::Aabb;
    if (text == "sphere") return CullMode::Sphere;
    if (text == "cone") return CullMode::Cone;
    throw std::invalid_argument("--cull '" + text + "': expected aabb, sphere or cone");
}

const char* cullModeName(CullMode mode) {
    switch (mode) {
    case CullMode::Aabb: return "aabb";
    case CullMode::Sphere: return "sphere";
    case CullMode::Cone: return "cone";
    }
    return "?";
}

ClusterFrustum clusterFrustum(const ClusterGrid& grid, const DepthSlicing& slicing, float cameraNear, float cameraFar,
                              const glm::mat4& projection, int width, int height, std::uint32_t x, std::uint32_t y,
                              std::uint32_t slice) {
    const float w = float(width), h = float(height);
    const glm::vec2 p0(std::min(x * grid.tileSizePx, w), std::min(y * grid.tileSizePx, h));
    const glm::vec2 p1(std::min((x + 1) * grid.tileSizePx, w), std::min((y + 1) * grid.tileSizePx, h));
    const glm::vec2 scale(projection[0][0], projection[1][1]);
    ClusterFrustum f;
    f.slopeLo = (p0 / glm::vec2(w, h) * 2.0f - 1.0f) / scale;
    f.slopeHi = (p1 / glm::vec2(w, h) * 2.0f - 1.0f) / scale;
    const float z0 = slice == 0 ? std::min(cameraNear, slicing.zNear) : slicing.boundary(slice, grid.slices);
    const float z1 = slice + 1 == grid.slices ? std::max(cameraFar, slicing.zFar) : slicing.boundary(slice + 1, grid.slices);
    // Widen by a relative epsilon so rounding in the fragment's slice lookup cannot fall outside.
    f.zNear = z0 * (1.0f - 1e-4f);
    f.zFar = z1 * (1.0f + 1e-4f);
    for (int k = 0; k < 8; ++k) {
        const float sx = (k & 1) ? f.slopeHi.x : f.slopeLo.x, sy = (k & 2) ? f.slopeHi.y : f.slopeLo.y;
        const float z = (k & 4) ? f.zFar : f.zNear;
        f.corners[k] = glm::vec3(sx * z, sy * z, -z);
    }
    return f;
}

Aabb boundsOf(const ClusterFrustum& f) {
    Aabb box{glm::vec3(std::numeric_limits<float>::max()), glm::vec3(std::numeric_limits<float>::lowest())};
    for (const glm::vec3& p : f.corners) {
        box.min = glm::min(box.min, p);
        box.max = glm::max(box.max, p);
    }
    return box;
}

bool passesCullTest(CullMode mode, const ClusterFrustum& cluster, const glm::vec3& center, float radius) {
    const float r = radius * kRadiusSlack;
    switch (mode) {
    case CullMode::Aabb: return reachesAabb(cluster, center, r);
    case CullMode::Sphere: return reachesFrustumPlanes(cluster, center, r);
    case CullMode::Cone: return reachesSlicedCone(cluster, center, r);
    }
    return true;
}

bool passesLightCullTest(CullMode mode, const ClusterFrustum& cluster, const SpotCone& light) {
    if (!(light.radius > 0.0f)) return false;
    const glm::vec4 sphere = spotBoundingSphere(light);
    if (!passesCullTest(mode, cluster, glm::vec3(sphere), sphere.w)) return false;
    const Aabb box = boundsOf(cluster);
    return spotMayReachSphere(light, 0.5f * (box.min + box.max), 0.5f * glm::length(box.max - box.min));
}

bool lightReachesCluster(const ClusterFrustum& cluster, const SpotCone& light) {
    if (distanceToCluster(cluster, light.apex) >= light.radius) return false;
    return !light.isSpot() || spotMeetsConvexHull(light, cluster.corners);
}

float distanceToCluster(const ClusterFrustum& f, const glm::vec3& p) {
    const glm::vec3 centroid = [&] {
        glm::vec3 s(0.0f);
        for (const glm::vec3& c : f.corners) s += c;
        return s / 8.0f;
    }();
    float best = std::numeric_limits<float>::max();
    bool inside = true;
    for (const auto& face : kFaces) {
        const glm::vec3& a = f.corners[face[0]];
        glm::vec3 n = glm::normalize(glm::cross(f.corners[face[1]] - a, f.corners[face[3]] - a));
        if (glm::dot(n, centroid - a) > 0.0f) n = -n;  // outward
        const float d = glm::dot(n, p - a);
        if (d <= 0.0f) continue;
        inside = false;
        // The closest point is in this face when p's projection lies inside the (convex) face.
        const glm::vec3 q = p - d * n;
        bool within = true;
        for (int i = 0; i < 4 && within; ++i) {
            const glm::vec3& u = f.corners[face[i]];
            const glm::vec3& v = f.corners[face[(i + 1) % 4]];
            within = glm::dot(glm::cross(v - u, q - u), n) >= 0.0f;
        }
        if (!within) {  // the other winding
            within = true;
            for (int i = 0; i < 4 && within; ++i) {
                const glm::vec3& u = f.corners[face[i]];
                const glm::vec3& v = f.corners[face[(i + 1) % 4]];
                within = glm::dot(glm::cross(v - u, q - u), n) <= 0.0f;
            }
        }
        if (within) best = std::min(best, d);
    }
    if (inside) return 0.0f;
    // Otherwise the closest point is on an edge (or a corner, an edge's end).
    for (int k = 0; k < 8; ++k)
        for (int bit : {1, 2, 4})
            if (!(k & bit)) best = std::min(best, distanceToSegment(p, f.corners[k], f.corners[k | bit]));
    return best;
}

}  // namespace ml
