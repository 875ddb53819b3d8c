// The shadow rays' traversal on the CPU: a mirror of glsl/include/shadow_rays.glsl over the same
// arrays (shadow_bvh.h), written in the same arithmetic, operation by operation, so that the
// tests can hold the GPU's structure to Embree's own answer (embree_occlusion.h) and the GPU's
// decisions to this one. A ray is the segment origin + t direction, t in (0, tMax): t counts in
// units of |direction| (the GPU traces direction = light - origin, tMax = 1).
//
// The arithmetic (float, no fused multiply-add: this build has none, and the GLSL should mark it
// `precise` where it must agree to the bit):
//
//   inverse   per axis: d' = |d| < 1e-30 ? (d < 0 ? -1e-30 : 1e-30) : d, then 1 / d'. Finite, so
//             no 0 * inf makes a NaN where the origin lies on a box's face (d = -0 takes +1e-30).
//             A ray with d = 0 on an axis, lying exactly in the plane of a box's face on it, gets
//             the slab [0, 1e30 (hi - lo)] on the lo face and [-1e30 (hi - lo), 0] on the hi face:
//             the box is met on the one and not (past t = 0) on the other. Inside such a box the
//             ray can touch a triangle only on its edge or corner in that plane (a triangle in the
//             plane itself has det == 0), and the triangle across a shared edge lies in the box
//             whose lo face that is: only a free edge lying exactly in the ray's plane is lost.
//   box       t0 = (lo - o) * inverse, t1 = (hi - o) * inverse (per axis);
//             tNear = min(t0, t1), tFar = max(t0, t1), min and max as GLSL's (y < x ? y : x);
//             enter = max(max(tNear.x, tNear.y), max(tNear.z, 0)),
//             leave = min(min(tFar.x, tFar.y), min(tFar.z, tMax)); met where enter <= leave.
//             (That is: tNear <= tFar, tFar >= 0, tNear <= tMax, the box closed.) An empty box
//             (lo +inf, hi -inf) gives tNear -inf, tFar +inf: met, see shadow_bvh.h.
//   triangle  Moller-Trumbore, two-sided: e1 = v1 - v0, e2 = v2 - v0, p = cross(d, e2),
//             det = dot(e1, p); none where det == 0 exactly; inv = 1 / det; s = o - v0,
//             u = dot(s, p) * inv, none where u < 0 || u > 1; q = cross(s, e1),
//             v = dot(d, q) * inv, none where v < 0 || u + v > 1; t = dot(e2, q) * inv,
//             a hit where t > 0 && t < tMax. cross and dot as GLSL and GLM write them:
//             cross(a, b) = (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y),
//             dot(a, b) = (a.x b.x + a.y b.y) + a.z b.z.
//   walk      a stack of ML_SHADOW_STACK references, the root pushed first; pop one: a leaf
//             tests its triangles in order and ends the walk at the first that blocks; a node
//             tests its children's boxes in slot order (binary: left, then right), pushing the
//             reference of each box met (so the last child is popped first); a wide node's empty
//             slots are skipped. At most width * nodes + 1 pops (each reference once).
//             The GLSL skips a push onto a full stack; here it throws std::logic_error, and
//             the build's depth bound (shadow_bvh.h) keeps it from happening.
//   finite    a ray whose origin or direction is infinite or NaN is not traced (unblocked): a
//             NaN meets every box where min and max drop NaN operands, as GPUs' do.
//   MASK      a triangle whose material word is not ML_SHADOW_OPAQUE blocks where `covered`
//             says so for its material, its scene triangle and the hit's (u, v) (the GPU samples
//             the base colour's alpha there); with no `covered`, it blocks as an opaque one.
#pragma once

#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "renderer/raytracing/shadow_bvh.h"

namespace ml {

// Whether an alpha-tested triangle covers the hit at barycentrics (u, v): the point
// (1 - u - v) v0 + u v1 + v v2 of the scene triangle's corners, in the scene's order.
using ShadowCoverage = std::function<bool(std::uint32_t material, std::uint32_t sceneTriangle, float u, float v)>;

// What a walk did, added up over rays: the work the GPU's traversal does for the same rays.
struct ShadowTraversalCounts {
    std::uint64_t rays = 0;
    std::uint64_t nodes = 0;      // inner nodes popped (their boxes read and tested)
    std::uint64_t boxes = 0;      // child boxes tested
    std::uint64_t pushes = 0;     // references pushed (stack writes)
    std::uint64_t triangles = 0;  // triangles tested
};

// Whether anything blocks the segment from origin to origin + tMax direction; `counts`, where
// given, adds up the walk's work.
bool occludedByBvh(const ShadowBvh& bvh, glm::vec3 origin, glm::vec3 direction, float tMax,
                   const ShadowCoverage& covered = {}, ShadowTraversalCounts* counts = nullptr);

// The pieces, for tests of their own.
glm::vec3 shadowRayInverse(glm::vec3 direction);
bool shadowBoxHit(glm::vec3 lo, glm::vec3 hi, glm::vec3 origin, glm::vec3 inverse, float tMax);
// On a hit, (u, v) are the hit's barycentrics as above.
bool shadowTriangleHit(const GpuBvhTriangle& triangle, glm::vec3 origin, glm::vec3 direction, float tMax, float& u, float& v);

// glsl/include/shadow_rays.glsl's shadowRayOrigin: the point p moved off its surface along n
// (Wachter and Binder, Ray Tracing Gems chapter 6): by 256 ulps of each coordinate, or by n / 65536
// for a coordinate within 1/32 of 0. The tests start their rays here, as the GPU does.
glm::vec3 shadowRayOrigin(glm::vec3 p, glm::vec3 n);

}  // namespace ml
