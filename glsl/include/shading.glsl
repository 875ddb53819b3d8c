// The shading model shared by every method (README, "Shading model"):
//   L_out = ambient * albedo
//         + sum over lights of  color * W(d, r) * max(N.L, 0) * (albedo + ks * max(N.H, 0)^shininess)
//   W(d, r) = saturate(1 - (d/r)^4)^2 / (d^2 + 1)
// W is smooth, and exactly zero at and beyond r, so culling a light outside its radius is exact.
// The specular term is weighted by N.L too, so shading is continuous at the terminator and a
// tiny error in a rebuilt position or normal cannot switch a highlight on or off. --specular off
// (a frame uniform, the same in every method) leaves it out: Lambert only.

float lightFalloff(float d, float radius) {
    if (d >= radius) return 0.0;
    float x = d / radius;
    float x2 = x * x;
    float w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    return (w * w) / (d * d + 1.0);
}

struct SurfacePoint {
    vec3 position;   // world space
    vec3 normal;     // world space, unit length
    vec3 albedo;     // linear
    float specularStrength;
    float shininess;
};

vec3 shadePointLight(SurfacePoint s, vec3 viewDir, vec4 positionRadius, vec3 color) {
    vec3 toLight = positionRadius.xyz - s.position;
    float d = length(toLight);
    float falloff = lightFalloff(d, positionRadius.w);
    if (falloff <= 0.0) return vec3(0.0);
    vec3 l = toLight / max(d, 1e-6);
    float nDotL = dot(s.normal, l);
    if (nDotL <= 0.0) return vec3(0.0);
    if (!specularEnabled()) return color * (falloff * nDotL) * s.albedo;
    vec3 h = normalize(l + viewDir);
    float spec = s.specularStrength * pow(max(dot(s.normal, h), 0.0), s.shininess);
    return color * (falloff * nDotL) * (s.albedo + vec3(spec));
}

vec3 shadeAmbient(SurfacePoint s) { return ambientStrength() * s.albedo; }
