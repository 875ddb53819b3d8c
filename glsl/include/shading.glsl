// The shading model shared by every method (docs/lights-and-shading.md), mirrored on the CPU by
// renderer/reference/shading_reference.cpp. A glTF metallic-roughness material gives
//   diffuse = base * (1 - metallic)        f0 = mix(0.04, base, metallic)      alpha = roughness^2
//   L_out = ambient * occlusion * (diffuse + f0) + emissive + sum over lights of  color * falloff * max(N.L, 0) * f
// with the BRDF f chosen by --brdf (a frame uniform, the same in every method):
//   blinn-phong  f = diffuse + f0 * (s + 8) / 8 * max(N.H, 0)^s,  s = clamp(2 / alpha^2 - 2, 1, 8192)
//                (normalized Blinn-Phong without the 1/pi: a white surface facing a light of
//                intensity I at distance d shows I * falloff)
//   ggx          glTF's (specification, appendix B): alpha floored at ML_GGX_MIN_ALPHA,
//                F = f0 + (1 - f0) (1 - |V.H|)^5,  D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2),
//                Vis = 0.5 / (N.L sqrt((N.V)^2 (1 - alpha^2) + alpha^2) + |N.V| sqrt((N.L)^2 (1 - alpha^2) + alpha^2))
//                (height-correlated Smith, as Khronos' Sample Viewer, Filament and Bevy),
//                f = (1 - F) diffuse / pi + F D Vis   (a white surface shows I * falloff / pi)
// and the falloff chosen by the light model (lightFalloff below). A spot light's colour is
// further weighted by glTF's angular attenuation (KHR_lights_punctual):
//   A = saturate((cos - cosOuter) / (cosInner - cosOuter))^2,  cos = angle between its direction and -L,
// exactly zero at and outside the outer cone, so culling by the cone is as exact as by r. A
// directional light has colour c from direction -L everywhere (falloff = A = 1).
// Every falloff but the untruncated one is exactly zero at and beyond the light's radius, so
// culling a light outside it is exact. The specular term is weighted by N.L too, so shading is
// continuous at the terminator and a tiny error in a rebuilt position or normal cannot switch a
// highlight on or off. --specular off leaves it out: the diffuse term only. Emissive surfaces
// glow but light nothing else: only the scene's lights do.
//
// Where the scene has them (ML_FEATURE_*, material_features.glsl), two glTF extensions change this:
//   KHR_materials_ior, KHR_materials_specular: the dielectric's F0 is w * c, c = min(((ior - 1) /
//     (ior + 1))^2 * specularColor, 1), w the specular weight, and its F90 is w, so
//       f0 = mix(w c, base, metallic),  F = f0 + (mix(w, 1, metallic) - f0) (1 - |V.H|)^5,
//     and the diffuse is weighted by 1 - Fd, Fd the same Fresnel from f0 = mix(w max(c), base, metallic):
//     the extension's max_value(dielectric Fresnel), so a coloured F0 takes its largest channel's
//     energy from the diffuse. With c = 0.04 (ior 1.5, white) and w = 1 both are the F above, to the bit.
//   KHR_materials_unlit: the surface shows its base colour and nothing else (no ambient, no
//     emissive, no light: every light adds an exact zero).
//   KHR_materials_clearcoat: a second specular lobe of its own roughness c_r and normal Nc over all
//     of the above, layered by the coat's weight c and its Fresnel from N.V:
//       k = c (0.04 + 0.96 (1 - |V.Nc|)^5),   each light adds  (1 - k) max(N.L, 0) f + k max(Nc.L, 0) f_c
//     with f_c = D Vis at alpha_c = c_r^2 and normal Nc (GGX; under Blinn-Phong its normalized lobe
//     at the coat's shininess), and the unlit terms become (1 - k) unlit + k ambient occlusion:
//     the emissive under the coat is dimmed by it, and the ambient reflects off it. --specular off
//     leaves the coat out, lobe and layering both (k = 0).
//   KHR_materials_sheen: a micro-fibre lobe of colour c_s and roughness r_s over the material (under
//     any coat: the coat layers over sheen and material together), which it dims by its albedo
//     (the extension's albedo scaling, Conty Estevez and Kulla 2017):
//       each light adds  max(N.L, 0) (c_s D_s V_s + f s),   s = min(1 - max(c_s) E(N.V), 1 - max(c_s) E(N.L))
//     with alpha_s = max(r_s, 0.07)^2 (the Sample Viewer's floor, which keeps D's exponent at or under
//     102), D_s = (2 + 1 / alpha_s) sin(N,H)^(1 / alpha_s) / (2 pi) (Charlie),
//     V_s = 1 / ((1 + Lambda(N.V) + Lambda(N.L)) 4 N.V N.L) (Charlie, the extension's fit of Lambda),
//     N.V floored at 1e-4, and E the lobe's directional albedo by Conty Estevez and Kulla's fit
//       E(mu) = 0.65584461 (1 - mu)^3 + 1 / (4.16526551 + exp(6.33516894 - 7.97291361 sqrt(alpha_s)))
//     (a fit, not the integral: within 0.08 of the integrated E at roughness >= 0.3 and N.V >= 0.1, but
//     up to 2 below it at grazing N.V near the roughness floor, where the lobe's integral exceeds 1;
//     tests/reference/check_material_extensions.py measures it). The
//     unlit terms take the albedo scaling from N.V alone, and the ambient reflects off the sheen:
//       ambient occlusion ((diffuse + f0) (1 - max(c_s) E(N.V)) + c_s E(N.V)) + emissive.
//     Under Blinn-Phong the lobe is scaled by pi (that model's f is pi times a physical BRDF).
//     --specular off leaves the sheen out, lobe and scaling both.
//   KHR_materials_anisotropy: GGX's D and Vis stretched along a unit direction T in the surface
//     (the tangent frame's T and B turned by anisotropyRotation, after the map's RG direction) of
//     strength a (anisotropyStrength x the map's B), with B_a = normalize(Ng x T), Ng the
//     interpolated normal before any normal map (the specification's normal_geometric):
//       alpha_t = mix(alpha, 1, a^2),  alpha_b = alpha,
//       D   = 1 / (pi alpha_t alpha_b ((T.H / alpha_t)^2 + (B_a.H / alpha_b)^2 + (N.H)^2)^2),
//       Vis = min(0.5 / (N.L |(alpha_t T.V, alpha_b B_a.V, N.V)| + N.V |(alpha_t T.L, alpha_b B_a.L, N.L)|), 1)
//     (the specification's and the Sample Viewer's height-correlated anisotropic Smith, clamped as
//     they clamp it); F and the diffuse as above. Where a is 0 the isotropic D Vis above, to the
//     bit. Under Blinn-Phong the lobe stays isotropic (the extension defines GGX's).
//   KHR_materials_iridescence: a thin film of IOR eta_f >= 1 and thickness d (nm) over the
//     material (under any coat or sheen), of strength k_i. Its Fresnel F_i (Belcour and Barla 2017,
//     as the extension writes it: iridescentFresnel below) replaces F by mix(F, F_i, k_i) in GGX's
//     specular term and the diffuse's weight by 1 - mix(Fd, max(F_i), k_i) (the extension's
//     rgb_mix), F_i taken at |V.H| for each light, with F0 the material's f0 (metals: the base
//     colour; KHR_materials_specular's w c for dielectrics) as the film's base. Under Blinn-Phong F0
//     becomes mix(f0, F_i(|V.H|), k_i). The unlit terms reflect the ambient off the film at |N.V|:
//     f0 becomes mix(f0, F_i(|N.V|), k_i). A thickness of 0 is no film (F_i = F). --specular off
//     leaves it out (a specular layer).
//   KHR_materials_transmission, KHR_materials_volume: the dielectric's diffuse gives up t of itself
//     to light through the surface (t the transmission factor x map R; metals transmit nothing):
//       diffuse' = (1 - t) diffuse,  T = t base (1 - metallic),  tint = c_a^(d / d_a) (1 where d or d_a is 0)
//     A light behind the surface (N.L < 0) adds, through the extension's specular BTDF as the Sample
//     Viewer evaluates it, with L' = L - 2 (N.L) N the light mirrored through the surface's plane and
//     H' = normalize(L' + V):
//       color falloff (1 - F(|V.H'|)) T D(N.H') Vis(N.L', N.V) N.L' tint
//     (GGX at the surface's alpha; under Blinn-Phong T (1 - f0) (s + 8) / 8 (N.H')^s N.L' tint;
//     --specular off: none). The unlit terms add the opaque scene behind, B, as the Sample Viewer
//     refracts it: the frame before the glass, sampled where the refracted ray leaves the volume
//     (x + d normalize(refract(-V, N, 1 / eta)); thin-walled, d = 0: the pixel itself), at the level
//     log2(width) r clamp(2 eta - 2, 0, 1) of its mip chain (r the roughness):
//       + T (1 - f0) B tint
//     under any coat (dimmed by it), beside any sheen. Transmissive surfaces are drawn as glass
//     (the transparent pass) in every method, so B is each method's own opaque frame.

#include "include/material_features.glsl"

#ifndef ML_SPOT_LIGHTS
#define ML_SPOT_LIGHTS 1  // as in lights.glsl: spot paths compiled in unless the renderer says none
#endif
// --shadows rays: a light counts only where its shadow ray reaches it (ShadingSwitches).
#ifndef ML_SHADOW_RAYS
#define ML_SHADOW_RAYS 0
#endif
#if ML_SHADOW_RAYS
#include "include/shadow_rays.glsl"
#endif
// --shadows sampled: the program that defines ML_SHADOW_SAMPLED_LIGHTING (the compute lighting,
// deferred_lighting.comp) sums its lights unshadowed and draws ML_SHADOW_SAMPLES of them a pixel to
// trace (shadow_sampling.glsl); every other program traces the exact rays.
#if ML_SHADOW_RAYS && defined(ML_SHADOW_SAMPLED_LIGHTING)
#define ML_TRACE_EVERY_LIGHT 0
#include "include/shadow_sampling.glsl"
#define ML_OFFER_SHADOW_SAMPLE(contribution, target, key) offerShadowSample(contribution, target, key)
#else
#define ML_TRACE_EVERY_LIGHT ML_SHADOW_RAYS
#define ML_OFFER_SHADOW_SAMPLE(contribution, target, key)
#endif

const float kPi = 3.14159265358979;

// The falloff of a point or spot light of radius r and brightest channel `intensity` at squared
// distance d2, by the frame's falloff mode (bindings.h, ML_FALLOFF_*; renderer/lights/light_model.h):
//   smooth       saturate(1 - (d/r)^4)^2 / (d^2 + 1)                  zero at r
//   gltf         saturate(1 - (d/r)^4) / max(d, dmin)^2                zero at r
//   stochastic   saturate(1 - (d/r)^4) / max(d, dmin)^2 / A(d), r drawn per light and frame
//                (animate_lights.comp; Tokuyoshi and Harada 2016) and A(d) the window's mean over
//                the draws, so that the expectation is 1 / max(d, dmin)^2 (stochasticAcceptance)
//   untruncated  1 / max(d, dmin)^2 everywhere: the physical reference
// Every windowed falloff is continuous and zero at r, so a surface point rebuilt from depth a
// little off its true place is lit by a light at its edge almost as much as the true point.
// Every term is a function of d^2, so no light needs a square root for its falloff, and one beyond
// its radius (about half of those a list serves a point) costs a dot product and a compare.

// The stochastic cut-off's mean window. r = r_E / sqrt(xi), xi uniform in (0, 1], r_E where the
// light's inverse square falls to E; with u = (d / r_E)^2 the window is 1 - u^2 xi^2, whose mean
// over xi is 1 - u^2 / 3 for u <= 1 and 2 / (3 u) beyond (zero for xi > 1/u).
float stochasticAcceptance(float d2, float intensity) {
    float u = d2 * lightCutoff() / intensity;
    return u <= 1.0 ? 1.0 - u * u / 3.0 : 2.0 / (3.0 * u);
}

float lightFalloff(float d2, float radius, float intensity) {
    const float kMinDistance2 = ML_LIGHT_MIN_DISTANCE * ML_LIGHT_MIN_DISTANCE;
    uint mode = falloffMode();
    if (mode == ML_FALLOFF_UNTRUNCATED) return 1.0 / max(d2, kMinDistance2);
    float r2 = radius * radius;
    if (d2 >= r2) return 0.0;
    float x2 = d2 / r2;
    float w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    if (mode == ML_FALLOFF_SMOOTH) return (w * w) / (d2 + 1.0);
    float inverseSquare = 1.0 / max(d2, kMinDistance2);
    if (mode == ML_FALLOFF_GLTF) return w * inverseSquare;
    return w * inverseSquare / stochasticAcceptance(d2, intensity);
}

struct SurfacePoint {
    vec3 position;   // world space
    float rayDistance;  // from the eye along the pixel-centre ray to position (triangle_surface.glsl)
    vec3 normal;     // world space, unit length, after any normal map
    // The material at this point, after its textures: what the G-buffer stores.
    vec3 baseColor;  // linear
    float metallic;
    float roughness;
    float occlusion;  // ambient only
    vec3 emissive;    // linear radiance, added as is
#if ML_HAS(ML_FEATURE_SPECULAR)
    vec3 specularF0;       // KHR_materials_ior x KHR_materials_specular colour, clamped: c above
    float specularWeight;  // KHR_materials_specular: w above
#endif
#if ML_HAS(ML_FEATURE_UNLIT)
    bool unlitMaterial;    // KHR_materials_unlit
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    float clearcoat;           // KHR_materials_clearcoat: the coat's weight c (0: no coat)
    float clearcoatRoughness;  // c_r
    vec3 clearcoatNormal;      // Nc: world space, unit length, after the coat's own normal map
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    vec3 sheenColor;       // KHR_materials_sheen: c_s, linear (0: no sheen)
    float sheenRoughness;  // r_s
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    vec3 anisotropyT;          // KHR_materials_anisotropy: T, world space, unit length
    float anisotropyStrength;  // a in [0, 1] (0: the isotropic lobe)
    vec3 anisotropyB;          // B_a = normalize(Ng x T)
#endif
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    float iridescence;           // KHR_materials_iridescence: the film's strength k_i (0: no film)
    float iridescenceIor;        // eta_f
    float iridescenceThickness;  // d, nm (0: no film)
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    float transmission;          // KHR_materials_transmission: t (0: opaque)
    float thickness;             // KHR_materials_volume: d, world units (0: thin-walled)
    float attenuationDistance;   // d_a (0: infinite, no tint)
    float transmissionIor;       // eta, the refraction's
    vec3 attenuationColor;       // c_a
    vec3 behind;                 // B: the opaque scene seen through the surface (the transparent pass's)
#endif
    // Derived by deriveShadingTerms: what the light loop reads, and the unlit term, worked out
    // before the loop so that the material's inputs need not stay in registers through it.
    vec3 diffuse;
    vec3 diffuseOverPi;  // GGX's Lambert term, diffuse / pi
    vec3 f0;          // GGX
    float alpha;      // GGX: roughness^2, floored at ML_GGX_MIN_ALPHA
    vec3 specular;    // Blinn-Phong: f0 * (s + 8) / 8
    float shininess;  // Blinn-Phong
    vec3 unlit;       // ambient * occlusion * (diffuse + f0) + emissive
#if ML_HAS(ML_FEATURE_SPECULAR)
    float f90;        // GGX: mix(w, 1, metallic)
    vec3 f0Diffuse;   // GGX: mix(w max(c), base, metallic), the diffuse's Fresnel
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    float clearcoatAlpha;      // GGX: c_r^2, floored at ML_GGX_MIN_ALPHA
    float clearcoatShininess;  // Blinn-Phong
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    float sheenAlpha;          // alpha_s
    float sheenAlbedoOffset;   // E's term in alpha_s alone: 1 / (4.16526551 + exp(...))
    float sheenMax;            // max(c_s)
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    float anisotropyAlphaT;    // GGX: alpha_t = mix(alpha, 1, a^2)
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    vec3 transmitted;          // t base (1 - metallic): what the diffuse gave up to the transmission
#endif
};

#if ML_HAS(ML_FEATURE_SHEEN)
// KHR_materials_sheen's roughness floor (the Sample Viewer's): alpha_s >= 0.0049.
const float kSheenMinRoughness = 0.07;
#endif

// Blinn-Phong's exponent for GGX's alpha = roughness^2 (unfloored).
float blinnPhongShininess(float alpha) { return clamp(2.0 / max(alpha * alpha, 1e-6) - 2.0, 1.0, 8192.0); }

void deriveShadingTerms(inout SurfacePoint s) {
    float m = clamp(s.metallic, 0.0, 1.0);
    float r = clamp(s.roughness, 0.0, 1.0);
    float alpha = r * r;
    s.shininess = blinnPhongShininess(alpha);
    s.alpha = max(alpha, ML_GGX_MIN_ALPHA);
    s.diffuse = s.baseColor * (1.0 - m);
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    // The dielectric's diffuse becomes transmission by t (a metal transmits nothing); t = 0: to the bit.
    float t = clamp(s.transmission, 0.0, 1.0);
    s.transmitted = s.diffuse * t;
    s.diffuse *= 1.0 - t;
#endif
    s.diffuseOverPi = s.diffuse * (1.0 / kPi);
#if ML_HAS(ML_FEATURE_SPECULAR)
    vec3 dielectricF0 = s.specularF0 * s.specularWeight;
    s.f0 = mix(dielectricF0, s.baseColor, m);
    s.f90 = s.specularWeight + m * (1.0 - s.specularWeight);  // 1 to the bit where w is 1
    s.f0Diffuse = mix(vec3(max(dielectricF0.r, max(dielectricF0.g, dielectricF0.b))), s.baseColor, m);
#else
    s.f0 = mix(vec3(0.04), s.baseColor, m);
#endif
    s.specular = s.f0 * ((s.shininess + 8.0) / 8.0);
    s.unlit = ambientStrength() * s.occlusion * (s.diffuse + s.f0) + s.emissive;
#if ML_HAS(ML_FEATURE_UNLIT)
    if (s.unlitMaterial) s.unlit = s.baseColor;
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    float coatRoughness = clamp(s.clearcoatRoughness, 0.0, 1.0);
    s.clearcoatAlpha = max(coatRoughness * coatRoughness, ML_GGX_MIN_ALPHA);
    s.clearcoatShininess = blinnPhongShininess(coatRoughness * coatRoughness);
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    float sheenRoughness = max(clamp(s.sheenRoughness, 0.0, 1.0), kSheenMinRoughness);
    s.sheenAlpha = sheenRoughness * sheenRoughness;
    s.sheenAlbedoOffset = 1.0 / (4.16526551 + exp(6.33516894 - 7.97291361 * sheenRoughness));
    s.sheenMax = max(s.sheenColor.r, max(s.sheenColor.g, s.sheenColor.b));
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    s.anisotropyAlphaT = mix(s.alpha, 1.0, s.anisotropyStrength * s.anisotropyStrength);
#endif
}

// glTF's angular attenuation: linear in the cosine between the outer and inner cones, squared.
// Zero at and outside the outer cone, one inside the inner; an inner cone equal to the outer
// gives a hard edge (no division by zero: the middle case then never happens).
float spotAttenuation(float cosToAxis, float cosInner, float cosOuter) {
    if (cosToAxis <= cosOuter) return 0.0;
    if (cosToAxis >= cosInner) return 1.0;
    float t = (cosToAxis - cosOuter) / (cosInner - cosOuter);
    return t * t;
}

#if ML_HAS(ML_FEATURE_IRIDESCENCE)
// Does the film take part? Not where there is none (no strength or no thickness), nor under
// --specular off (a specular layer).
bool iridescent(SurfacePoint s) { return s.iridescence > 0.0 && s.iridescenceThickness > 0.0 && specularEnabled(); }

// The CIE XYZ colour matching functions' Fourier transform at phase `phase` (2 pi OPD / nm), by
// Belcour and Barla's Gaussian fit, shifted by `shift`, in linear Rec. 709 (the extension's
// evalSensitivity).
vec3 filmSensitivity(float phase, vec3 shift) {
    const vec3 amplitude = vec3(5.4856e-13, 4.4201e-13, 5.2481e-13);
    const vec3 centre = vec3(1.6810e+06, 1.7953e+06, 2.2084e+06);
    const vec3 variance = vec3(4.3278e+09, 9.3046e+09, 6.6121e+09);
    vec3 xyz = amplitude * sqrt(2.0 * kPi * variance) * cos(centre * phase + shift) * exp(-phase * phase * variance);
    xyz.x += 9.7470e-14 * sqrt(2.0 * kPi * 4.5282e+09) * cos(2.2399e+06 * phase + shift.x) * exp(-4.5282e+09 * phase * phase);
    xyz /= 1.0685e-7;
    return mat3(3.2404542, -0.9692660, 0.0556434, -1.5371385, 1.8760108, -0.2040259, -0.4985314, 0.0415560, 1.0572252) * xyz;
}

// F_i: the film's reflectance at cosine cosTheta1 from the outside (air), over a base of
// reflectance f0 at normal incidence (the extension's iridescent_fresnel; Schlick at both
// interfaces, the Airy sum's first two orders integrated over the spectrum).
vec3 iridescentFresnel(SurfacePoint s, float cosTheta1) {
    float eta = s.iridescenceIor;
    float sinTheta2Sq = (1.0 - cosTheta1 * cosTheta1) / (eta * eta);
    float cosTheta2 = sqrt(1.0 - sinTheta2Sq);  // never total reflection: eta >= 1 (the loader's rule)
    // Outside to film: R12 by Schlick; its phase is 0 (the film is denser), the way back pi.
    float r0 = (eta - 1.0) / (eta + 1.0);
    float q1 = 1.0 - cosTheta1;
    float q1Sq = q1 * q1;
    float r12 = r0 * r0 + (1.0 - r0 * r0) * (q1Sq * q1Sq * q1);
    float t121 = 1.0 - r12;
    // Film to base: the base's IOR from its F0 (guarded against F0 = 1), R23 by Schlick at theta2.
    vec3 sqrtF0 = sqrt(min(s.f0 + 1e-4, vec3(0.9999)));
    vec3 baseIor = (1.0 + sqrtF0) / (1.0 - sqrtF0);
    vec3 r1 = (baseIor - eta) / (baseIor + eta);
    float q2 = 1.0 - cosTheta2;
    float q2Sq = q2 * q2;
    vec3 r23 = r1 * r1 + (1.0 - r1 * r1) * (q2Sq * q2Sq * q2);
    vec3 phi = vec3(kPi) + mix(vec3(0.0), vec3(kPi), lessThan(baseIor, vec3(eta)));
    // The optical path difference (nm) and the Airy sum: its mean, then two orders.
    float opd = 2.0 * eta * s.iridescenceThickness * cosTheta2;
    vec3 r123 = clamp(r12 * r23, 1e-5, 0.9999);
    vec3 rs = t121 * t121 * r23 / (1.0 - r123);
    vec3 reflectance = r12 + rs;
    vec3 cm = rs - t121;
    vec3 sqrtR123 = sqrt(r123);
    for (int m = 1; m <= 2; ++m) {
        cm *= sqrtR123;
        reflectance += cm * 2.0 * filmSensitivity(float(m) * 2.0 * kPi * opd * 1e-9, float(m) * phi);
    }
    return max(reflectance, vec3(0.0));
}
#endif

// The F0 the unlit terms reflect the ambient with: the film's, at N.V, mixed in where there is one.
vec3 unlitF0(SurfacePoint s, vec3 viewDir) {
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    if (iridescent(s)) return mix(s.f0, iridescentFresnel(s, abs(dot(s.normal, viewDir))), s.iridescence);
#endif
    return s.f0;
}

// glTF's BRDF (appendix B) for unit l, v, n with N.L > 0, with the height-correlated Smith
// visibility of Khronos' Sample Viewer, Filament and Bevy (the appendix writes the separable one;
// they differ at grazing angles). 1 - (N.H)^2 as |N x H|^2: near the peak of a small alpha, the
// difference 1 - (N.H)^2 loses the bits D depends on (Filament does the same).
// GGX's D * Vis for alpha^2 = a2 (the terms as ggxBrdf names them).
float ggxDistributionVisibility(float nDotH, vec3 nCrossH, float nDotL, float nDotV, float a2) {
    float dDenominator = dot(nCrossH, nCrossH) + nDotH * nDotH * a2;  // (N.H)^2 (alpha^2 - 1) + 1
    float visibilityDenominator = nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2) + nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2);
    // D * Vis = (a2 / pi) / dDenominator^2 * 0.5 / visibilityDenominator, in one division.
    return (0.5 / kPi) * a2 / (dDenominator * dDenominator * visibilityDenominator);
}

#if ML_HAS(ML_FEATURE_ANISOTROPY)
// KHR_materials_anisotropy's D * Vis (the formulas above) for unit l, v, h.
float anisotropicGgxDistributionVisibility(SurfacePoint s, vec3 viewDir, vec3 l, vec3 h, float nDotH, float nDotL, float nDotV) {
    float at = s.anisotropyAlphaT, ab = s.alpha;
    vec3 t = s.anisotropyT, b = s.anisotropyB;
    float a2 = at * ab;
    vec3 f = vec3(ab * dot(t, h), at * dot(b, h), a2 * nDotH);
    float w2 = a2 / dot(f, f);
    float distribution = a2 * w2 * w2 * (1.0 / kPi);
    float ggxV = nDotL * length(vec3(at * dot(t, viewDir), ab * dot(b, viewDir), nDotV));
    float ggxL = nDotV * length(vec3(at * dot(t, l), ab * dot(b, l), nDotL));
    return distribution * min(0.5 / (ggxV + ggxL), 1.0);
}
#endif

vec3 ggxBrdf(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL) {
    vec3 h = normalize(l + viewDir);
    float nDotV = abs(dot(s.normal, viewDir));
    float nDotH = max(dot(s.normal, h), 0.0);
    float vDotH = abs(dot(viewDir, h));
    vec3 nCrossH = cross(s.normal, h);
    float a2 = s.alpha * s.alpha;
    float q = 1.0 - vDotH;
    float q2 = q * q;
    float q5 = q2 * q2 * q;
#if ML_HAS(ML_FEATURE_SPECULAR)
    vec3 fresnel = s.f0 + (s.f90 - s.f0) * q5;
    vec3 diffuseFresnel = s.f0Diffuse + (s.f90 - s.f0Diffuse) * q5;
#else
    vec3 fresnel = s.f0 + (1.0 - s.f0) * q5;
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    float distributionVisibility = s.anisotropyStrength > 0.0
                                       ? anisotropicGgxDistributionVisibility(s, viewDir, l, h, nDotH, nDotL, nDotV)
                                       : ggxDistributionVisibility(nDotH, nCrossH, nDotL, nDotV, a2);
#else
    float distributionVisibility = ggxDistributionVisibility(nDotH, nCrossH, nDotL, nDotV, a2);
#endif
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    if (iridescent(s)) {
        // The film's Fresnel mixed into F, and its largest channel into the diffuse's weight.
        vec3 film = iridescentFresnel(s, vDotH);
#if ML_HAS(ML_FEATURE_SPECULAR)
        vec3 plainDiffuseFresnel = diffuseFresnel;
#else
        vec3 plainDiffuseFresnel = fresnel;
#endif
        vec3 filmFresnel = mix(fresnel, film, s.iridescence);
        vec3 filmDiffuseFresnel = mix(plainDiffuseFresnel, vec3(max(film.r, max(film.g, film.b))), s.iridescence);
        return (1.0 - filmDiffuseFresnel) * s.diffuseOverPi + filmFresnel * distributionVisibility;
    }
#endif
    // (1 - F) diffuse / pi + F D Vis, as one multiply-add a channel.
#if ML_HAS(ML_FEATURE_SPECULAR)
    // (1 - Fd) diffuse / pi + F D Vis: the last term is an exact zero where Fd is F.
    return s.diffuseOverPi + fresnel * (distributionVisibility - s.diffuseOverPi) + (fresnel - diffuseFresnel) * s.diffuseOverPi;
#else
    return s.diffuseOverPi + fresnel * (distributionVisibility - s.diffuseOverPi);
#endif
}

// The frame's BRDF for a light from unit direction l with N.L = nDotL > 0.
vec3 surfaceBrdf(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL) {
    if (ggxEnabled()) return specularEnabled() ? ggxBrdf(s, viewDir, l, nDotL) : s.diffuseOverPi;
    if (!specularEnabled()) return s.diffuse;
    vec3 h = normalize(l + viewDir);
    float spec = pow(max(dot(s.normal, h), 0.0), s.shininess);
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    if (iridescent(s))
        return s.diffuse + mix(s.f0, iridescentFresnel(s, abs(dot(viewDir, h))), s.iridescence) * ((s.shininess + 8.0) / 8.0) * spec;
#endif
    return s.diffuse + s.specular * spec;
}

#if ML_HAS(ML_FEATURE_SHEEN)
// Does the sheen take part? Not where there is none, nor under --specular off (a specular layer).
bool sheened(SurfacePoint s) { return s.sheenMax > 0.0 && specularEnabled(); }

// E: the sheen lobe's directional albedo at cosine mu (Conty Estevez and Kulla's fit).
float sheenAlbedo(SurfacePoint s, float mu) {
    float q = 1.0 - clamp(mu, 0.0, 1.0);
    return 0.65584461 * (q * q * q) + s.sheenAlbedoOffset;
}

// The Charlie visibility's Lambda, by the extension's fit, interpolated in (1 - alpha_s)^2.
float sheenLambdaFit(float x, float alpha) {
    float t = (1.0 - alpha) * (1.0 - alpha);
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c = mix(0.19823, 0.16801, t);
    float d = mix(-1.97760, -1.27393, t);
    float e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(x, c)) + d * x + e;
}
float sheenLambda(float cosTheta, float alpha) {
    return cosTheta < 0.5 ? exp(sheenLambdaFit(cosTheta, alpha))
                          : exp(2.0 * sheenLambdaFit(0.5, alpha) - sheenLambdaFit(1.0 - cosTheta, alpha));
}

// The sheen lobe D_s V_s times N.L (the N.L of V_s cancelled, so that a grazing light stays finite).
float sheenLobeTimesNDotL(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL, float nDotV) {
    vec3 nCrossH = cross(s.normal, normalize(l + viewDir));
    float sin2h = dot(nCrossH, nCrossH);  // 1 - (N.H)^2, as GGX takes it
    float inverseAlpha = 1.0 / s.sheenAlpha;
    float distribution = (2.0 + inverseAlpha) * pow(sin2h, 0.5 * inverseAlpha) * (0.5 / kPi);
    return distribution / ((1.0 + sheenLambda(nDotV, s.sheenAlpha) + sheenLambda(nDotL, s.sheenAlpha)) * (4.0 * nDotV));
}

// The sheen over the material for a light with N.L = nDotL > 0, times N.L.
vec3 sheenReflected(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL) {
    float nDotV = max(abs(dot(s.normal, viewDir)), 1e-4);
    float scaling = min(1.0 - s.sheenMax * sheenAlbedo(s, nDotV), 1.0 - s.sheenMax * sheenAlbedo(s, nDotL));
    vec3 sheen = s.sheenColor * sheenLobeTimesNDotL(s, viewDir, l, nDotL, nDotV);
    if (!ggxEnabled()) sheen *= kPi;
    return sheen + nDotL * surfaceBrdf(s, viewDir, l, nDotL) * scaling;
}

// The unlit terms under the sheen: the ambient dimmed by E(N.V), and reflected off the sheen.
vec3 sheenUnlit(SurfacePoint s, vec3 viewDir) {
    float albedo = sheenAlbedo(s, max(abs(dot(s.normal, viewDir)), 1e-4));
    return ambientStrength() * s.occlusion * ((s.diffuse + unlitF0(s, viewDir)) * (1.0 - s.sheenMax * albedo) + s.sheenColor * albedo) + s.emissive;
}
#endif

#if ML_HAS(ML_FEATURE_TRANSMISSION)
// Does light pass through? Not where there is none. (Under --specular off the lights behind add
// nothing, transmittedLight says so, but the scene behind still shows through.)
bool transmissive(SurfacePoint s) { return s.transmission > 0.0; }

// Beer's law over the volume's thickness: c_a^(d / d_a); 1 where thin-walled or untinted.
vec3 volumeTint(SurfacePoint s) {
    if (!(s.attenuationDistance > 0.0) || !(s.thickness > 0.0)) return vec3(1.0);
    return pow(s.attenuationColor, vec3(s.thickness / s.attenuationDistance));
}

// A light from behind the surface (N.L = nDotL < 0) through it, times |N.L|: the extension's
// specular BTDF as the Sample Viewer evaluates it, GGX's D Vis at the light mirrored through the
// surface's plane (so N.L' = -N.L), weighted by 1 - F and the transmitted colour, tinted by the
// volume. Under Blinn-Phong the normalized lobe at the mirrored light's half vector.
vec3 transmittedLight(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL) {
    if (!specularEnabled()) return vec3(0.0);
    vec3 mirrored = l - 2.0 * nDotL * s.normal;
    float nDotM = -nDotL;
    vec3 h = normalize(mirrored + viewDir);
    float nDotH = max(dot(s.normal, h), 0.0);
    if (!ggxEnabled())
        return s.transmitted * (1.0 - s.f0) * (nDotM * (s.shininess + 8.0) / 8.0 * pow(nDotH, s.shininess)) * volumeTint(s);
    float nDotV = abs(dot(s.normal, viewDir));
    float q = 1.0 - abs(dot(viewDir, h));
    float q2 = q * q;
#if ML_HAS(ML_FEATURE_SPECULAR)
    vec3 fresnel = s.f0 + (s.f90 - s.f0) * (q2 * q2 * q);
#else
    vec3 fresnel = s.f0 + (1.0 - s.f0) * (q2 * q2 * q);
#endif
    float lobe = ggxDistributionVisibility(nDotH, cross(s.normal, h), nDotM, nDotV, s.alpha * s.alpha);
    return (1.0 - fresnel) * s.transmitted * (nDotM * lobe) * volumeTint(s);
}

// The opaque scene behind, as it reaches the eye through the surface: B times the transmitted
// colour, 1 - f0 (the ambient's Fresnel) and the volume's tint.
vec3 transmittedBehind(SurfacePoint s) { return s.transmitted * (1.0 - s.f0) * s.behind * volumeTint(s); }
#endif

// The material under any coat for a light with N.L = nDotL > 0, times N.L: under a sheen where
// there is one.
vec3 underCoatReflected(SurfacePoint s, vec3 viewDir, vec3 l, float nDotL) {
#if ML_HAS(ML_FEATURE_SHEEN)
    if (sheened(s)) return sheenReflected(s, viewDir, l, nDotL);
#endif
    return nDotL * surfaceBrdf(s, viewDir, l, nDotL);
}

#if ML_HAS(ML_FEATURE_CLEARCOAT)
// Does the coat take part? Not where there is none, nor under --specular off (a specular layer).
bool coated(SurfacePoint s) { return s.clearcoat > 0.0 && specularEnabled(); }

// k: the coat's share, its weight times its Fresnel from Nc.V (IOR 1.5).
float clearcoatLayerWeight(SurfacePoint s, vec3 viewDir) {
    float q = 1.0 - abs(dot(s.clearcoatNormal, viewDir));
    float q2 = q * q;
    return s.clearcoat * (0.04 + 0.96 * (q2 * q2 * q));
}

// The coat's lobe for unit l with Nc.L = coatNDotL > 0, Fresnel left to the layering.
float clearcoatBrdf(SurfacePoint s, vec3 viewDir, vec3 l, float coatNDotL) {
    vec3 h = normalize(l + viewDir);
    float nDotH = max(dot(s.clearcoatNormal, h), 0.0);
    if (!ggxEnabled()) return (s.clearcoatShininess + 8.0) / 8.0 * pow(nDotH, s.clearcoatShininess);
    float a2 = s.clearcoatAlpha * s.clearcoatAlpha;
    return ggxDistributionVisibility(nDotH, cross(s.clearcoatNormal, h), coatNDotL, abs(dot(s.clearcoatNormal, viewDir)), a2);
}

// A light through the coat: each lobe with its own normal's cosine, layered by k.
vec3 shadeCoated(SurfacePoint s, vec3 viewDir, vec3 l, vec3 color, float weight, float nDotL) {
    float coatNDotL = dot(s.clearcoatNormal, l);
    vec3 base = nDotL > 0.0 ? underCoatReflected(s, viewDir, l, nDotL) : vec3(0.0);
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    if (nDotL < 0.0 && transmissive(s)) base = transmittedLight(s, viewDir, l, nDotL);
#endif
    if (base == vec3(0.0) && coatNDotL <= 0.0) return vec3(0.0);
    float k = clearcoatLayerWeight(s, viewDir);
    float coat = coatNDotL > 0.0 ? coatNDotL * clearcoatBrdf(s, viewDir, l, coatNDotL) : 0.0;
    return color * weight * (base * (1.0 - k) + coat * k);
}
#endif

// A light of colour `color` arriving from unit direction l, weighted by its falloff (and cone),
// through the frame's BRDF.
vec3 shadeIncoming(SurfacePoint s, vec3 viewDir, vec3 l, vec3 color, float weight) {
    float nDotL = dot(s.normal, l);
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    if (coated(s)) return shadeCoated(s, viewDir, l, color, weight, nDotL);  // never unlit (the loader's rule)
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    if (nDotL < 0.0 && transmissive(s)) return color * weight * transmittedLight(s, viewDir, l, nDotL);  // never unlit either
#endif
    if (nDotL <= 0.0) return vec3(0.0);
#if ML_HAS(ML_FEATURE_UNLIT)
    if (s.unlitMaterial) return vec3(0.0);  // lit by nothing (and so no shadow ray either)
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    if (sheened(s)) return color * weight * sheenReflected(s, viewDir, l, nDotL);  // never unlit either
#endif
    return color * (weight * nDotL) * surfaceBrdf(s, viewDir, l, nDotL);
}

// A point or spot light (include/lights.glsl's fields). A point light's cone cosines are
// ML_POINT_LIGHT_CONE_COS, and the branch on them is uniform where a scene has no spots.
vec3 shadeLight(SurfacePoint s, vec3 viewDir, vec4 positionRadius, vec4 colorCosInner, vec4 directionCosOuter) {
    vec3 toLight = positionRadius.xyz - s.position;
    float d2 = dot(toLight, toLight);
    vec3 color = colorCosInner.rgb;
    float falloff = lightFalloff(d2, positionRadius.w, max(color.r, max(color.g, color.b)));
    if (falloff <= 0.0) return vec3(0.0);
    vec3 l = toLight * inversesqrt(max(d2, 1e-12));
    if (ML_SPOT_LIGHTS != 0 && directionCosOuter.w > -1.5) {
        falloff *= spotAttenuation(dot(-l, directionCosOuter.xyz), colorCosInner.w, directionCosOuter.w);
        if (falloff <= 0.0) return vec3(0.0);
    }
    vec3 lit = shadeIncoming(s, viewDir, l, color, falloff);
#if ML_TRACE_EVERY_LIGHT
    // Traced only for a light that adds something: the ray is the costly part.
    if (lit != vec3(0.0) && pointLightShadowed(s.position, s.normal, positionRadius.xyz)) return vec3(0.0);
#endif
    return lit;
}

// A directional light travelling along the unit `direction`: no falloff, no cone.
vec3 shadeDirectionalLight(SurfacePoint s, vec3 viewDir, vec3 direction, vec3 color) {
    vec3 lit = shadeIncoming(s, viewDir, -direction, color, 1.0);
#if ML_TRACE_EVERY_LIGHT
    if (lit != vec3(0.0) && directionalLightShadowed(s.position, s.normal, -direction)) return vec3(0.0);
#endif
    return lit;
}

// What a surface shows with no light on it: the ambient term and its own glow (under a sheen,
// the ambient dimmed by it and reflected off it; under a coat, all of it dimmed by the coat, and
// the ambient's reflection off the coat).
vec3 shadeUnlit(SurfacePoint s, vec3 viewDir) {
    vec3 unlit = s.unlit;
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    if (iridescent(s)) unlit = ambientStrength() * s.occlusion * (s.diffuse + unlitF0(s, viewDir)) + s.emissive;
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    if (sheened(s)) unlit = sheenUnlit(s, viewDir);
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    if (transmissive(s)) unlit += transmittedBehind(s);
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    if (coated(s)) {
        float k = clearcoatLayerWeight(s, viewDir);
        return unlit * (1.0 - k) + ambientStrength() * s.occlusion * k;
    }
#endif
    return unlit;
}
