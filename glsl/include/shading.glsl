// The shading model shared by every method (README, "Shading model"), mirrored on the CPU by
// renderer/shading_reference.cpp. A glTF metallic-roughness material maps onto normalized
// Blinn-Phong:
//   diffuse = base * (1 - metallic)        f0 = mix(0.04, base, metallic)
//   alpha = roughness^2                    shininess s = clamp(2 / alpha^2 - 2, 1, 8192)
//   L_out = ambient * occlusion * (diffuse + f0) + emissive
//         + sum over lights of  color * W(d, r) * max(N.L, 0) * (diffuse + f0 * (s + 8) / 8 * max(N.H, 0)^s)
//   W(d, r) = saturate(1 - (d/r)^4)^2 / (d^2 + 1)
// W is smooth, and exactly zero at and beyond r, so culling a light outside its radius is exact.
// The specular term is weighted by N.L too, so shading is continuous at the terminator and a
// tiny error in a rebuilt position or normal cannot switch a highlight on or off. --specular off
// (a frame uniform, the same in every method) leaves it out: the diffuse term only. Emissive
// surfaces glow but light nothing else: only the scene's lights do.

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

vec3 shadePointLight(SurfacePoint s, vec3 viewDir, vec4 positionRadius, vec3 color) {
    vec3 toLight = positionRadius.xyz - s.position;
    float d = length(toLight);
    float falloff = lightFalloff(d, positionRadius.w);
    if (falloff <= 0.0) return vec3(0.0);
    vec3 l = toLight / max(d, 1e-6);
    float nDotL = dot(s.normal, l);
    if (nDotL <= 0.0) return vec3(0.0);
    if (!specularEnabled()) return color * (falloff * nDotL) * s.diffuse;
    vec3 h = normalize(l + viewDir);
    float spec = pow(max(dot(s.normal, h), 0.0), s.shininess);
    return color * (falloff * nDotL) * (s.diffuse + s.specular * spec);
}

// What a surface shows with no light on it: the ambient term and its own glow.
vec3 shadeUnlit(SurfacePoint s) { return s.unlit; }
