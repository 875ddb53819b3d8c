// What a shadow ray reads where it meets an alpha-tested (MASK) triangle: the base colour's alpha
// at the hit, so that foliage casts leaf-shaped shadows. GL 4.5 has no bindless textures and a
// ray may meet any material, so the alpha of every MASK material's base colour texture is copied
// into one R8 texture array (a layer per image, each resampled to the largest one's size), bound
// once beside the BVH, and each MASK triangle's UVs go into the BVH's buffer.
//
// The rule, the same in every method (they trace the same rays): alpha = baseColorFactor.a times
// the layer's alpha at the hit's UV (its texture transform applied, repeat wrap, bilinear, level 0),
// covered where alpha >= alphaCutoff. Left out: COLOR_0's alpha, the sampler's own wrap modes and
// mip level (a shadow ray has no footprint to choose one from).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/raytracing/shadow_bvh.h"
#include "renderer/raytracing/shadow_bvh_traversal.h"
#include "scenes/scene.h"

namespace ml {

struct ShadowAlphaMasks {
    // Each layer layerSize x layerSize texels of alpha, rows as the images hold them (top first:
    // row 0 at v = 0, as glTF's UVs and the material textures have it).
    int layerSize = 0;
    int layerCount = 0;
    std::vector<std::uint8_t> texels;
    // Three vec4s per scene material (MASK ones filled): the UV transform's columns; its offset,
    // alphaCutoff, baseColorFactor.a; the layer (float bits of an int, -1: no texture).
    std::vector<glm::vec4> materials;
    // Two vec4s per MASK triangle of the BVH, indexed by the triangle's v2.w: (uv0, uv1), (uv2, 0, 0).
    std::vector<glm::vec4> uvs;

    bool empty() const { return uvs.empty(); }
};

// Fills the masks for `bvh`'s MASK triangles and points each one's v2.w at its UV record.
ShadowAlphaMasks buildShadowAlphaMasks(const Scene& scene, ShadowBvh& bvh);

// The CPU's reading of the same rule, for occludedByBvh (the tests' mirror of the GPU): a
// bilinear sample of the same layers (the GPU's filter weights have 8 bits of sub-texel
// precision, so the two can part where alpha crosses the cut-off between two texels).
ShadowCoverage shadowAlphaCoverage(const Scene& scene, const ShadowAlphaMasks& masks);

}  // namespace ml
