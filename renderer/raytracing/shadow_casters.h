// Which of a scene's triangles cast shadows, and how: the one list that the shadow rays' BVH
// (shadow_bvh.h) and the Embree oracle of the tests (embree_occlusion.h) are both built from.
//
// The rule (docs: lights and shading): every triangle of a draw range whose material is not BLEND
// casts a shadow. BLEND surfaces, glass among them, cast none, in every method. OPAQUE triangles
// always block; MASK (alpha-tested) ones block where their base colour's alpha covers the hit,
// which the GPU samples there (so they carry their material's index).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace ml {

struct ShadowCaster {
    glm::vec3 corners[3];          // world space, as Scene::vertices holds them, in the scene's corner order
    std::uint32_t material;        // kShadowOpaque (shadow_bvh_layout.h), or the MASK material's index
    std::uint32_t sceneTriangle;   // the triangle's index in the scene: indices[3t .. 3t + 2]
};

// In the order of scene.draws, then of each range's triangles. Throws std::runtime_error, one
// line naming the scene, for a corner that is not finite (NaN or infinity): no box holds it.
std::vector<ShadowCaster> shadowCasters(const Scene& scene);

}  // namespace ml
