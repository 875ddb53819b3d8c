// Materials, mirrored in C++ by ml::GpuMaterial (renderer/gpu_types.h), and how a surface point
// samples them. Needs shading.glsl. Paths a scene does not use are compiled out through
// ML_MATERIAL_FEATURES (bindings.h, ML_FEATURE_*), so their cost is paid only where used.
#include "include/material_features.glsl"

// The slots a material record holds (bindings.h, ML_GPU_MATERIAL_VEC4S): the extensions' only in
// scenes that model one.
#if ML_EXTENDED_MATERIAL_RECORD
#define ML_MATERIAL_SLOTS ML_TEXTURE_SLOTS
#else
#define ML_MATERIAL_SLOTS ML_CORE_TEXTURE_SLOTS
#endif

struct Material {
    vec4 baseColorFactor;  // linear
    vec4 emissiveCutoff;   // rgb: emissive factor times strength, a: alpha cutoff
    vec4 factors;          // metallic, roughness, normal scale, occlusion strength
    uvec4 info;            // x: slots with a texture (bit per ML_SLOT_*), y: slots reading TEXCOORD_1,
                           // z: texture set + 1 (0: none), w: ML_MATERIAL_* bits
    // Per slot, KHR_texture_transform as uv' = mat2(xy, zw) * uv + offset: [2 slot] the matrix's
    // columns, [2 slot + 1].xy the offset.
    vec4 uvTransforms[2 * ML_MATERIAL_SLOTS];
#if ML_EXTENDED_MATERIAL_RECORD
    // KHR_materials_ior and KHR_materials_specular: rgb ((ior - 1) / (ior + 1))^2 x specularColorFactor,
    // a specularFactor.
    vec4 specular;
    // KHR_materials_clearcoat: factor, roughness, normal scale.
    vec4 clearcoat;
    // KHR_materials_sheen: rgb colour factor, a roughness factor.
    vec4 sheen;
    // KHR_materials_anisotropy: cos and sin of the rotation, the strength, 0.
    vec4 anisotropy;
    // KHR_materials_iridescence: factor, the film's IOR, its thickness's minimum and maximum (nm).
    vec4 iridescence;
    // KHR_materials_transmission and KHR_materials_volume: factor, thickness, attenuation distance
    // (0: infinite), the IOR; rgb attenuation colour.
    vec4 transmission;
    vec4 attenuation;
#endif
};
layout(std430, binding = ML_SSBO_MATERIALS) readonly buffer MaterialBuffer { Material materials[]; };
// sRGB textures (base colour, emissive) are stored as such and sampled as linear.
layout(binding = ML_TEX_BASE_COLOR) uniform sampler2D u_baseColorTexture;
layout(binding = ML_TEX_METALLIC_ROUGHNESS) uniform sampler2D u_metallicRoughnessTexture;
layout(binding = ML_TEX_NORMAL) uniform sampler2D u_normalTexture;
layout(binding = ML_TEX_OCCLUSION) uniform sampler2D u_occlusionTexture;
layout(binding = ML_TEX_EMISSIVE) uniform sampler2D u_emissiveTexture;
#if ML_HAS(ML_FEATURE_SPECULAR_MAP)
layout(binding = ML_TEX_SPECULAR) uniform sampler2D u_specularTexture;             // linear; A
layout(binding = ML_TEX_SPECULAR_COLOR) uniform sampler2D u_specularColorTexture;  // sRGB; RGB
#endif
#if ML_HAS(ML_FEATURE_CLEARCOAT_MAP)
layout(binding = ML_TEX_CLEARCOAT) uniform sampler2D u_clearcoatTexture;                    // linear; R
layout(binding = ML_TEX_CLEARCOAT_ROUGHNESS) uniform sampler2D u_clearcoatRoughnessTexture;  // linear; G
layout(binding = ML_TEX_CLEARCOAT_NORMAL) uniform sampler2D u_clearcoatNormalTexture;        // linear, tangent space
#endif
#if ML_HAS(ML_FEATURE_SHEEN_MAP)
layout(binding = ML_TEX_SHEEN_COLOR) uniform sampler2D u_sheenColorTexture;          // sRGB; RGB
layout(binding = ML_TEX_SHEEN_ROUGHNESS) uniform sampler2D u_sheenRoughnessTexture;  // linear; A
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY_MAP)
layout(binding = ML_TEX_ANISOTROPY) uniform sampler2D u_anisotropyTexture;  // linear; RG direction, B strength
#endif
#if ML_HAS(ML_FEATURE_IRIDESCENCE_MAP)
// Both of KHR_materials_iridescence's maps: one image on one unit (bindings.h), each slot with its
// own transform and texture coordinates.
layout(binding = ML_TEX_IRIDESCENCE) uniform sampler2D u_iridescenceTexture;  // linear; R strength, G thickness
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION_MAP)
layout(binding = ML_TEX_TRANSMISSION) uniform sampler2D u_transmissionTexture;  // linear; R
layout(binding = ML_TEX_THICKNESS) uniform sampler2D u_thicknessTexture;        // linear; G
#endif

// Where a point samples its material: its UV sets and their screen-space gradients, which every
// texture read takes explicitly (textureGrad). Every pass, raster or compute, builds them from the
// point's triangle as a rasterizer's coarse 2x2-quad derivatives would take them
// (triangle_surface.glsl), so every method samples at the same coordinates and level to the last
// bit; implicit derivatives would differ between a rasterizer's quads and the compute passes, and
// after an alpha test's discard a quad's discarded lanes are undefined.
struct MaterialCoords {
    vec2 uv[2];
    vec2 dx[2];
    vec2 dy[2];
};

bool hasTexture(Material m, uint slot) { return (m.info.x & (1u << slot)) != 0u; }

vec4 sampleMaterialTexture(sampler2D tex, Material m, uint slot, MaterialCoords c) {
#if ML_HAS(ML_FEATURE_UV1)
    uint set = (m.info.y >> slot) & 1u;
#else
    const uint set = 0u;
#endif
    vec2 uv = c.uv[set];
#if ML_HAS(ML_FEATURE_TEXTURE_TRANSFORM)
    mat2 linear = mat2(m.uvTransforms[2u * slot].xy, m.uvTransforms[2u * slot].zw);
    uv = linear * uv + m.uvTransforms[2u * slot + 1u].xy;
#endif
    vec2 dx = c.dx[set], dy = c.dy[set];
#if ML_HAS(ML_FEATURE_TEXTURE_TRANSFORM)
    dx = linear * dx;
    dy = linear * dy;
#endif
    return textureGrad(tex, uv, dx, dy);
}

// Base colour and coverage: factor x texture x COLOR_0.
vec4 materialBaseColor(Material m, MaterialCoords c, vec4 vertexColor) {
    vec4 base = m.baseColorFactor;
    if (hasTexture(m, ML_SLOT_BASE_COLOR)) base *= sampleMaterialTexture(u_baseColorTexture, m, ML_SLOT_BASE_COLOR, c);
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
    base *= vertexColor;
#endif
    return base;
}

// glTF MASK: covered where alpha >= alphaCutoff.
bool alphaCovered(Material m, float alpha) { return alpha >= m.emissiveCutoff.a; }

// The tangent-space normal map's direction in world space (glTF: B = cross(N, T) * w, the map's
// x and y scaled by normalTexture.scale). A degenerate tangent leaves the normal as it is.
vec3 perturbNormal(vec3 n, vec4 tangent, vec3 texel, float scale) {
    vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
    float length2 = dot(t, t);
    if (!(length2 > 1e-16)) return n;
    t *= inversesqrt(length2);
    vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 k = texel * 2.0 - 1.0;
    k.xy *= scale;
    vec3 mapped = t * k.x + b * k.y + n * k.z;
    float mapped2 = dot(mapped, mapped);
    return mapped2 > 1e-16 ? mapped * inversesqrt(mapped2) : n;
}

#if ML_HAS(ML_FEATURE_ANISOTROPY)
// KHR_materials_anisotropy at a point of geometric (interpolated) normal ng: the direction T, the
// tangent frame's (T, B as perturbNormal builds them from ng) combination by the map's RG in
// [-1, 1], normalized ((1, 0) without a map, or where it reads (0, 0)), turned by the rotation; its
// strength, the factor times the map's B; and B_a = normalize(ng x T). A degenerate tangent leaves
// the lobe isotropic (strength 0), as does a strength of 0 (no T then: the rotation's record is 0
// for materials without the extension).
void anisotropyFromMaterial(Material m, vec3 ng, vec4 tangent, MaterialCoords c, inout SurfacePoint s) {
    vec2 direction = vec2(1.0, 0.0);
    float strength = m.anisotropy.z;
#if ML_HAS(ML_FEATURE_ANISOTROPY_MAP)
    if (hasTexture(m, ML_SLOT_ANISOTROPY)) {
        vec3 texel = sampleMaterialTexture(u_anisotropyTexture, m, ML_SLOT_ANISOTROPY, c).rgb;
        vec2 mapped = texel.xy * 2.0 - 1.0;
        float mapped2 = dot(mapped, mapped);
        if (mapped2 > 1e-16) direction = mapped * inversesqrt(mapped2);
        strength *= texel.z;
    }
#endif
    s.anisotropyT = vec3(1.0, 0.0, 0.0);
    s.anisotropyB = vec3(0.0, 1.0, 0.0);
    s.anisotropyStrength = 0.0;
    vec3 t = tangent.xyz - ng * dot(ng, tangent.xyz);
    float length2 = dot(t, t);
    // No lobe (the scene's other materials, a map's B of 0), or no frame to stretch it in.
    if (!(strength > 0.0) || !(length2 > 1e-16)) return;
    direction = mat2(m.anisotropy.x, m.anisotropy.y, -m.anisotropy.y, m.anisotropy.x) * direction;
    t *= inversesqrt(length2);
    vec3 b = cross(ng, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
    s.anisotropyT = normalize(t * direction.x + b * direction.y);
    s.anisotropyB = normalize(cross(ng, s.anisotropyT));
    s.anisotropyStrength = clamp(strength, 0.0, 1.0);
}
#endif

// The shading inputs at a point of material m whose base colour (materialBaseColor) is known.
SurfacePoint surfaceFromMaterial(Material m, vec3 worldPos, vec3 worldNormal, vec4 worldTangent, vec4 base, MaterialCoords c) {
    SurfacePoint s;
    s.position = worldPos;
    s.normal = normalize(worldNormal);
#if ML_HAS(ML_FEATURE_CLEARCOAT)
    // KHR_materials_clearcoat: the coat's normal is the surface's own unless it has a map of its
    // own (the material's normal map does not reach it).
    s.clearcoat = m.clearcoat.x;
    s.clearcoatRoughness = m.clearcoat.y;
    s.clearcoatNormal = s.normal;
#if ML_HAS(ML_FEATURE_CLEARCOAT_MAP)
    if (hasTexture(m, ML_SLOT_CLEARCOAT)) s.clearcoat *= sampleMaterialTexture(u_clearcoatTexture, m, ML_SLOT_CLEARCOAT, c).r;
    if (hasTexture(m, ML_SLOT_CLEARCOAT_ROUGHNESS))
        s.clearcoatRoughness *= sampleMaterialTexture(u_clearcoatRoughnessTexture, m, ML_SLOT_CLEARCOAT_ROUGHNESS, c).g;
    if (hasTexture(m, ML_SLOT_CLEARCOAT_NORMAL))
        s.clearcoatNormal = perturbNormal(s.normal, worldTangent,
                                          sampleMaterialTexture(u_clearcoatNormalTexture, m, ML_SLOT_CLEARCOAT_NORMAL, c).xyz, m.clearcoat.z);
#endif
#endif
#if ML_HAS(ML_FEATURE_ANISOTROPY)
    anisotropyFromMaterial(m, s.normal, worldTangent, c, s);  // from the normal before its map
#endif
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
    if (hasTexture(m, ML_SLOT_NORMAL))
        s.normal = perturbNormal(s.normal, worldTangent, sampleMaterialTexture(u_normalTexture, m, ML_SLOT_NORMAL, c).xyz, m.factors.z);
#endif
    s.baseColor = base.rgb;
    s.metallic = m.factors.x;
    s.roughness = m.factors.y;
#if ML_HAS(ML_FEATURE_METALLIC_ROUGHNESS_MAP)
    if (hasTexture(m, ML_SLOT_METALLIC_ROUGHNESS)) {
        vec4 mr = sampleMaterialTexture(u_metallicRoughnessTexture, m, ML_SLOT_METALLIC_ROUGHNESS, c);
        s.roughness *= mr.g;
        s.metallic *= mr.b;
    }
#endif
    s.occlusion = 1.0;
#if ML_HAS(ML_FEATURE_OCCLUSION_MAP)
    if (hasTexture(m, ML_SLOT_OCCLUSION))
        s.occlusion = 1.0 + m.factors.w * (sampleMaterialTexture(u_occlusionTexture, m, ML_SLOT_OCCLUSION, c).r - 1.0);
#endif
    s.emissive = vec3(0.0);
#if ML_HAS(ML_FEATURE_EMISSIVE)
    s.emissive = m.emissiveCutoff.rgb;
#if ML_HAS(ML_FEATURE_EMISSIVE_MAP)
    if (hasTexture(m, ML_SLOT_EMISSIVE)) s.emissive *= sampleMaterialTexture(u_emissiveTexture, m, ML_SLOT_EMISSIVE, c).rgb;
#endif
#endif
#if ML_HAS(ML_FEATURE_SPECULAR)
    // The dielectric's F0 colour, clamped after the texture (KHR_materials_specular), and its weight.
    vec3 specularColor = m.specular.rgb;
    s.specularWeight = m.specular.a;
#if ML_HAS(ML_FEATURE_SPECULAR_MAP)
    if (hasTexture(m, ML_SLOT_SPECULAR)) s.specularWeight *= sampleMaterialTexture(u_specularTexture, m, ML_SLOT_SPECULAR, c).a;
    if (hasTexture(m, ML_SLOT_SPECULAR_COLOR))
        specularColor *= sampleMaterialTexture(u_specularColorTexture, m, ML_SLOT_SPECULAR_COLOR, c).rgb;
#endif
    s.specularF0 = min(specularColor, vec3(1.0));
#endif
#if ML_HAS(ML_FEATURE_UNLIT)
    s.unlitMaterial = (m.info.w & ML_MATERIAL_UNLIT) != 0u;
#endif
#if ML_HAS(ML_FEATURE_SHEEN)
    s.sheenColor = m.sheen.rgb;
    s.sheenRoughness = m.sheen.a;
#if ML_HAS(ML_FEATURE_SHEEN_MAP)
    if (hasTexture(m, ML_SLOT_SHEEN_COLOR)) s.sheenColor *= sampleMaterialTexture(u_sheenColorTexture, m, ML_SLOT_SHEEN_COLOR, c).rgb;
    if (hasTexture(m, ML_SLOT_SHEEN_ROUGHNESS))
        s.sheenRoughness *= sampleMaterialTexture(u_sheenRoughnessTexture, m, ML_SLOT_SHEEN_ROUGHNESS, c).a;
#endif
#endif
#if ML_HAS(ML_FEATURE_IRIDESCENCE)
    // KHR_materials_iridescence: the thickness is the maximum where there is no thickness map.
    s.iridescence = m.iridescence.x;
    s.iridescenceIor = m.iridescence.y;
    s.iridescenceThickness = m.iridescence.w;
#if ML_HAS(ML_FEATURE_IRIDESCENCE_MAP)
    if (hasTexture(m, ML_SLOT_IRIDESCENCE)) s.iridescence *= sampleMaterialTexture(u_iridescenceTexture, m, ML_SLOT_IRIDESCENCE, c).r;
    if (hasTexture(m, ML_SLOT_IRIDESCENCE_THICKNESS))
        s.iridescenceThickness =
            mix(m.iridescence.z, m.iridescence.w, sampleMaterialTexture(u_iridescenceTexture, m, ML_SLOT_IRIDESCENCE_THICKNESS, c).g);
#endif
#endif
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    s.transmission = m.transmission.x;
    s.thickness = m.transmission.y;
    s.attenuationDistance = m.transmission.z;
    s.transmissionIor = m.transmission.w;
    s.attenuationColor = m.attenuation.rgb;
    s.behind = vec3(0.0);  // the transparent pass sees what is behind (glass_shade.comp)
#if ML_HAS(ML_FEATURE_TRANSMISSION_MAP)
    if (hasTexture(m, ML_SLOT_TRANSMISSION)) s.transmission *= sampleMaterialTexture(u_transmissionTexture, m, ML_SLOT_TRANSMISSION, c).r;
    if (hasTexture(m, ML_SLOT_THICKNESS)) s.thickness *= sampleMaterialTexture(u_thicknessTexture, m, ML_SLOT_THICKNESS, c).g;
#endif
#endif
    deriveShadingTerms(s);
    return s;
}
