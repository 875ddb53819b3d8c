// An independent answer to "is this segment blocked?" for the tests: Embree's own ray caster
// (rtcOccluded1, libembree-dev) over the same shadow casters as the shadow rays' BVH
// (shadow_casters.h: the same world-space float corners, BLEND triangles left out), in a scene
// of one triangle geometry. It shares nothing with our structure but the triangle list: Embree
// builds its own BVH and, with RTC_SCENE_FLAG_ROBUST, tests triangles watertight, so a ray
// through a shared edge meets one of its two triangles. Only the tests use it (the shipping
// binary links none of it).
//
// Rays as in shadow_bvh_traversal.h: origin + t direction for t in [0, tMax], t in units of
// |direction| (tnear 0, tfar tMax; direction need not be unit).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "renderer/raytracing/shadow_bvh_traversal.h"
#include "scenes/scene.h"

namespace ml {

class EmbreeOcclusion {
public:
    // Throws std::runtime_error, one line naming the scene, where Embree fails.
    explicit EmbreeOcclusion(const Scene& scene);
    ~EmbreeOcclusion();
    EmbreeOcclusion(const EmbreeOcclusion&) = delete;
    EmbreeOcclusion& operator=(const EmbreeOcclusion&) = delete;

    // As occludedByBvh: an alpha-tested (MASK) triangle blocks where `covered` says so (asked
    // from Embree's occlusion filter with the hit's u, v, which weigh corners 1 and 2 as ours
    // do), and always where no `covered` is given.
    bool occluded(glm::vec3 origin, glm::vec3 direction, float tMax, const ShadowCoverage& covered = {}) const;

    // The nearest casting triangle along the ray (rtcIntersect1), for the tests' primary rays:
    // MASK triangles count as opaque here (no filter), so callers set their hits apart.
    struct Hit {
        float t;                     // in units of |direction|
        std::uint32_t sceneTriangle;  // indices[3t .. 3t + 2]
        std::uint32_t material;       // kShadowOpaque, or the MASK material
        float u, v;                   // weighing the scene triangle's corners 1 and 2
    };
    std::optional<Hit> firstHit(glm::vec3 origin, glm::vec3 direction, float tMax) const;

    std::size_t triangles() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ml
