#include "renderer/reference/shading_reference.h"

#include <algorithm>
#include <cmath>

namespace ml {

namespace {
constexpr float kPi = 3.14159265358979f;

// GGX's D * Vis (height-correlated Smith) for unit n, v, l with N.L > 0 and alpha^2 = a2.
float ggxDistributionVisibility(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, float a2) {
    const glm::vec3 h = glm::normalize(l + v);
    const float nDotL = glm::dot(n, l);
    const float nDotV = std::abs(glm::dot(n, v));
    const float nDotH = std::max(glm::dot(n, h), 0.0f);
    const glm::vec3 nCrossH = glm::cross(n, h);
    const float dDenominator = glm::dot(nCrossH, nCrossH) + nDotH * nDotH * a2;
    const float visibilityDenominator =
        nDotL * std::sqrt(nDotV * nDotV * (1.0f - a2) + a2) + nDotV * std::sqrt(nDotL * nDotL * (1.0f - a2) + a2);
    return (0.5f / kPi) * a2 / (dDenominator * dDenominator * visibilityDenominator);
}

// KHR_materials_anisotropy's D * Vis (glsl/include/shading.glsl has the formulas).
float anisotropicGgxDistributionVisibility(const ShadingTerms& t, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const glm::vec3 h = glm::normalize(l + v);
    const float nDotL = glm::dot(n, l);
    const float nDotV = std::abs(glm::dot(n, v));
    const float nDotH = std::max(glm::dot(n, h), 0.0f);
    const float at = t.alphaT, ab = t.alpha, a2 = at * ab;
    const glm::vec3 f(ab * glm::dot(t.anisotropyT, h), at * glm::dot(t.anisotropyB, h), a2 * nDotH);
    const float w2 = a2 / glm::dot(f, f);
    const float distribution = a2 * w2 * w2 * (1.0f / kPi);
    const float ggxV = nDotL * glm::length(glm::vec3(at * glm::dot(t.anisotropyT, v), ab * glm::dot(t.anisotropyB, v), nDotV));
    const float ggxL = nDotV * glm::length(glm::vec3(at * glm::dot(t.anisotropyT, l), ab * glm::dot(t.anisotropyB, l), nDotL));
    return distribution * std::min(0.5f / (ggxV + ggxL), 1.0f);
}

float blinnPhongShininess(float alpha) { return std::clamp(2.0f / std::max(alpha * alpha, 1e-6f) - 2.0f, 1.0f, 8192.0f); }

}  // namespace

float stochasticAcceptance(float d2, float intensity, float cutoff) {
    const float u = d2 * cutoff / intensity;
    return u <= 1.0f ? 1.0f - u * u / 3.0f : 2.0f / (3.0f * u);
}

float lightFalloffAtSquaredDistance(float d2, float radius, float intensity, const LightModel& model) {
    constexpr float kMinDistance2 = static_cast<float>(ML_LIGHT_MIN_DISTANCE) * static_cast<float>(ML_LIGHT_MIN_DISTANCE);
    if (model.falloff == Falloff::Untruncated) return 1.0f / std::max(d2, kMinDistance2);
    const float r2 = radius * radius;
    if (d2 >= r2) return 0.0f;
    const float x2 = d2 / r2;
    const float w = std::clamp(1.0f - x2 * x2, 0.0f, 1.0f);
    if (model.falloff == Falloff::Smooth) return (w * w) / (d2 + 1.0f);
    const float inverseSquare = 1.0f / std::max(d2, kMinDistance2);
    if (model.falloff == Falloff::Gltf) return w * inverseSquare;
    return w * inverseSquare / stochasticAcceptance(d2, intensity, model.cutoff);
}

float lightFalloff(float d, float radius, float intensity, const LightModel& model) {
    return lightFalloffAtSquaredDistance(d * d, radius, intensity, model);
}

float spotAttenuation(float cosToAxis, float cosInner, float cosOuter) {
    if (cosToAxis <= cosOuter) return 0.0f;
    if (cosToAxis >= cosInner) return 1.0f;
    const float t = (cosToAxis - cosOuter) / (cosInner - cosOuter);
    return t * t;
}

ShadingTerms shadingTerms(const glm::vec3& baseColor, float metallic, float roughness) {
    ShadingTerms t;
    const float m = std::clamp(metallic, 0.0f, 1.0f);
    const float alpha = std::clamp(roughness, 0.0f, 1.0f) * std::clamp(roughness, 0.0f, 1.0f);
    t.shininess = blinnPhongShininess(alpha);
    t.alpha = std::max(alpha, static_cast<float>(ML_GGX_MIN_ALPHA));
    t.diffuse = baseColor * (1.0f - m);
    t.f0 = glm::mix(glm::vec3(0.04f), baseColor, m);
    t.specular = t.f0 * ((t.shininess + 8.0f) / 8.0f);
    t.f0Diffuse = t.f0;
    return t;
}

ShadingTerms shadingTerms(const SurfaceSample& s) {
    ShadingTerms t = shadingTerms(s.baseColor, s.metallic, s.roughness);
    const float m = std::clamp(s.metallic, 0.0f, 1.0f);
    const glm::vec3 dielectricF0 = s.specularF0 * s.specularWeight;
    t.f0 = glm::mix(dielectricF0, s.baseColor, m);
    t.f90 = s.specularWeight + m * (1.0f - s.specularWeight);
    t.f0Diffuse = glm::mix(glm::vec3(std::max({dielectricF0.r, dielectricF0.g, dielectricF0.b})), s.baseColor, m);
    t.specular = t.f0 * ((t.shininess + 8.0f) / 8.0f);
    t.anisotropyStrength = std::clamp(s.anisotropyStrength, 0.0f, 1.0f);
    t.alphaT = t.alpha + (1.0f - t.alpha) * (t.anisotropyStrength * t.anisotropyStrength);
    t.anisotropyT = s.anisotropyT;
    t.anisotropyB = s.anisotropyB;
    const float transmission = std::clamp(s.transmission, 0.0f, 1.0f);
    t.transmitted = t.diffuse * transmission;
    t.diffuse *= 1.0f - transmission;
    return t;
}

glm::vec3 volumeTint(const SurfaceSample& s) {
    if (!(s.attenuationDistance > 0.0f) || !(s.thickness > 0.0f)) return glm::vec3(1.0f);
    return glm::pow(s.attenuationColor, glm::vec3(s.thickness / s.attenuationDistance));
}

bool anisotropyDirections(const glm::vec3& ng, const glm::vec4& tangent, glm::vec2 mapDirection, float rotation, glm::vec3& t,
                          glm::vec3& b) {
    glm::vec2 direction(1.0f, 0.0f);
    if (glm::dot(mapDirection, mapDirection) > 1e-16f) direction = glm::normalize(mapDirection);
    const float c = std::cos(rotation), s = std::sin(rotation);
    direction = glm::vec2(c * direction.x - s * direction.y, s * direction.x + c * direction.y);
    glm::vec3 frameT = glm::vec3(tangent) - ng * glm::dot(ng, glm::vec3(tangent));
    if (!(glm::dot(frameT, frameT) > 1e-16f)) return false;
    frameT = glm::normalize(frameT);
    const glm::vec3 frameB = glm::cross(ng, frameT) * (tangent.w < 0.0f ? -1.0f : 1.0f);
    t = glm::normalize(frameT * direction.x + frameB * direction.y);
    b = glm::normalize(glm::cross(ng, t));
    return true;
}

glm::vec3 ggxBrdf(const ShadingTerms& t, const glm::vec3& n, const glm::vec3& v, const glm::vec3& l) {
    const glm::vec3 h = glm::normalize(l + v);
    const float vDotH = std::abs(glm::dot(v, h));
    const float q5 = std::pow(1.0f - vDotH, 5.0f);
    const glm::vec3 fresnel = t.f0 + (t.f90 - t.f0) * q5;
    const glm::vec3 diffuseFresnel = t.f0Diffuse + (t.f90 - t.f0Diffuse) * q5;
    const float distributionVisibility = t.anisotropyStrength > 0.0f ? anisotropicGgxDistributionVisibility(t, n, v, l)
                                                                      : ggxDistributionVisibility(n, v, l, t.alpha * t.alpha);
    const glm::vec3 diffuseOverPi = t.diffuse * (1.0f / kPi);
    return diffuseOverPi + fresnel * (distributionVisibility - diffuseOverPi) + (fresnel - diffuseFresnel) * diffuseOverPi;
}

glm::vec3 iridescentFresnel(float cosTheta1, float filmIor, float thicknessNm, const glm::vec3& f0) {
    const float eta = filmIor;
    const float cosTheta2 = std::sqrt(1.0f - (1.0f - cosTheta1 * cosTheta1) / (eta * eta));
    const float r0 = (eta - 1.0f) / (eta + 1.0f);
    const float r12 = r0 * r0 + (1.0f - r0 * r0) * std::pow(1.0f - cosTheta1, 5.0f);
    const float t121 = 1.0f - r12;
    const glm::vec3 sqrtF0 = glm::sqrt(glm::min(f0 + 1e-4f, glm::vec3(0.9999f)));
    const glm::vec3 baseIor = (1.0f + sqrtF0) / (1.0f - sqrtF0);
    const glm::vec3 r1 = (baseIor - eta) / (baseIor + eta);
    const glm::vec3 r23 = r1 * r1 + (1.0f - r1 * r1) * std::pow(1.0f - cosTheta2, 5.0f);
    glm::vec3 phi(kPi);
    for (int c = 0; c < 3; ++c)
        if (baseIor[c] < eta) phi[c] += kPi;
    const float opd = 2.0f * eta * thicknessNm * cosTheta2;
    const glm::vec3 r123 = glm::clamp(r12 * r23, 1e-5f, 0.9999f);
    const glm::vec3 rs = t121 * t121 * r23 / (1.0f - r123);
    glm::vec3 reflectance = r12 + rs;
    glm::vec3 cm = rs - t121;
    // The sensitivity's Gaussian fit (Belcour and Barla), XYZ to linear Rec. 709.
    const glm::vec3 amplitude(5.4856e-13f, 4.4201e-13f, 5.2481e-13f), centre(1.6810e+06f, 1.7953e+06f, 2.2084e+06f),
        variance(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    const glm::mat3 xyzToRec709(3.2404542f, -0.9692660f, 0.0556434f, -1.5371385f, 1.8760108f, -0.2040259f, -0.4985314f, 0.0415560f,
                                1.0572252f);
    for (int m = 1; m <= 2; ++m) {
        cm *= glm::sqrt(r123);
        const float phase = static_cast<float>(m) * 2.0f * kPi * opd * 1e-9f;
        const glm::vec3 shift = static_cast<float>(m) * phi;
        glm::vec3 xyz = amplitude * glm::sqrt(2.0f * kPi * variance) * glm::cos(centre * phase + shift) * glm::exp(-phase * phase * variance);
        xyz.x += 9.7470e-14f * std::sqrt(2.0f * kPi * 4.5282e+09f) * std::cos(2.2399e+06f * phase + shift.x) *
                 std::exp(-4.5282e+09f * phase * phase);
        xyz /= 1.0685e-7f;
        reflectance += cm * 2.0f * (xyzToRec709 * xyz);
    }
    return glm::max(reflectance, glm::vec3(0.0f));
}

float clearcoatLayerWeight(const SurfaceSample& s, const glm::vec3& v) {
    return s.clearcoat * (0.04f + 0.96f * std::pow(1.0f - std::abs(glm::dot(s.clearcoatNormal, v)), 5.0f));
}

float clearcoatGgx(const SurfaceSample& s, const glm::vec3& v, const glm::vec3& l) {
    const float r = std::clamp(s.clearcoatRoughness, 0.0f, 1.0f);
    const float alpha = std::max(r * r, static_cast<float>(ML_GGX_MIN_ALPHA));
    return ggxDistributionVisibility(s.clearcoatNormal, v, l, alpha * alpha);
}

namespace {
// alpha_s's floor, as the shader's kSheenMinRoughness, and N.V's.
constexpr float kSheenMinRoughness = 0.07f;
constexpr float kSheenMinCos = 1e-4f;

float sheenRoughnessFloored(float r) { return std::max(std::clamp(r, 0.0f, 1.0f), kSheenMinRoughness); }

// The Charlie visibility's Lambda by the extension's fit, interpolated in (1 - alpha)^2.
float sheenLambdaFit(float x, float alpha) {
    const float t = (1.0f - alpha) * (1.0f - alpha);
    const auto mix = [t](float a, float b) { return a + (b - a) * t; };
    const float a = mix(21.5473f, 25.3245f), b = mix(3.82987f, 3.32435f), c = mix(0.19823f, 0.16801f);
    const float d = mix(-1.97760f, -1.27393f), e = mix(-4.32054f, -4.85967f);
    return a / (1.0f + b * std::pow(x, c)) + d * x + e;
}
float sheenLambda(float cosTheta, float alpha) {
    return cosTheta < 0.5f ? std::exp(sheenLambdaFit(cosTheta, alpha))
                           : std::exp(2.0f * sheenLambdaFit(0.5f, alpha) - sheenLambdaFit(1.0f - cosTheta, alpha));
}
}  // namespace

float sheenAlbedo(float mu, float sheenRoughness) {
    const float q = 1.0f - std::clamp(mu, 0.0f, 1.0f);
    return 0.65584461f * (q * q * q) + 1.0f / (4.16526551f + std::exp(6.33516894f - 7.97291361f * sheenRoughnessFloored(sheenRoughness)));
}

float sheenCharlieTimesNDotL(const glm::vec3& n, const glm::vec3& v, const glm::vec3& l, float nDotL, float nDotV,
                             float sheenRoughness) {
    const float r = sheenRoughnessFloored(sheenRoughness);
    const float alpha = r * r;
    const glm::vec3 nCrossH = glm::cross(n, glm::normalize(l + v));
    const float sin2h = glm::dot(nCrossH, nCrossH);
    const float distribution = (2.0f + 1.0f / alpha) * std::pow(sin2h, 0.5f / alpha) * (0.5f / kPi);
    return distribution / ((1.0f + sheenLambda(nDotV, alpha) + sheenLambda(nDotL, alpha)) * (4.0f * nDotV));
}

glm::vec3 shadeReference(const SurfaceSample& s, const glm::vec3& eye, const std::vector<Light>& lights, float ambient,
                         bool specular, const LightModel& model) {
    if (s.unlit) return s.baseColor;
    const ShadingTerms t = shadingTerms(s);
    const glm::vec3 v = glm::normalize(eye - s.position);
    // KHR_materials_clearcoat's share k (none under --specular off: the coat is a specular layer).
    const float k = specular && s.clearcoat > 0.0f ? clearcoatLayerWeight(s, v) : 0.0f;
    // KHR_materials_sheen (none under --specular off either): its largest channel and E(N.V).
    const float sheenMax = std::max({s.sheenColor.r, s.sheenColor.g, s.sheenColor.b});
    const bool sheen = specular && sheenMax > 0.0f;
    const float nDotV = std::max(std::abs(glm::dot(s.normal, v)), kSheenMinCos);
    const float viewAlbedo = sheen ? sheenAlbedo(nDotV, s.sheenRoughness) : 0.0f;
    // KHR_materials_iridescence (none under --specular off either): the film's Fresnel at a cosine,
    // over the material's f0; the ambient reflects off it at N.V.
    const bool film = specular && s.iridescence > 0.0f && s.iridescenceThickness > 0.0f;
    const auto filmFresnel = [&](float cosTheta) { return iridescentFresnel(cosTheta, s.iridescenceIor, s.iridescenceThickness, t.f0); };
    const glm::vec3 unlitF0 = film ? glm::mix(t.f0, filmFresnel(std::abs(glm::dot(s.normal, v))), s.iridescence) : t.f0;
    const glm::vec3 unlit =
        sheen ? ambient * s.occlusion * ((t.diffuse + unlitF0) * (1.0f - sheenMax * viewAlbedo) + s.sheenColor * viewAlbedo) + s.emissive
              : ambient * s.occlusion * (t.diffuse + unlitF0) + s.emissive;
    // KHR_materials_transmission: the scene behind, through the transmitted colour and 1 - f0.
    const bool transmits = s.transmission > 0.0f;
    const glm::vec3 behind = transmits ? t.transmitted * (1.0f - t.f0) * s.behind * volumeTint(s) : glm::vec3(0.0f);
    glm::vec3 color = (unlit + behind) * (1.0f - k) + ambient * s.occlusion * k;
    // A light from behind (N.L < 0) through the surface, times |N.L|: mirrored through its plane.
    const auto transmitted = [&](const glm::vec3& dir, float nDotL) {
        if (!transmits || !specular) return glm::vec3(0.0f);
        const glm::vec3 mirrored = dir - 2.0f * nDotL * s.normal;
        const glm::vec3 h = glm::normalize(mirrored + v);
        const float nDotH = std::max(glm::dot(s.normal, h), 0.0f);
        if (model.brdf != Brdf::Ggx)
            return t.transmitted * (1.0f - t.f0) * (-nDotL * (t.shininess + 8.0f) / 8.0f * std::pow(nDotH, t.shininess)) * volumeTint(s);
        const float q5 = std::pow(1.0f - std::abs(glm::dot(v, h)), 5.0f);
        const glm::vec3 fresnel = t.f0 + (t.f90 - t.f0) * q5;
        return (1.0f - fresnel) * t.transmitted * (-nDotL * ggxDistributionVisibility(s.normal, v, mirrored, t.alpha * t.alpha)) *
               volumeTint(s);
    };
    // The material's BRDF times N.L for a light from unit direction `dir`.
    const auto baseReflected = [&](const glm::vec3& dir) {
        const float nDotL = glm::dot(s.normal, dir);
        if (nDotL < 0.0f) return transmitted(dir, nDotL);
        if (nDotL <= 0.0f) return glm::vec3(0.0f);
        if (model.brdf == Brdf::Ggx) {
            if (!specular) return nDotL * (t.diffuse * (1.0f / kPi));
            if (!film) return nDotL * ggxBrdf(t, s.normal, v, dir);
            // F and the diffuse's Fd with the film's Fresnel (and its largest channel) mixed in.
            const glm::vec3 h = glm::normalize(dir + v);
            const float q5 = std::pow(1.0f - std::abs(glm::dot(v, h)), 5.0f);
            const glm::vec3 iridescent = filmFresnel(std::abs(glm::dot(v, h)));
            const glm::vec3 fresnel = glm::mix(t.f0 + (t.f90 - t.f0) * q5, iridescent, s.iridescence);
            const glm::vec3 diffuseFresnel = glm::mix(t.f0Diffuse + (t.f90 - t.f0Diffuse) * q5,
                                                      glm::vec3(std::max({iridescent.r, iridescent.g, iridescent.b})), s.iridescence);
            const float distributionVisibility = ggxDistributionVisibility(s.normal, v, dir, t.alpha * t.alpha);
            return nDotL * ((1.0f - diffuseFresnel) * t.diffuse * (1.0f / kPi) + fresnel * distributionVisibility);
        }
        if (!specular) return nDotL * t.diffuse;
        const glm::vec3 h = glm::normalize(dir + v);
        const float spec = std::pow(std::max(glm::dot(s.normal, h), 0.0f), t.shininess);
        if (film)
            return nDotL * (t.diffuse + glm::mix(t.f0, filmFresnel(std::abs(glm::dot(v, h))), s.iridescence) *
                                            ((t.shininess + 8.0f) / 8.0f) * spec);
        return nDotL * (t.diffuse + t.specular * spec);
    };
    // ...under the sheen, where there is one: its lobe (pi times it under Blinn-Phong, whose f is
    // pi times a physical BRDF) over the material, dimmed by the albedo scaling.
    const auto reflected = [&](const glm::vec3& dir) {
        const float nDotL = glm::dot(s.normal, dir);
        if (!sheen || nDotL <= 0.0f) return baseReflected(dir);
        const float scaling = std::min(1.0f - sheenMax * viewAlbedo, 1.0f - sheenMax * sheenAlbedo(nDotL, s.sheenRoughness));
        glm::vec3 lobe = s.sheenColor * sheenCharlieTimesNDotL(s.normal, v, dir, nDotL, nDotV, s.sheenRoughness);
        if (model.brdf != Brdf::Ggx) lobe *= kPi;
        return lobe + baseReflected(dir) * scaling;
    };
    // The coat's lobe times Nc.L.
    const auto coatReflected = [&](const glm::vec3& dir) {
        const float coatNDotL = glm::dot(s.clearcoatNormal, dir);
        if (coatNDotL <= 0.0f) return 0.0f;
        if (model.brdf == Brdf::Ggx) return coatNDotL * clearcoatGgx(s, v, dir);
        const float r = std::clamp(s.clearcoatRoughness, 0.0f, 1.0f);
        const float shininess = blinnPhongShininess(r * r);
        const glm::vec3 h = glm::normalize(dir + v);
        return coatNDotL * (shininess + 8.0f) / 8.0f * std::pow(std::max(glm::dot(s.clearcoatNormal, h), 0.0f), shininess);
    };
    // A light of colour c from unit direction `dir`, weighted by its falloff and cone.
    const auto incoming = [&](const glm::vec3& dir, const glm::vec3& c, float weight) {
        if (k == 0.0f) return c * weight * reflected(dir);
        return c * weight * (reflected(dir) * (1.0f - k) + coatReflected(dir) * k);
    };
    // Directional lights first, as the shaders add them to the unlit terms (sun_lights.glsl).
    for (const Light& l : lights)
        if (l.type == LightType::Directional) color += incoming(-glm::normalize(l.direction), l.color, 1.0f);
    for (const Light& l : lights) {
        if (l.type == LightType::Directional) continue;
        const glm::vec3 toLight = l.position - s.position;
        const float d2 = glm::dot(toLight, toLight);
        float falloff = lightFalloffAtSquaredDistance(d2, l.radius, std::max({l.color.r, l.color.g, l.color.b}), model);
        if (falloff <= 0.0f) continue;
        const glm::vec3 dir = toLight * (1.0f / std::sqrt(std::max(d2, 1e-12f)));
        if (l.type == LightType::Spot) {
            falloff *= spotAttenuation(glm::dot(-dir, glm::normalize(l.direction)), std::cos(l.innerConeAngle),
                                       std::cos(l.outerConeAngle));
            if (falloff <= 0.0f) continue;
        }
        color += incoming(dir, l.color, falloff);
    }
    return color;
}

}  // namespace ml
