// C++ mirrors of the structs the shaders read. Layouts are locked with static_assert so a
// change on one side cannot silently drift from the other (glsl/include/*.glsl).
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"

namespace ml {

// glsl/include/lights.glsl: struct Light (std430), 32 B. A spot's cone lives in a buffer of its
// own (GpuLightCone), uploaded only where the set has spots, so that the passes that stream every
// light of a list through a workgroup read 32 B a light where no light is a spot.
struct alignas(16) GpuLight {
    glm::vec4 positionRadius;  // xyz world position, w radius
    glm::vec4 colorCosInner;   // rgb linear colour times intensity, w cos of the inner cone angle
};
static_assert(sizeof(GpuLight) == 32);
static_assert(alignof(GpuLight) == 16);

// glsl/include/lights.glsl: lightCones[] (std430), one per clustered light.
struct alignas(16) GpuLightCone {
    glm::vec4 directionCosOuter;  // xyz unit spot direction (0 for points), w cos of the outer cone angle
};
static_assert(sizeof(GpuLightCone) == 16);

// glsl/include/sun_lights.glsl: SunLightsBlock (std140).
struct alignas(16) GpuSunLights {
    glm::uvec4 count;  // x: directional lights in use
    glm::vec4 direction[ML_MAX_SUN_LIGHTS];  // xyz unit direction the light travels
    glm::vec4 color[ML_MAX_SUN_LIGHTS];      // rgb linear colour times intensity
};
static_assert(sizeof(GpuSunLights) == 16 + 32 * ML_MAX_SUN_LIGHTS);

// glsl/include/material.glsl: struct Material (std430). A scene without ML_FEATURES_EXTENDED_RECORD
// uploads the record up to the core slots' transforms (ML_GPU_MATERIAL_VEC4S(false) vec4s); with
// any, the whole record (ML_GPU_MATERIAL_VEC4S(true)).
struct alignas(16) GpuMaterial {
    glm::vec4 baseColorFactor;
    glm::vec4 emissiveCutoff;  // rgb emissive, a alpha cutoff
    glm::vec4 factors;         // metallic, roughness, normal scale, occlusion strength
    glm::uvec4 info;           // texture slot bits, TEXCOORD_1 slot bits, texture set + 1, ML_MATERIAL_* bits
    glm::vec4 uvTransforms[2 * ML_TEXTURE_SLOTS];  // per slot: mat2 columns, offset
    // KHR_materials_ior and KHR_materials_specular: rgb ((ior - 1) / (ior + 1))^2 x specularColorFactor
    // (the colour texture multiplies it, then it is clamped to 1), a specularFactor.
    glm::vec4 specular;
    // KHR_materials_clearcoat: clearcoatFactor, clearcoatRoughnessFactor, the clearcoat normal
    // texture's scale, 0.
    glm::vec4 clearcoat;
    // KHR_materials_sheen: rgb sheenColorFactor, a sheenRoughnessFactor.
    glm::vec4 sheen;
    // KHR_materials_anisotropy: cos and sin of anisotropyRotation, anisotropyStrength, 0.
    glm::vec4 anisotropy;
    // KHR_materials_iridescence: iridescenceFactor, iridescenceIor, the thickness's minimum and
    // maximum (nm).
    glm::vec4 iridescence;
    // KHR_materials_transmission and KHR_materials_volume: transmissionFactor, thicknessFactor,
    // attenuationDistance (0: infinite), the IOR; and rgb attenuationColor, 0.
    glm::vec4 transmission;
    glm::vec4 attenuation;
};
static_assert(sizeof(GpuMaterial) == 16 * ML_GPU_MATERIAL_VEC4S(true));
static_assert(offsetof(GpuMaterial, uvTransforms) + 32 * ML_CORE_TEXTURE_SLOTS == 16 * ML_GPU_MATERIAL_VEC4S(false));

// glsl/include/frame_uniforms.glsl: FrameUniformsBlock (std140).
struct alignas(16) FrameUniforms {
    glm::mat4 view;
    glm::mat4 proj;
    glm::mat4 viewProj;
    glm::mat4 invProj;
    glm::mat4 invView;
    glm::vec4 cameraPos;
    glm::vec4 viewport;    // width, height, 1/width, 1/height
    glm::vec4 depthRange;  // near, far, time, ambient
    glm::uvec4 counts;     // light count, shading switches (ML_SHADING_*), falloff (ML_FALLOFF_*), the frame's draw seed (stochasticDrawSeed)
    glm::vec4 lightModel;  // --light-cutoff E, a directional shadow ray's length, 0, 0
    glm::uvec4 shadows;    // --shadows rays: the first triangle's vec4 in the BVH buffer, nodes, triangles, 0
};
static_assert(sizeof(FrameUniforms) == 5 * 64 + 6 * 16);

// glsl/include/cluster_grid.glsl: ClusterGridData (std430).
struct alignas(16) ClusterGridGpu {
    glm::uvec4 dims;       // tilesX, tilesY, slices, cluster count
    glm::vec4 slicing;     // zNear, zFar, scale, bias
    glm::vec4 tile;        // tile size px, logarithmic, camera near, camera far
    glm::uvec4 reduction;  // min, max visible depth bits (fitted)
    glm::uvec4 options;    // fitted, cap (0: exact), active-only, debug view
};
static_assert(sizeof(ClusterGridGpu) == 80);

// glsl/cluster_bounds.comp: ClusterAabb (std430).
struct alignas(16) ClusterAabbGpu {
    glm::vec4 minPoint;
    glm::vec4 maxPoint;
};
static_assert(sizeof(ClusterAabbGpu) == 32);

}  // namespace ml
