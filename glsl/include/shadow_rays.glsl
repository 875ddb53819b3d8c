// Exact shadow rays (--shadows rays): is anything between a shaded point and a light? Any-hit
// traversal of a BVH of ML_SHADOW_BVH_WIDTH children a node, built on the CPU by Embree
// (renderer/raytracing/shadow_bvh.h; occludedByBvh in shadow_bvh_traversal.h mirrors this file),
// in one buffer after a 16-byte header (the ray count below): binary node i is the four vec4s
// from 4i (each child's box, in the parent, with the child references in the w of the first
// two); a wide node is ML_SHADOW_BVH_WIDTH / 4 groups of seven vec4s (four boxes' coordinates,
// then their references; shadow_bvh_layout.h). Triangles
// are three vec4s each from u_shadows.x (the corners; v0.w the material word, ML_SHADOW_OPAQUE or
// an alpha-tested material), then two vec4s of UVs per MASK triangle and three vec4s per material
// from u_shadows.w (renderer/raytracing/shadow_alpha.h). Every method calls it with the same
// origin and light position, so they trace the same rays (design.md). Needs frame_uniforms.
// ML_COUNT_SHADOW_RAYS (FrameRenderer::countShadowRays, for rays per second): every ray adds one
// to a 64-bit count in the buffer's 16-byte header, an untimed frame's worth.
#ifndef ML_COUNT_SHADOW_RAYS
#define ML_COUNT_SHADOW_RAYS 0
#endif
#ifndef ML_SHADOW_BVH_WIDTH
#define ML_SHADOW_BVH_WIDTH 4  // kDefaultShadowBvhWidth; the renderer always defines it
#endif
#if ML_COUNT_SHADOW_RAYS
#define ML_SHADOW_BVH_ACCESS coherent
#else
#define ML_SHADOW_BVH_ACCESS readonly
#endif
layout(std430, binding = ML_SSBO_SHADOW_BVH) ML_SHADOW_BVH_ACCESS buffer ShadowBvhBuffer {
    uint shadowRaysTraced;  // ML_COUNT_SHADOW_RAYS: the rays traced, modulo 2^32...
    uint shadowRayWraps;    // ...and how often that count wrapped
    uvec2 shadowBvhHeaderPadding;
    vec4 shadowBvh[];
};
layout(binding = ML_TEX_SHADOW_ALPHA) uniform sampler2DArray u_shadowAlpha;

// Wächter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing
// Gems, chapter 6): the point moved along the normal by 256 ulps of each of its own coordinates
// (by 1/65536 near the origin, where ulps vanish), so that the ray leaves its own surface at any
// angle and the offset scales with the coordinates' precision rather than the scene's size.
vec3 shadowRayOrigin(vec3 p, vec3 n) {
    const float kOrigin = 1.0 / 32.0, kFloatScale = 1.0 / 65536.0, kIntScale = 256.0;
    ivec3 offset = ivec3(kIntScale * n);
    ivec3 bits = floatBitsToInt(p);
    vec3 moved = intBitsToFloat(ivec3(p.x < 0.0 ? bits.x - offset.x : bits.x + offset.x,
                                      p.y < 0.0 ? bits.y - offset.y : bits.y + offset.y,
                                      p.z < 0.0 ? bits.z - offset.z : bits.z + offset.z));
    return vec3(abs(p.x) < kOrigin ? p.x + kFloatScale * n.x : moved.x,
                abs(p.y) < kOrigin ? p.y + kFloatScale * n.y : moved.y,
                abs(p.z) < kOrigin ? p.z + kFloatScale * n.z : moved.z);
}

// The slab test over t in [0, 1] (the ray ends at the light). `inverse` has no infinities
// (shadowRayInverse), so no 0 * inf makes a NaN of a box the ray starts on.
bool shadowBoxHit(vec3 lo, vec3 hi, vec3 origin, vec3 inverse) {
    vec3 t0 = (lo - origin) * inverse, t1 = (hi - origin) * inverse;
    vec3 tNear = min(t0, t1), tFar = max(t0, t1);
    float enter = max(max(tNear.x, tNear.y), max(tNear.z, 0.0));
    float leave = min(min(tFar.x, tFar.y), min(tFar.z, 1.0));
    return enter <= leave;
}

vec3 shadowRayInverse(vec3 d) {
    const float kTiny = 1e-30;
    return 1.0 / vec3(abs(d.x) < kTiny ? (d.x < 0.0 ? -kTiny : kTiny) : d.x,
                      abs(d.y) < kTiny ? (d.y < 0.0 ? -kTiny : kTiny) : d.y,
                      abs(d.z) < kTiny ? (d.z < 0.0 ? -kTiny : kTiny) : d.z);
}

// Whether a MASK triangle covers the hit at barycentrics (u, v): the base colour's alpha there
// (factor times the texture's, its transform applied) against the cut-off (shadow_alpha.h).
bool shadowAlphaCovers(uint material, uint uvRecord, float u, float v) {
    uint uvAt = u_shadows.x + 3u * u_shadows.z + 2u * uvRecord, materialAt = u_shadows.w + 3u * material;
    vec4 uv01 = shadowBvh[uvAt], uv2 = shadowBvh[uvAt + 1u];
    vec2 uv = (1.0 - u - v) * uv01.xy + u * uv01.zw + v * uv2.xy;
    vec4 columns = shadowBvh[materialAt], rule = shadowBvh[materialAt + 1u];
    vec2 transformed = columns.xy * uv.x + columns.zw * uv.y + rule.xy;
    float alpha = rule.w;
    int layer = floatBitsToInt(shadowBvh[materialAt + 2u].x);
    if (layer >= 0) alpha *= textureLod(u_shadowAlpha, vec3(transformed, float(layer)), 0.0).r;
    return alpha >= rule.z;
}

// Moller-Trumbore, two-sided, hit strictly between the origin and the light: t in (0, 1); a MASK
// triangle blocks only where its alpha covers the hit.
bool shadowTriangleHit(uint triangle, vec3 origin, vec3 direction) {
    uint at = u_shadows.x + 3u * triangle;
    vec4 a = shadowBvh[at], b = shadowBvh[at + 1u], c = shadowBvh[at + 2u];
    vec3 e1 = b.xyz - a.xyz, e2 = c.xyz - a.xyz;
    vec3 p = cross(direction, e2);
    float det = dot(e1, p);
    if (det == 0.0) return false;
    float inv = 1.0 / det;
    vec3 s = origin - a.xyz;
    float u = dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(direction, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    float t = dot(e2, q) * inv;
    if (!(t > 0.0 && t < 1.0)) return false;
    uint material = floatBitsToUint(a.w);
    return material == ML_SHADOW_OPAQUE || shadowAlphaCovers(material, floatBitsToUint(c.w), u, v);
}

// Whether a coordinate is infinite or NaN, by its bits (a compiler may take x != x as false).
bool shadowNotFinite(vec3 v) { return any(equal(floatBitsToUint(v) & 0x7F800000u, uvec3(0x7F800000u))); }

// Whether anything blocks the segment from `origin` to origin + direction. A ray that is not
// finite is not traced: a NaN meets every box in min and max that drop NaN operands, so it
// would walk the whole tree (helper invocations beside a silhouette make such rays from
// extrapolated surfaces; on llvmpipe the walk then ran past the shader's loop limit and ended
// the pixels' light loops with it).
bool shadowRayBlocked(vec3 origin, vec3 direction) {
    uint nodes = u_shadows.y;
    if (nodes == 0u || shadowNotFinite(origin) || shadowNotFinite(direction)) return false;
#if ML_COUNT_SHADOW_RAYS
    if (atomicAdd(shadowRaysTraced, 1u) == 0xFFFFFFFFu) atomicAdd(shadowRayWraps, 1u);
#endif
    vec3 inverse = shadowRayInverse(direction);
    uint stack[ML_SHADOW_STACK];
    uint top = 0u;
    stack[top++] = 0u;
    // A tree visits each reference at most once: the bound only guards against a broken buffer.
    for (uint step = 0u; top > 0u && step <= uint(ML_SHADOW_BVH_WIDTH) * nodes; ++step) {
        uint ref = stack[--top];
        if ((ref & ML_SHADOW_LEAF_BIT) != 0u) {
            uint first = ref & 0x0FFFFFFFu, count = ((ref >> 28) & 7u) + 1u;
            for (uint i = 0u; i < count; ++i)
                if (shadowTriangleHit(first + i, origin, direction)) return true;
            continue;
        }
#if ML_SHADOW_BVH_WIDTH == 2
        uint at = 4u * ref;
        vec4 leftMin = shadowBvh[at], leftMax = shadowBvh[at + 1u];
        vec4 rightMin = shadowBvh[at + 2u], rightMax = shadowBvh[at + 3u];
        if (shadowBoxHit(leftMin.xyz, leftMax.xyz, origin, inverse) && top < uint(ML_SHADOW_STACK)) stack[top++] = floatBitsToUint(leftMin.w);
        if (shadowBoxHit(rightMin.xyz, rightMax.xyz, origin, inverse) && top < uint(ML_SHADOW_STACK)) stack[top++] = floatBitsToUint(leftMax.w);
#else
        // Four slab tests a vec4, in the scalar test's operations (shadowBoxHit) component by component.
        uint at = uint(ML_SHADOW_BVH_WIDTH / 4 * ML_SHADOW_WIDE_GROUP_VEC4S) * ref;
        for (uint group = 0u; group < uint(ML_SHADOW_BVH_WIDTH / 4); ++group, at += uint(ML_SHADOW_WIDE_GROUP_VEC4S)) {
            vec4 t0x = (shadowBvh[at] - origin.x) * inverse.x, t1x = (shadowBvh[at + 1u] - origin.x) * inverse.x;
            vec4 t0y = (shadowBvh[at + 2u] - origin.y) * inverse.y, t1y = (shadowBvh[at + 3u] - origin.y) * inverse.y;
            vec4 t0z = (shadowBvh[at + 4u] - origin.z) * inverse.z, t1z = (shadowBvh[at + 5u] - origin.z) * inverse.z;
            vec4 enter = max(max(min(t0x, t1x), min(t0y, t1y)), max(min(t0z, t1z), vec4(0.0)));
            vec4 leave = min(min(max(t0x, t1x), max(t0y, t1y)), min(max(t0z, t1z), vec4(1.0)));
            uvec4 children = floatBitsToUint(shadowBvh[at + 6u]);
            for (int k = 0; k < 4; ++k)
                if (children[k] != 0u && enter[k] <= leave[k] && top < uint(ML_SHADOW_STACK)) stack[top++] = children[k];
        }
#endif
    }
    return false;
}

// Whether a point light at `lightPosition` is hidden from surface point s (normal n facing it).
bool pointLightShadowed(vec3 position, vec3 normal, vec3 lightPosition) {
    vec3 origin = shadowRayOrigin(position, normal);
    return shadowRayBlocked(origin, lightPosition - origin);
}

// Whether a directional light from unit direction l is hidden: the ray runs u_lightModel.y, past
// the occluders' bounds from any point inside them.
bool directionalLightShadowed(vec3 position, vec3 normal, vec3 l) {
    vec3 origin = shadowRayOrigin(position, normal);
    return shadowRayBlocked(origin, l * u_lightModel.y);
}
