// The --gbuffer layouts (gbuffer_format.h; numbered in bindings.h), chosen by the define
// ML_GBUFFER_FORMAT. Encoded by the G-buffer pass and the visibility resolve, decoded by the
// deferred lighting; position is never stored (it comes back from depth). Needs shading.glsl.
//
//   standard       target 0 RGBA16F normal xyz     target 1 RGBA16F albedo   target 2 RGBA16F ks, shininess   24 B
//   packed         target 0 RGBA32UI: x octahedral normal (2 x snorm16), y albedo (sRGB-encoded RGBA8),
//                  z ks and shininess (2 x half), w spare                                                      16 B
//   two-component  target 0 RGBA16F normal x, y, ks, shininess   target 1 RGBA16F albedo                      16 B
//                  z is rebuilt as +sqrt(1 - x^2 - y^2): every normal with z < 0 (world space) is mirrored
//                  to z > 0, so surfaces facing -z are lit as if they faced +z. The documented failure case.
#ifndef ML_GBUFFER_FORMAT
#define ML_GBUFFER_FORMAT ML_GBUFFER_STANDARD
#endif

#if ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD
#define ML_GBUFFER_FLOAT_TARGETS 3
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_TWO_COMPONENT
#define ML_GBUFFER_FLOAT_TARGETS 2
#else
#define ML_GBUFFER_FLOAT_TARGETS 0
#endif

// One pixel of the G-buffer as its targets hold it: float targets, or the one packed target.
struct GBufferTexel {
    vec4 target[3];
    uvec4 bits;  // the packed layout's one RGBA32UI texel
};

// Octahedral encoding (Cigolle et al. 2014, the normal encoding of seed 001): the unit sphere
// projected onto the octahedron |x| + |y| + |z| = 1, the lower half folded over the upper,
// into [-1, 1]^2. 16 bits a component keep the direction to about 3e-5 rad.
vec2 signNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }
vec2 octEncode(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * signNotZero(p);
}
vec3 octDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
    return normalize(n);
}

// Albedo is stored sRGB-encoded in 8 bits, as 8-bit colour textures are: the steps are even to
// the eye, so dark albedos do not band (linear 8 bits would put 1/255 steps into the shadows).
vec3 encodeSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 decodeSrgb(vec3 c) { return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(vec3(0.04045), c)); }

GBufferTexel encodeGBuffer(SurfacePoint s) {
    GBufferTexel t;
    t.target[0] = t.target[1] = t.target[2] = vec4(0.0);
    t.bits = uvec4(0u);
#if ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD
    t.target[0] = vec4(s.normal, 0.0);
    t.target[1] = vec4(s.albedo, 1.0);
    t.target[2] = vec4(s.specularStrength, s.shininess, 0.0, 0.0);
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_PACKED
    t.bits = uvec4(packSnorm2x16(octEncode(s.normal)), packUnorm4x8(vec4(encodeSrgb(s.albedo), 1.0)),
                     packHalf2x16(vec2(s.specularStrength, s.shininess)), 0u);
#else
    t.target[0] = vec4(s.normal.xy, s.specularStrength, s.shininess);
    t.target[1] = vec4(s.albedo, 1.0);
#endif
    return t;
}

// Fills the surface's normal (unit length), albedo and specular parameters.
void decodeGBuffer(GBufferTexel t, inout SurfacePoint s) {
#if ML_GBUFFER_FORMAT == ML_GBUFFER_STANDARD
    s.normal = normalize(t.target[0].xyz);  // 16-bit storage: restore unit length
    s.albedo = t.target[1].rgb;
    s.specularStrength = t.target[2].x;
    s.shininess = t.target[2].y;
#elif ML_GBUFFER_FORMAT == ML_GBUFFER_PACKED
    s.normal = octDecode(unpackSnorm2x16(t.bits.x));
    s.albedo = decodeSrgb(unpackUnorm4x8(t.bits.y).rgb);
    vec2 spec = unpackHalf2x16(t.bits.z);
    s.specularStrength = spec.x;
    s.shininess = spec.y;
#else
    vec2 xy = t.target[0].xy;
    s.normal = normalize(vec3(xy, sqrt(max(1.0 - dot(xy, xy), 0.0))));  // the sign of z is gone
    s.albedo = t.target[1].rgb;
    s.specularStrength = t.target[0].z;
    s.shininess = t.target[0].w;
#endif
}
