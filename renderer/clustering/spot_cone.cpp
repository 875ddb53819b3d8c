#include "renderer/clustering/spot_cone.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ml {

namespace {

constexpr float kSpotSlack = 1e-4f;  // as in glsl/include/spot_cone.glsl

// GJK's simplex update (Muratori's formulation): a = the newest point, the origin is tested
// against the simplex's features; returns true when the simplex holds the origin.
bool lineCase(std::vector<glm::vec3>& s, glm::vec3& d) {
    const glm::vec3 a = s[1], b = s[0], ab = b - a, ao = -a;
    if (glm::dot(ab, ao) > 0.0f) {
        d = glm::cross(glm::cross(ab, ao), ab);
        if (glm::dot(d, d) < 1e-30f) return true;  // the origin lies on the segment
    } else {
        s = {a};
        d = ao;
    }
    return false;
}

bool triangleCase(std::vector<glm::vec3>& s, glm::vec3& d) {
    const glm::vec3 a = s[2], b = s[1], c = s[0];
    const glm::vec3 ab = b - a, ac = c - a, ao = -a, abc = glm::cross(ab, ac);
    if (glm::dot(glm::cross(abc, ac), ao) > 0.0f) {
        if (glm::dot(ac, ao) > 0.0f) {
            s = {c, a};
            d = glm::cross(glm::cross(ac, ao), ac);
            return glm::dot(d, d) < 1e-30f;
        }
        s = {b, a};
        return lineCase(s, d);
    }
    if (glm::dot(glm::cross(ab, abc), ao) > 0.0f) {
        s = {b, a};
        return lineCase(s, d);
    }
    const float side = glm::dot(abc, ao);
    if (side == 0.0f) return true;  // the origin lies in the triangle
    if (side > 0.0f) {
        s = {c, b, a};
        d = abc;
    } else {
        s = {b, c, a};
        d = -abc;
    }
    return false;
}

bool tetrahedronCase(std::vector<glm::vec3>& s, glm::vec3& d) {
    const glm::vec3 a = s[3], b = s[2], c = s[1], e = s[0];
    const glm::vec3 ab = b - a, ac = c - a, ae = e - a, ao = -a;
    // Each face's normal pointing away from the fourth point.
    glm::vec3 abc = glm::cross(ab, ac), ace = glm::cross(ac, ae), aeb = glm::cross(ae, ab);
    if (glm::dot(abc, ae) > 0.0f) abc = -abc;
    if (glm::dot(ace, ab) > 0.0f) ace = -ace;
    if (glm::dot(aeb, ac) > 0.0f) aeb = -aeb;
    if (glm::dot(abc, ao) > 0.0f) {
        s = {c, b, a};
        return triangleCase(s, d);
    }
    if (glm::dot(ace, ao) > 0.0f) {
        s = {e, c, a};
        return triangleCase(s, d);
    }
    if (glm::dot(aeb, ao) > 0.0f) {
        s = {b, e, a};
        return triangleCase(s, d);
    }
    return true;
}

}  // namespace

SpotCone spotConeOf(const Light& light, const glm::mat4& transform) {
    SpotCone c;
    c.apex = glm::vec3(transform * glm::vec4(light.position, 1.0f));
    c.radius = light.radius;
    if (light.type == LightType::Spot) {
        c.axis = glm::mat3(transform) * glm::normalize(light.direction);
        c.cosOuter = std::cos(light.outerConeAngle);
    }
    return c;
}

float spotReach(const SpotCone& cone, const glm::vec3& n) {
    const float cosToAxis = glm::dot(n, cone.axis);
    if (cosToAxis >= cone.cosOuter) return cone.radius;
    const float sinOuter = std::sqrt(std::max(1.0f - cone.cosOuter * cone.cosOuter, 0.0f));
    const float sinToAxis = std::sqrt(std::max(1.0f - cosToAxis * cosToAxis, 0.0f));
    return cone.radius * std::max(cosToAxis * cone.cosOuter + sinToAxis * sinOuter, 0.0f);
}

glm::vec3 spotSupportPoint(const SpotCone& cone, const glm::vec3& direction) {
    const glm::vec3 n = glm::normalize(direction);
    if (!cone.isSpot() || glm::dot(n, cone.axis) >= cone.cosOuter) return cone.apex + cone.radius * n;
    // Outside the cone: the cone's edge ray nearest to n, if it leans towards n at all.
    const glm::vec3 across = n - glm::dot(n, cone.axis) * cone.axis;
    const float acrossLength = glm::length(across);
    if (acrossLength < 1e-12f) return cone.apex;  // n is -axis
    const float sinOuter = std::sqrt(std::max(1.0f - cone.cosOuter * cone.cosOuter, 0.0f));
    const glm::vec3 edge = cone.cosOuter * cone.axis + sinOuter * (across / acrossLength);
    return glm::dot(edge, n) > 0.0f ? cone.apex + cone.radius * edge : cone.apex;
}

glm::vec4 spotBoundingSphere(const SpotCone& cone) {
    if (!cone.isSpot()) return glm::vec4(cone.apex, cone.radius);
    const float slack = kSpotSlack * (cone.radius + glm::length(cone.apex));
    if (cone.cosOuter >= 0.70710678f) {
        const float t = cone.radius / (2.0f * cone.cosOuter);
        return glm::vec4(cone.apex + cone.axis * t, t + slack);
    }
    const float c = std::max(cone.cosOuter, 0.0f);
    return glm::vec4(cone.apex + cone.axis * (cone.radius * c), cone.radius * std::sqrt(1.0f - c * c) + slack);
}

Aabb spotBounds(const SpotCone& cone) {
    if (!cone.isSpot()) return Aabb{cone.apex - cone.radius, cone.apex + cone.radius};
    const float slack = kSpotSlack * (cone.radius + glm::length(cone.apex));
    Aabb box;
    for (int a = 0; a < 3; ++a) {
        glm::vec3 e(0.0f);
        e[a] = 1.0f;
        box.max[a] = cone.apex[a] + spotReach(cone, e) + slack;
        box.min[a] = cone.apex[a] - spotReach(cone, -e) - slack;
    }
    return box;
}

bool spotMayReachSphere(const SpotCone& cone, const glm::vec3& center, float sphereRadius) {
    if (!cone.isSpot()) return true;
    const glm::vec3 v = center - cone.apex;
    const float lengthSq = glm::dot(v, v);
    const float along = glm::dot(v, cone.axis);
    const float sinOuter = std::sqrt(std::max(1.0f - cone.cosOuter * cone.cosOuter, 0.0f));
    const float toSide = cone.cosOuter * std::sqrt(std::max(lengthSq - along * along, 0.0f)) - along * sinOuter;
    const float reach = sphereRadius + kSpotSlack * (std::sqrt(lengthSq) + sphereRadius + cone.radius);
    return !(toSide > reach || along > cone.radius + reach || along < -reach);
}

bool spotMeetsConvexHull(const SpotCone& cone, std::span<const glm::vec3> points) {
    if (points.empty()) return false;
    // Support of the Minkowski difference hull - sector: the origin is inside iff they meet.
    const auto support = [&](const glm::vec3& d) {
        glm::vec3 best = points[0];
        float bestDot = glm::dot(best, d);
        for (const glm::vec3& p : points)
            if (const float t = glm::dot(p, d); t > bestDot) bestDot = t, best = p;
        return best - spotSupportPoint(cone, -d);
    };
    std::vector<glm::vec3> simplex;
    glm::vec3 d = points[0] - cone.apex;
    if (glm::dot(d, d) == 0.0f) return true;
    simplex.push_back(support(d));
    d = -simplex[0];
    for (int iteration = 0; iteration < 64; ++iteration) {
        if (glm::dot(d, d) < 1e-30f) return true;
        const glm::vec3 a = support(d);
        // No point of the difference lies past the origin along d: a separating plane.
        if (glm::dot(a, d) < 0.0f) return false;
        simplex.push_back(a);
        const bool holds = simplex.size() == 2 ? lineCase(simplex, d)
                           : simplex.size() == 3 ? triangleCase(simplex, d)
                                                 : tetrahedronCase(simplex, d);
        if (holds) return true;
    }
    return true;
}

}  // namespace ml
