// How light leaves a light and what a surface does with it: the BRDF, the falloff with distance,
// and where a light is cut off (README, "The light model"). The same in every method (compiled in,
// ShadingSwitches, or frame uniforms) and in the CPU mirror (renderer/reference/shading_reference.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"
#include "renderer/lights/light_set.h"
#include "renderer/raytracing/shadow_bvh_layout.h"

namespace ml {

// --brdf: glTF's metallic-roughness BRDF (GGX, height-correlated Smith, Schlick, Lambert; the
// default, as in Khronos' Sample Viewer, Filament and Bevy), or the normalized Blinn-Phong
// mapping of the seeds.
enum class Brdf { BlinnPhong, Ggx };
const char* brdfName(Brdf brdf);
Brdf parseBrdf(const std::string& text);  // std::invalid_argument naming --brdf

// The fixed exposure that shows the seeds' unitless lights (the built-in scenes' generated
// lights, intensity 1) as bright under `brdf` as Blinn-Phong at exposure 1 did: glTF's Lambert
// divides by pi and the Blinn-Phong mapping never did, so the same light on a white surface gives
// I / (pi d^2) under GGX and I / d^2 under Blinn-Phong. pi for GGX (EV log2(pi) = 1.65), 1 for
// Blinn-Phong. The built-in scenes' default exposure, and the divisor of their ambient fill, which
// has no 1/pi under either BRDF and would otherwise come out pi times brighter against the lights
// (app/frame_options.h, defaultLook; the tests' setLightModel).
float unitlessLightExposure(Brdf brdf);

// The falloff of point and spot lights (glsl/include/shading.glsl, lightFalloff).
enum class Falloff : std::uint32_t {
    Smooth = ML_FALLOFF_SMOOTH,             // saturate(1 - (d/r)^4)^2 / (d^2 + 1): radii from --light-radius / overlap:K
    Gltf = ML_FALLOFF_GLTF,                 // --light-cutoff E, --cutoff hard: glTF's window at the range or cut-off radius
    Stochastic = ML_FALLOFF_STOCHASTIC,     // --light-cutoff E, --cutoff stochastic: ranges drawn by Russian roulette
    Untruncated = ML_FALLOFF_UNTRUNCATED,   // --cutoff none: pure inverse square, every light everywhere (naive only)
};
const char* falloffName(Falloff falloff);

struct LightModel {
    Brdf brdf = Brdf::Ggx;
    Falloff falloff = Falloff::Smooth;
    // --light-cutoff E: a light's unwindowed contribution max(colour) / d^2 falls to E at its
    // cut-off radius; 0 when not given.
    float cutoff = 0.0f;
};

// What the shading programs compile in of the frame's light model: the BRDF, its specular term
// (--specular) and the falloff (ML_BRDF_GGX, ML_SPECULAR, ML_FALLOFF; glsl/include/frame_uniforms.glsl).
// Branches on the frame's uniforms inside every (point, light) pair cost the H200's lighting pass
// 9 % (docs/bench/nvidia-h200/light-terms/); the cut-off E stays a uniform.
struct ShadingSwitches {
    Brdf brdf = Brdf::Ggx;
    bool specular = true;
    Falloff falloff = Falloff::Smooth;
    bool shadowRays = false;  // --shadows rays or sampled, where something casts a shadow
    // --shadows sampled: rays a pixel in the compute lighting (ML_SHADOW_SAMPLES; sampled_shadows.h), 0 otherwise
    std::uint32_t shadowSamples = 0;
    bool countShadowRays = false;  // and every ray counted (ML_COUNT_SHADOW_RAYS; FrameRenderer::countShadowRays)
    std::uint32_t shadowBvhWidth = kDefaultShadowBvhWidth;  // the BVH's children a node (ML_SHADOW_BVH_WIDTH; shadow_bvh.h)
    bool operator==(const ShadingSwitches&) const = default;
};

// The distance at which max(colour) / d^2 falls to `cutoff`: sqrt(max(colour) / cutoff).
float cutoffRadius(const glm::vec3& color, float cutoff);
// Every point and spot light's radius set to its cut-off radius (--light-cutoff on generated lights).
void applyCutoffRadii(std::vector<Light>& lights, float cutoff);

// Stochastic light culling (Tokuyoshi and Harada, JCGT 5(1), 2016): light `index` reaches as far
// as r = cutoffRadius / sqrt(xi) this draw, xi uniform in (0, 1] from the draw's seed; a point
// at distance d sees its inverse square times glTF's window 1 - (d/r)^4, divided by that window's
// mean over the draws (glsl/include/shading.glsl), so the expected contribution is the
// untruncated max(colour) / d^2, and each draw's falloff is continuous and zero at r. A point
// past the cut-off radius is reached with probability (cutoffRadius / d)^2 and sees at most
// 1.5 E there. Mirrors glsl/animate_lights.comp.
float stochasticRadius(const glm::vec3& color, float cutoff, std::uint32_t index, std::uint32_t drawSeed);
// The seed of a frame's draw: frame index and draw number (render --accumulate) hashed together,
// so every frame and every accumulated draw is reproducible alone.
std::uint32_t stochasticDrawSeed(std::uint32_t frameIndex, std::uint32_t draw);

}  // namespace ml
