// A spot light's lit region on the CPU, mirroring glsl/include/spot_cone.glsl: its cone (apex at
// the light, unit axis, outer half-angle at most 90 degrees) cut by the sphere of its radius, a
// convex spherical sector. The conservative tests the GPU runs, and an exact one (GJK against
// a convex hull) that --stats and the tests measure them by.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"
#include "renderer/lights/light_set.h"
#include "renderer/clustering/cluster_grid.h"

namespace ml {

struct SpotCone {
    glm::vec3 apex{0.0f};
    glm::vec3 axis{0.0f, 0.0f, -1.0f};  // unit
    float cosOuter = float(ML_POINT_LIGHT_CONE_COS);  // a point light: its whole sphere
    float radius = 1.0f;
    bool isSpot() const { return cosOuter > -1.5f; }
};

// The light's region in the space `transform` maps world space to (the view matrix for the
// clusters); a point light's cone is its whole sphere. The cosine is the one the GPU gets.
SpotCone spotConeOf(const Light& light, const glm::mat4& transform = glm::mat4(1.0f));

// The sector's farthest extent along unit direction n, from the apex (its support function).
float spotReach(const SpotCone& cone, const glm::vec3& n);
// The point of the sector farthest along n (any non-zero n).
glm::vec3 spotSupportPoint(const SpotCone& cone, const glm::vec3& n);
// A sphere holding the sector (xyz centre, w radius; a point light's own sphere).
glm::vec4 spotBoundingSphere(const SpotCone& cone);
// The sector's exact axis-aligned box (with the GPU's slack).
Aabb spotBounds(const SpotCone& cone);
// Wronski's cone-against-sphere test: false only where the sector cannot reach the sphere.
bool spotMayReachSphere(const SpotCone& cone, const glm::vec3& center, float sphereRadius);
// Exact (GJK, to float precision): does the sector meet the convex hull of `points`? Undecided
// cases (touching within rounding) count as meeting.
bool spotMeetsConvexHull(const SpotCone& cone, std::span<const glm::vec3> points);

}  // namespace ml
