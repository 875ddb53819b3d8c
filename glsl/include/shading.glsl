// The shading model shared by every method (docs/lights-and-shading.md), mirrored on the CPU by
// renderer/reference/shading_reference.cpp. A glTF metallic-roughness material maps onto normalized
// Blinn-Phong:
//   diffuse = base * (1 - metallic)        f0 = mix(0.04, base, metallic)
//   alpha = roughness^2                    shininess s = clamp(2 / alpha^2 - 2, 1, 8192)
//   L_out = ambient * occlusion * (diffuse + f0) + emissive
//         + sum over lights of  color * W(d, r) * max(N.L, 0) * (diffuse + f0 * (s + 8) / 8 * max(N.H, 0)^s)
//   W(d, r) = saturate(1 - (d/r)^4)^2 / (d^2 + 1)
// A spot light's colour is further weighted by glTF's angular attenuation (KHR_lights_punctual):
//   A = saturate((cos - cosOuter) / (cosInner - cosOuter))^2,  cos = angle between its direction and -L,
// exactly zero at and outside the outer cone, so culling by the cone is as exact as by r. A
// directional light has colour c from direction -L everywhere (W = A = 1).
// W is smooth, and exactly zero at and beyond r, so culling a light outside its radius is exact.
// The specular term is weighted by N.L too, so shading is continuous at the terminator and a
// tiny error in a rebuilt position or normal cannot switch a highlight on or off. --specular off
// (a frame uniform, the same in every method) leaves it out: the diffuse term only. Emissive
// surfaces glow but light nothing else: only the scene's lights do.

#ifndef ML_SPOT_LIGHTS
#define ML_SPOT_LIGHTS 1  // as in lights.glsl: spot paths compiled in unless the renderer says none
#endif

float lightFalloff(float d, float radius) {
    if (d >= radius) return 0.0;
    float x = d / radius;
    float x2 = x * x;
    float w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    return (w * w) / (d * d + 1.0);
}

struct SurfacePoint {
    vec3 position;   // world space
    vec3 normal;     // world space, unit length, after any normal map
    // The material at this point, after its textures: what the G-buffer stores.
    vec3 baseColor;  // linear
    float metallic;
    float roughness;
    float occlusion;  // ambient only
    vec3 emissive;    // linear radiance, added as is
    // Derived by deriveShadingTerms: what the light loop reads, and the unlit term, worked out
    // before the loop so that the material's inputs need not stay in registers through it.
    vec3 diffuse;
    vec3 specular;    // f0 * (s + 8) / 8
    float shininess;
    vec3 unlit;       // ambient * occlusion * (diffuse + f0) + emissive
};

void deriveShadingTerms(inout SurfacePoint s) {
    float m = clamp(s.metallic, 0.0, 1.0);
    float r = clamp(s.roughness, 0.0, 1.0);
    float alpha = r * r;
    s.shininess = clamp(2.0 / max(alpha * alpha, 1e-6) - 2.0, 1.0, 8192.0);
    s.diffuse = s.baseColor * (1.0 - m);
    vec3 f0 = mix(vec3(0.04), s.baseColor, m);
    s.specular = f0 * ((s.shininess + 8.0) / 8.0);
    s.unlit = ambientStrength() * s.occlusion * (s.diffuse + f0) + s.emissive;
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

// The Blinn-Phong terms of a light of colour `color` arriving from unit direction l, weighted
// by its falloff (and cone).
vec3 shadeIncoming(SurfacePoint s, vec3 viewDir, vec3 l, vec3 color, float weight) {
    float nDotL = dot(s.normal, l);
    if (nDotL <= 0.0) return vec3(0.0);
    if (!specularEnabled()) return color * (weight * nDotL) * s.diffuse;
    vec3 h = normalize(l + viewDir);
    float spec = pow(max(dot(s.normal, h), 0.0), s.shininess);
    return color * (weight * nDotL) * (s.diffuse + s.specular * spec);
}

// A point or spot light (include/lights.glsl's fields). A point light's cone cosines are
// ML_POINT_LIGHT_CONE_COS, and the branch on them is uniform where a scene has no spots.
vec3 shadeLight(SurfacePoint s, vec3 viewDir, vec4 positionRadius, vec4 colorCosInner, vec4 directionCosOuter) {
    vec3 toLight = positionRadius.xyz - s.position;
    float d = length(toLight);
    float falloff = lightFalloff(d, positionRadius.w);
    if (falloff <= 0.0) return vec3(0.0);
    vec3 l = toLight / max(d, 1e-6);
    if (ML_SPOT_LIGHTS != 0 && directionCosOuter.w > -1.5) {
        falloff *= spotAttenuation(dot(-l, directionCosOuter.xyz), colorCosInner.w, directionCosOuter.w);
        if (falloff <= 0.0) return vec3(0.0);
    }
    return shadeIncoming(s, viewDir, l, colorCosInner.rgb, falloff);
}

// A directional light travelling along the unit `direction`: no falloff, no cone.
vec3 shadeDirectionalLight(SurfacePoint s, vec3 viewDir, vec3 direction, vec3 color) {
    return shadeIncoming(s, viewDir, -direction, color, 1.0);
}

// What a surface shows with no light on it: the ambient term and its own glow.
vec3 shadeUnlit(SurfacePoint s) { return s.unlit; }
