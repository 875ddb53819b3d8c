// The --gbuffer layouts (gbuffer_format.h; numbered in bindings.h), chosen by the define
// ML_GBUFFER_FORMAT. Encoded by the G-buffer pass and the visibility resolve, decoded by the
// deferred lighting; position comes back from depth but in the exact layout. What is stored is the
// material at the point (shading.glsl's SurfacePoint before deriveShadingTerms). Needs
// shading.glsl and frame_uniforms.glsl.
//
//   standard       target 0 RGBA16F normal xyz, occlusion   target 1 RGBA16F base colour, metallic
//                  target 2 RGBA16F roughness, emissive rgb                                             24 B
//   packed         target 0 RGBA32UI: x octahedral normal (2 x snorm16), y base colour (sRGB-encoded
//                  RGB8) and metallic (unorm8), z roughness and occlusion (2 x unorm16),
//                  w emissive (RGB9E5, written only where the scene has emissive materials)             16 B
//   two-component  target 0 RGBA16F normal x, y, roughness, metallic   target 1 RGBA16F base colour,
//                  occlusion; no room for emissive (the renderer warns where a scene has some).        16 B
//                  z is rebuilt as +sqrt(1 - x^2 - y^2): every normal with z < 0 (world space) is mirrored
//                  to z > 0, so surfaces facing -z are lit as if they faced +z. The documented failure case.
//   exact          target 0 RGBA32F distance along the pixel's ray, octahedral normal (2 x fp32),
//                  roughness   target 1 RGBA32F base colour, metallic   target 2 RGBA32F emissive
//                  rgb, occlusion: only where the scene has emissive materials or occlusion maps,
//                  written and read only at pixels whose emissive is not zero or occlusion not one
//                  (roughness's sign bit says which; roughness is never negative). Every value as
//                  the shading computed it, and the position with it (no depth-buffer rounding):
//                  the lighting sees what naive's fragment sees.                               32-48 B
//                  Where the scene has KHR_materials_specular / ior or unlit materials, a target 3
//                  RGBA32F: the specular F0 colour rgb, the specular weight (negative: unlit),
//                  written and read only at pixels whose values are not glTF's default (metallic's
//                  sign bit says which), and target 2 with it.                                    64 B
//                  Where the scene has KHR_materials_clearcoat, a target 4 RGBA32F: the coat's
//                  weight, roughness and octahedral normal (2 x fp32), written and read only at
//                  pixels with a coat (the distance's sign bit says which), targets 2 and 3 with it. 80 B
//                  Where the scene has KHR_materials_sheen, a target 5 RGBA32F: the sheen colour rgb
//                  and roughness, written and read only at pixels with a sheen (the base colour red's
//                  sign bit says which; it is never negative), targets 2 to 4 with it.           96 B
//                  Where the scene has KHR_materials_anisotropy, a target 6 RGBA32F: the direction T
//                  times the strength a in world space, and B_a's component along N's part across
//                  T (u = T x normalize(N x T); B_a = sqrt(1 - w^2) normalize(N x T) + w u, B_a
//                  on N's side: a normal map tilts N under 90 degrees from Ng), written and read only
//                  at pixels with a > 0 (the base colour green's sign bit says which), targets 2 to 5
//                  with it.                                                                    112 B
//                  Where the scene has KHR_materials_iridescence, a target 7 RGBA32F: the film's
//                  strength, thickness (nm) and IOR, written and read only at pixels with a film
//                  (the base colour blue's sign bit says which), targets 2 to 6 with it (target 6
//                  never written nor read where the scene has no anisotropy).                  128 B
// The lossy layouts hold neither specular, unlit, clearcoat, sheen, anisotropy nor iridescence (the renderer
// warns where a scene has them).
// The lossy layouts lose what a bright many-light sum makes visible on glossy, normal-mapped
// content (docs/accuracy-and-stability.md#g-buffer-precision-on-glossy-normal-mapped-surfaces).
#include "include/material_features.glsl"
#include "include/pixel_ray.glsl"

#ifndef ML_GBUFFER_FORMAT
#define ML_GBUFFER_FORMAT ML_GBUFFER_STANDARD
#endif

// The exact layout's target 2 (emissive, occlusion) exists where the scene has either.
// Its target 3 (specular, unlit) where the scene has either; target 2 then exists too.
// Its target 4 (clearcoat) where the scene has a coat; targets 2 and 3 then exist too.
// Its target 5 (sheen) where the scene has a sheen; targets 2 to 4 then exist too.
// Its target 6 (anisotropy) where the scene has an anisotropic lobe; targets 2 to 5 then exist too.
// Its target 7 (iridescence) where the scene has a film; targets 2 to 6 then exist too.
#define ML_GBUFFER_EXACT_CLEARCOAT ML_HAS(ML_FEATURE_CLEARCOAT)
#define ML_GBUFFER_EXACT_SHEEN ML_HAS(ML_FEATURE_SHEEN)
#define ML_GBUFFER_EXACT_ANISOTROPY ML_HAS(ML_FEATURE_ANISOTROPY)
#define ML_GBUFFER_EXACT_IRIDESCENCE ML_HAS(ML_FEATURE_IRIDESCENCE)
#define ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS                                                                   \
    (ML_HAS(ML_FEATURE_SPECULAR) || ML_HAS(ML_FEATURE_UNLIT) || ML_GBUFFER_EXACT_CLEARCOAT || ML_GBUFFER_EXACT_SHEEN || \
     ML_GBUFFER_EXACT_ANISOTROPY || ML_GBUFFER_EXACT_IRIDESCENCE)
#define ML_GBUFFER_EXACT_EXTRAS (ML_HAS(ML_FEATURE_EMISSIVE) || ML_HAS(ML_FEATURE_OCCLUSION_MAP) || ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS)

#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_IRIDESCENCE
#define ML_GBUFFER_FLOAT_TARGETS 8
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_ANISOTROPY
#define ML_GBUFFER_FLOAT_TARGETS 7
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_SHEEN
#define ML_GBUFFER_FLOAT_TARGETS 6
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_CLEARCOAT
#define ML_GBUFFER_FLOAT_TARGETS 5
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS
#define ML_GBUFFER_FLOAT_TARGETS 4
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD || (ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_EXTRAS)
#define ML_GBUFFER_FLOAT_TARGETS 3
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT
#define ML_GBUFFER_FLOAT_TARGETS 2
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_TWO_COMPONENT
#define ML_GBUFFER_FLOAT_TARGETS 2
#else
#define ML_GBUFFER_FLOAT_TARGETS 0
#endif
// The float targets' image format, for passes that write them from compute.
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT
#define ML_GBUFFER_FLOAT_IMAGE rgba32f
#else
#define ML_GBUFFER_FLOAT_IMAGE rgba16f
#endif

// One pixel of the G-buffer as its targets hold it: float targets, or the one packed target.
struct GBufferTexel {
    vec4 target[8];
    uvec4 bits;  // the packed layout's one RGBA32UI texel
};

#include "include/octahedral.glsl"

// Base colour is stored sRGB-encoded in 8 bits, as 8-bit colour textures are: the steps are even
// to the eye, so dark colours do not band (linear 8 bits would put 1/255 steps into the shadows).
vec3 encodeSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 decodeSrgb(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c)); }

// RGB9E5 (GL's shared-exponent format, EXT_texture_shared_exponent): three 9-bit mantissas and a
// 5-bit exponent in 32 bits, for emissive radiance, which is HDR. Relative error under 2^-9 of
// the largest channel.
uint packRgb9e5(vec3 c) {
    const float kBias = 15.0, kMantissaBits = 9.0, kMaxValue = 65408.0;  // (511/512) * 2^16
    vec3 rc = clamp(c, 0.0, kMaxValue);
    float maxc = max(rc.r, max(rc.g, rc.b));
    float exponent = max(-kBias - 1.0, floor(log2(max(maxc, 1e-30)))) + 1.0 + kBias;
    float denom = exp2(exponent - kBias - kMantissaBits);
    if (floor(maxc / denom + 0.5) >= 512.0) {
        denom *= 2.0;
        exponent += 1.0;
    }
    uvec3 m = uvec3(min(floor(rc / denom + 0.5), vec3(511.0)));
    return m.r | (m.g << 9u) | (m.b << 18u) | (uint(exponent) << 27u);
}
vec3 unpackRgb9e5(uint v) {
    vec3 m = vec3(uvec3(v, v >> 9u, v >> 18u) & 511u);
    return m * exp2(float(v >> 27u) - 15.0 - 9.0);
}

// Does the layout hold the position (else it comes back from depth)?
#define ML_GBUFFER_STORES_POSITION (ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT)

// The stored point in world space, on the ray through window position windowPos: the surface's
// position to the bit (pixel_ray.glsl).
// The exact layout flags a pixel whose optional targets hold something in the sign bit of a value
// that is never negative, so that the pixels without (most of them) neither write nor read them:
// target 2 (emissive, occlusion) in its roughness's, target 3 (specular, unlit) in its metallic's,
// target 4 (clearcoat) in its distance's, target 5 (sheen) in its base colour red's, target 6
// (anisotropy) in its base colour green's, target 7 (iridescence) in its base colour blue's.
const uint kGBufferSignFlag = 0x80000000u;
float withoutSignFlag(float v) { return uintBitsToFloat(floatBitsToUint(v) & ~kGBufferSignFlag); }
bool signFlagged(float v) { return (floatBitsToUint(v) & kGBufferSignFlag) != 0u; }

vec3 gbufferPosition(GBufferTexel t, vec2 windowPos) { return pixelRayPoint(windowPos, withoutSignFlag(t.target[0].x)); }

// Does this pixel's target 2 hold what decodeGBuffer needs? Known from target 0 alone.
bool gbufferUsesTarget2(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT
    return signFlagged(t.target[0].w);
#else
    return ML_GBUFFER_FLOAT_TARGETS == 3;
#endif
}

// ...its target 3, known from target 1.
bool gbufferUsesTarget3(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS
    return signFlagged(t.target[1].w);
#else
    return false;
#endif
}

// ...its target 4, known from target 0.
bool gbufferUsesTarget4(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_CLEARCOAT
    return signFlagged(t.target[0].x);
#else
    return false;
#endif
}

// ...its target 7, known from target 1.
bool gbufferUsesTarget7(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_IRIDESCENCE
    return signFlagged(t.target[1].b);
#else
    return false;
#endif
}

// ...its target 5, known from target 1.
bool gbufferUsesTarget5(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_SHEEN
    return signFlagged(t.target[1].r);
#else
    return false;
#endif
}

// ...its target 6, known from target 1.
bool gbufferUsesTarget6(GBufferTexel t) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_ANISOTROPY
    return signFlagged(t.target[1].g);
#else
    return false;
#endif
}

#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT && ML_GBUFFER_EXACT_ANISOTROPY
// The frame target 6 holds B_a in: e = normalize(N x T) and u = T x e, both across T (zero where
// N is along T, which no normal map under 90 degrees from Ng makes).
void anisotropyStorageFrame(vec3 n, vec3 t, out vec3 e, out vec3 u) {
    vec3 c = cross(n, t);
    e = c * inversesqrt(max(dot(c, c), 1e-30));
    u = cross(t, e);
}
#endif

GBufferTexel encodeGBuffer(SurfacePoint s) {
    GBufferTexel t;
    t.target[0] = t.target[1] = t.target[2] = t.target[3] = t.target[4] = t.target[5] = t.target[6] = t.target[7] = vec4(0.0);
    t.bits = uvec4(0u);
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT
    uint roughnessBits = floatBitsToUint(s.roughness);
#if ML_GBUFFER_EXACT_EXTRAS
    t.target[2] = vec4(s.emissive, s.occlusion);
    if (s.emissive != vec3(0.0) || s.occlusion != 1.0) roughnessBits |= kGBufferSignFlag;
#endif
    uint distanceBits = floatBitsToUint(s.rayDistance);
#if ML_GBUFFER_EXACT_CLEARCOAT
    t.target[4] = vec4(s.clearcoat, s.clearcoatRoughness, octEncode(s.clearcoatNormal));
    if (s.clearcoat > 0.0) distanceBits |= kGBufferSignFlag;
#endif
    uint redBits = floatBitsToUint(s.baseColor.r);
#if ML_GBUFFER_EXACT_SHEEN
    t.target[5] = vec4(s.sheenColor, s.sheenRoughness);
    if (s.sheenColor != vec3(0.0)) redBits |= kGBufferSignFlag;
#endif
    uint greenBits = floatBitsToUint(s.baseColor.g);
#if ML_GBUFFER_EXACT_ANISOTROPY
    if (s.anisotropyStrength > 0.0) {
        vec3 e, u;
        anisotropyStorageFrame(s.normal, s.anisotropyT, e, u);
        t.target[6] = vec4(s.anisotropyT * s.anisotropyStrength, dot(s.anisotropyB, u));
        greenBits |= kGBufferSignFlag;
    }
#endif
    uint blueBits = floatBitsToUint(s.baseColor.b);
#if ML_GBUFFER_EXACT_IRIDESCENCE
    t.target[7] = vec4(s.iridescence, s.iridescenceThickness, s.iridescenceIor, 0.0);
    if (s.iridescence > 0.0) blueBits |= kGBufferSignFlag;
#endif
    uint metallicBits = floatBitsToUint(s.metallic);
#if ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS
    bool extended = false;
#if ML_HAS(ML_FEATURE_SPECULAR)
    t.target[3] = vec4(s.specularF0, s.specularWeight);
    extended = s.specularF0 != vec3(0.04) || s.specularWeight != 1.0;
#else
    t.target[3] = vec4(0.04, 0.04, 0.04, 1.0);
#endif
#if ML_HAS(ML_FEATURE_UNLIT)
    if (s.unlitMaterial) {
        t.target[3].w = -1.0;
        extended = true;
    }
#endif
    if (extended) metallicBits |= kGBufferSignFlag;
#endif
    t.target[0] = vec4(uintBitsToFloat(distanceBits), octEncode(s.normal), uintBitsToFloat(roughnessBits));
    t.target[1] = vec4(uintBitsToFloat(redBits), uintBitsToFloat(greenBits), uintBitsToFloat(blueBits), uintBitsToFloat(metallicBits));
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD
    t.target[0] = vec4(s.normal, s.occlusion);
    t.target[1] = vec4(s.baseColor, s.metallic);
    t.target[2] = vec4(s.roughness, s.emissive);
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_PACKED
    t.bits = uvec4(packSnorm2x16(octEncode(s.normal)), packUnorm4x8(vec4(encodeSrgb(s.baseColor), s.metallic)),
                   packUnorm2x16(vec2(s.roughness, s.occlusion)), 0u);
#if ML_HAS(ML_FEATURE_EMISSIVE)
    t.bits.w = packRgb9e5(s.emissive);
#endif
#else
    t.target[0] = vec4(s.normal.xy, s.roughness, s.metallic);
    t.target[1] = vec4(s.baseColor, s.occlusion);
#endif
    return t;
}

// Fills the surface's normal (unit length) and material, then its shading terms.
void decodeGBuffer(GBufferTexel t, inout SurfacePoint s) {
    s.emissive = vec3(0.0);
#if ML_GBUFFER_FORMAT == ML_GBUFFER_EXACT
    s.normal = octDecode(t.target[0].yz);
    s.roughness = withoutSignFlag(t.target[0].w);
    s.baseColor = vec3(withoutSignFlag(t.target[1].r), withoutSignFlag(t.target[1].g), withoutSignFlag(t.target[1].b));
    s.metallic = withoutSignFlag(t.target[1].w);
    s.occlusion = 1.0;
    if (gbufferUsesTarget2(t)) {
        s.emissive = t.target[2].rgb;
        s.occlusion = t.target[2].w;
    }
#if ML_GBUFFER_EXACT_MATERIAL_EXTENSIONS
    // Unflagged pixels hold glTF's defaults (material.glsl gives 0.04 and 1 to the bit there).
    vec4 extension = gbufferUsesTarget3(t) ? t.target[3] : vec4(0.04, 0.04, 0.04, 1.0);
#if ML_HAS(ML_FEATURE_SPECULAR)
    s.specularF0 = extension.rgb;
    s.specularWeight = max(extension.w, 0.0);
#endif
#if ML_HAS(ML_FEATURE_UNLIT)
    s.unlitMaterial = extension.w < 0.0;
#endif
#endif
#if ML_GBUFFER_EXACT_CLEARCOAT
    // Unflagged pixels have no coat (the normal is then never read).
    vec4 coat = gbufferUsesTarget4(t) ? t.target[4] : vec4(0.0);
    s.clearcoat = coat.x;
    s.clearcoatRoughness = coat.y;
    s.clearcoatNormal = gbufferUsesTarget4(t) ? octDecode(coat.zw) : s.normal;
#endif
#if ML_GBUFFER_EXACT_SHEEN
    // Unflagged pixels have no sheen.
    vec4 sheen = gbufferUsesTarget5(t) ? t.target[5] : vec4(0.0);
    s.sheenColor = sheen.rgb;
    s.sheenRoughness = sheen.a;
#endif
#if ML_GBUFFER_EXACT_ANISOTROPY
    // Unflagged pixels have the isotropic lobe (T and B_a then never read).
    s.anisotropyT = vec3(1.0, 0.0, 0.0);
    s.anisotropyB = vec3(0.0, 1.0, 0.0);
    s.anisotropyStrength = 0.0;
    if (gbufferUsesTarget6(t)) {
        vec3 scaled = t.target[6].xyz;
        s.anisotropyStrength = length(scaled);
        s.anisotropyT = scaled / s.anisotropyStrength;
        vec3 e, u;
        anisotropyStorageFrame(s.normal, s.anisotropyT, e, u);
        float w = t.target[6].w;
        s.anisotropyB = sqrt(max(1.0 - w * w, 0.0)) * e + w * u;
    }
#endif
#if ML_GBUFFER_EXACT_IRIDESCENCE
    // Unflagged pixels have no film.
    vec4 film = gbufferUsesTarget7(t) ? t.target[7] : vec4(0.0, 0.0, 1.0, 0.0);
    s.iridescence = film.x;
    s.iridescenceThickness = film.y;
    s.iridescenceIor = film.z;
#endif
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD
    s.normal = normalize(t.target[0].xyz);  // 16-bit storage: restore unit length
    s.occlusion = t.target[0].w;
    s.baseColor = t.target[1].rgb;
    s.metallic = t.target[1].w;
    s.roughness = t.target[2].x;
    s.emissive = t.target[2].yzw;
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_PACKED
    s.normal = octDecode(unpackSnorm2x16(t.bits.x));
    vec4 baseMetallic = unpackUnorm4x8(t.bits.y);
    s.baseColor = decodeSrgb(baseMetallic.rgb);
    s.metallic = baseMetallic.a;
    vec2 roughnessOcclusion = unpackUnorm2x16(t.bits.z);
    s.roughness = roughnessOcclusion.x;
    s.occlusion = roughnessOcclusion.y;
#if ML_HAS(ML_FEATURE_EMISSIVE)
    s.emissive = unpackRgb9e5(t.bits.w);
#endif
#else
    vec2 xy = t.target[0].xy;
    s.normal = normalize(vec3(xy, sqrt(max(1.0 - dot(xy, xy), 0.0))));  // the sign of z is gone
    s.roughness = t.target[0].z;
    s.metallic = t.target[0].w;
    s.baseColor = t.target[1].rgb;
    s.occlusion = t.target[1].w;
#endif
#if ML_GBUFFER_FORMAT != ML_GBUFFER_EXACT
    // The lossy layouts hold no material extension: glTF's default dielectric, lit.
#if ML_HAS(ML_FEATURE_SPECULAR)
    s.specularF0 = vec3(0.04);
    s.specularWeight = 1.0;
#endif
#if ML_HAS(ML_FEATURE_UNLIT)
    s.unlitMaterial = false;
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    s.clearcoat = 0.0;
    s.clearcoatRoughness = 0.0;
    s.clearcoatNormal = s.normal;
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    s.sheenColor = vec3(0.0);
    s.sheenRoughness = 0.0;
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    s.anisotropyT = vec3(1.0, 0.0, 0.0);
    s.anisotropyB = vec3(0.0, 1.0, 0.0);
    s.anisotropyStrength = 0.0;
#endif
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    s.iridescence = 0.0;
    s.iridescenceThickness = 0.0;
    s.iridescenceIor = 1.0;
#endif
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    // Transmissive surfaces are drawn as glass, never into a G-buffer: every pixel here is opaque.
    s.transmission = 0.0;
    s.thickness = 0.0;
    s.attenuationDistance = 0.0;
    s.transmissionIor = 1.5;
    s.attenuationColor = vec3(1.0);
    s.behind = vec3(0.0);
#endif
    deriveShadingTerms(s);
}
