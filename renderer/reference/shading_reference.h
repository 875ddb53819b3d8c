// CPU mirror of glsl/include/shading.glsl, for tests that check the GPU against the formula.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/lights/light_model.h"
#include "renderer/lights/light_set.h"

namespace ml {

// The falloff of a light of radius r and brightest channel `intensity` at `distance`, in the
// model's falloff mode (glsl/include/shading.glsl); the seeds' smooth one by default.
float lightFalloff(float distance, float radius, float intensity = 1.0f, const LightModel& model = {});
// The same at squared distance d2, as the shader computes it (no square root per light).
float lightFalloffAtSquaredDistance(float d2, float radius, float intensity = 1.0f, const LightModel& model = {});
// The stochastic cut-off's window 1 - (d/r)^4 averaged over the drawn ranges r, at squared
// distance d2 (shading.glsl).
float stochasticAcceptance(float d2, float intensity, float cutoff);

// glTF's angular attenuation of a spot (KHR_lights_punctual): saturate((cos - cosOuter) /
// (cosInner - cosOuter))^2, exactly 0 at and outside the outer cone, 1 inside the inner.
float spotAttenuation(float cosToAxis, float cosInner, float cosOuter);

// A material's parameters at one surface point, after its textures (docs/lights-and-shading.md).
struct SurfaceSample {
    glm::vec3 position;
    glm::vec3 normal;     // unit length, after any normal map
    glm::vec3 baseColor;  // linear
    float metallic = 0.0f;
    float roughness = 0.5f;
    float occlusion = 1.0f;       // ambient only
    glm::vec3 emissive{0.0f};     // added as is; lights nothing else
    // KHR_materials_ior x KHR_materials_specular: the dielectric's F0 colour, min(((ior - 1) /
    // (ior + 1))^2 x specular colour, 1), and the specular weight (glTF's defaults: 0.04 and 1).
    glm::vec3 specularF0{0.04f};
    float specularWeight = 1.0f;
    bool unlit = false;           // KHR_materials_unlit: the base colour, lit by nothing
    // KHR_materials_clearcoat: the coat's weight (0: none), roughness and unit normal.
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    glm::vec3 clearcoatNormal{0.0f, 0.0f, 1.0f};
    // KHR_materials_sheen: the sheen's linear colour (0: none) and roughness.
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    // KHR_materials_anisotropy: the strength (0: the isotropic lobe), the unit direction T and
    // B_a = normalize(Ng x T) (anisotropyDirections).
    float anisotropyStrength = 0.0f;
    glm::vec3 anisotropyT{1.0f, 0.0f, 0.0f};
    glm::vec3 anisotropyB{0.0f, 1.0f, 0.0f};
    // KHR_materials_iridescence: the film's strength (0: none), thickness (nm; 0: none) and IOR.
    float iridescence = 0.0f;
    float iridescenceThickness = 0.0f;
    float iridescenceIor = 1.3f;
    // KHR_materials_transmission and KHR_materials_volume: the transmission (0: opaque), the
    // volume's thickness (0: thin-walled), attenuation distance (0: infinite) and colour, and the
    // opaque scene's radiance seen through the surface (the transparent pass's B).
    float transmission = 0.0f;
    float thickness = 0.0f;
    float attenuationDistance = 0.0f;
    glm::vec3 attenuationColor{1.0f};
    glm::vec3 behind{0.0f};
};

// The metallic-roughness material's terms, shared by every method.
struct ShadingTerms {
    glm::vec3 diffuse;   // baseColor * (1 - metallic)
    glm::vec3 f0;        // mix(0.04, baseColor, metallic)
    float alpha;         // GGX: roughness^2, at least ML_GGX_MIN_ALPHA
    glm::vec3 specular;  // Blinn-Phong: f0 * (shininess + 8) / 8
    float shininess;     // Blinn-Phong: 2 / alpha^2 - 2, alpha = roughness^2, clamped to [1, 8192]
    float f90 = 1.0f;              // mix(specularWeight, 1, metallic)
    glm::vec3 f0Diffuse{0.04f};    // mix(specularWeight max(specularF0), baseColor, metallic): the diffuse's Fresnel
    // KHR_materials_anisotropy: the strength (0: isotropic), alpha_t = mix(alpha, 1, strength^2), T, B_a.
    float anisotropyStrength = 0.0f;
    float alphaT = 0.0f;
    glm::vec3 anisotropyT{1.0f, 0.0f, 0.0f};
    glm::vec3 anisotropyB{0.0f, 1.0f, 0.0f};
    // KHR_materials_transmission: transmission x baseColor (1 - metallic), which diffuse gave up.
    glm::vec3 transmitted{0.0f};
};
ShadingTerms shadingTerms(const glm::vec3& baseColor, float metallic, float roughness);
// The same with KHR_materials_ior / KHR_materials_specular (glsl/include/shading.glsl has the formulas).
ShadingTerms shadingTerms(const SurfaceSample& s);

// glTF's BRDF (specification, appendix B) for unit normal n, view v and light l with N.L > 0:
// (1 - Fd) diffuse / pi + F D Vis, Vis the height-correlated Smith term, Fd = F but where
// KHR_materials_specular colours F0 (glsl/include/shading.glsl has the formulas).
glm::vec3 ggxBrdf(const ShadingTerms& t, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l);

// KHR_materials_anisotropy's directions at a point of geometric normal ng (unit) and tangent
// (xyz, w the bitangent's sign), as glsl/include/material.glsl makes them: the map's direction
// (`mapDirection`, RG in [-1, 1]; (1, 0) without a map) normalized, turned by `rotation` radians
// counter-clockwise in the tangent frame, T = normalize(t x + b y) and B_a = normalize(ng x T).
// False (and nothing set) where the tangent lies along ng.
bool anisotropyDirections(const glm::vec3& ng, const glm::vec4& tangent, glm::vec2 mapDirection, float rotation, glm::vec3& t,
                          glm::vec3& b);

// KHR_materials_clearcoat's layer weight k = clearcoat (0.04 + 0.96 (1 - |V.Nc|)^5) and its lobe
// (GGX's D Vis at the coat's alpha and normal, no Fresnel) for unit v and l with Nc.L > 0.
float clearcoatLayerWeight(const SurfaceSample& s, const glm::vec3& v);
float clearcoatGgx(const SurfaceSample& s, const glm::vec3& v, const glm::vec3& l);

// KHR_materials_sheen (glsl/include/shading.glsl has the formulas): the lobe's directional albedo E
// at cosine mu by Conty Estevez and Kulla's fit, and the Charlie lobe D V times N.L for unit n, v, l
// with N.L = nDotL > 0 and N.V = nDotV (floored), alpha_s = max(roughness, 0.07)^2.
float sheenAlbedo(float mu, float sheenRoughness);
float sheenCharlieTimesNDotL(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, float nDotL, float nDotV,
                             float sheenRoughness);

// KHR_materials_iridescence (glsl/include/shading.glsl has the formulas): the film's Fresnel F_i at
// cosine cosTheta1 from air, over a base of normal-incidence reflectance f0.
glm::vec3 iridescentFresnel(float cosTheta1, float filmIor, float thicknessNm, const glm::vec3& f0);

// KHR_materials_volume's tint over the thickness, Beer's law: c_a^(d / d_a) (1 where d or d_a is 0).
glm::vec3 volumeTint(const SurfaceSample& s);

// The linear radiance the shaders compute for a surface point seen from `eye`, from lights of
// every type (glsl/include/shading.glsl and sun_lights.glsl), in the given light model; without
// `specular` the BRDF's specular term is left out (--specular off).
glm::vec3 shadeReference(const SurfaceSample& s, const glm::vec3& eye, const std::vector<Light>& lights, float ambient,
                         bool specular = true, const LightModel& model = {});

}  // namespace ml
