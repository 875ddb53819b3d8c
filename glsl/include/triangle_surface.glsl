// A surface rebuilt from a triangle id and a pixel, as a rasterizer would have interpolated it
// there: by the visibility resolve (the opaque pixel's nearest triangle), the transparent pass's
// shading (each captured glass fragment), and, for the texture coordinates, every raster pass
// (scene_fragment.glsl), so that every method reads its textures at the same coordinates. The
// pixel-centre ray through the triangle gives perspective-correct barycentrics (what the
// rasterizer interpolates with), and the rays through the pixel's quad give the UV gradients a
// rasterizer's coarse derivatives would. A rasterizer's own interpolation differs from the ray in
// the last bits, and texture filtering quantizes its weights (8 bits of sub-texel position on
// llvmpipe and NVIDIA), so a last-bit difference in UV moves a glossy normal-mapped highlight:
// hence one computation for all (docs/accuracy-and-stability.md). `precise` keeps it the same
// bits in a fragment and a compute shader. The optional vertex streams (tangents, TEXCOORD_1,
// COLOR_0) are read only where the scene has them (ML_MATERIAL_FEATURES). Needs frame_uniforms,
// shading and material.
layout(std430, binding = ML_SSBO_VERTICES) readonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
layout(std430, binding = ML_SSBO_INDICES) readonly buffer Indices { uint indexData[]; };
layout(std430, binding = ML_SSBO_TRIANGLE_MATERIALS) readonly buffer TriangleMaterials { uint triangleMaterial[]; };
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
layout(std430, binding = ML_SSBO_VERTEX_TANGENTS) readonly buffer VertexTangents { vec4 vertexTangent[]; };
#endif
#if ML_HAS(ML_FEATURE_UV1)
layout(std430, binding = ML_SSBO_VERTEX_UV1) readonly buffer VertexUv1 { vec2 vertexUv1[]; };
#endif
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
layout(std430, binding = ML_SSBO_VERTEX_COLORS) readonly buffer VertexColors { vec4 vertexColor[]; };
#endif

vec3 vertexPosition(uint v) { return vec3(vertexData[8u * v], vertexData[8u * v + 1u], vertexData[8u * v + 2u]); }
vec3 vertexNormal(uint v) { return vec3(vertexData[8u * v + 3u], vertexData[8u * v + 4u], vertexData[8u * v + 5u]); }
vec2 vertexUv(uint v) { return vec2(vertexData[8u * v + 6u], vertexData[8u * v + 7u]); }

#include "include/pixel_ray.glsl"

// Barycentrics (b1, b2) of the ray's hit on the triangle's plane and the distance t along the
// (unit) ray to it (Moller-Trumbore, unclipped).
vec3 rayHit(vec3 origin, vec3 direction, vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    vec3 pv = cross(direction, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-20) return vec3(1.0 / 3.0, 1.0 / 3.0, dot(p0 - origin, direction));
    float inv = 1.0 / det;
    vec3 tv = origin - p0;
    vec3 qv = cross(tv, e1);
    precise vec3 bt = vec3(dot(tv, pv), dot(direction, qv), dot(e2, qv)) * inv;
    return bt;
}

// A vertex attribute at the pixel centre (w) and its differences across the pixel's 2x2 quad
// (the rows wq[1] - wq[0] and wq[2] - wq[0]), as a rasterizer's coarse derivatives take them.
void interpolateCoords(vec2 a0, vec2 a1, vec2 a2, vec3 w, vec3 wq[3], out vec2 value, out vec2 dx, out vec2 dy) {
    precise vec2 v = w.x * a0 + w.y * a1 + w.z * a2;
    precise vec2 q0 = wq[0].x * a0 + wq[0].y * a1 + wq[0].z * a2;
    precise vec2 gx = wq[1].x * a0 + wq[1].y * a1 + wq[1].z * a2 - q0;
    precise vec2 gy = wq[2].x * a0 + wq[2].y * a1 + wq[2].z * a2 - q0;
    value = v;
    dx = gx;
    dy = gy;
}

// Where pixel p's centre ray meets `triangle`: its vertices, the perspective-correct
// barycentrics there (w) and at the pixel's 2x2 quad (wq, for gradients as a rasterizer's coarse
// derivatives take them: differences across the quad's first row and column, the triangle's plane
// extended past its edges; computed only where `gradients`).
struct TriangleHit {
    uint i0, i1, i2;
    vec3 p0, p1, p2;
    vec3 w;
    vec3 wq[3];
    float t;  // distance along the pixel-centre ray
};

TriangleHit triangleHit(uint triangle, ivec2 p, bool gradients) {
    TriangleHit h;
    h.i0 = indexData[3u * triangle];
    h.i1 = indexData[3u * triangle + 1u];
    h.i2 = indexData[3u * triangle + 2u];
    h.p0 = vertexPosition(h.i0);
    h.p1 = vertexPosition(h.i1);
    h.p2 = vertexPosition(h.i2);
    vec3 origin, direction;
    pixelRay(vec2(p) + 0.5, origin, direction);
    vec3 bt = rayHit(origin, direction, h.p0, h.p1, h.p2);
    h.w = vec3(1.0 - bt.x - bt.y, bt.x, bt.y);
    h.t = bt.z;
    h.wq = vec3[3](h.w, h.w, h.w);
    if (gradients) {
        vec2 quad = vec2(p & ~1) + 0.5;
        for (int k = 0; k < 3; ++k) {
            pixelRay(quad + vec2(k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0), origin, direction);
            vec2 bq = rayHit(origin, direction, h.p0, h.p1, h.p2).xy;
            h.wq[k] = vec3(1.0 - bq.x - bq.y, bq.x, bq.y);
        }
    }
    return h;
}

// The texture coordinates and their gradients at the hit: what every texture read of every
// method takes (material.glsl says why), so all of them sample alike to the last bit.
MaterialCoords triangleCoords(TriangleHit h) {
    MaterialCoords c;
    interpolateCoords(vertexUv(h.i0), vertexUv(h.i1), vertexUv(h.i2), h.w, h.wq, c.uv[0], c.dx[0], c.dy[0]);
#if ML_HAS(ML_FEATURE_UV1)
    interpolateCoords(vertexUv1[h.i0], vertexUv1[h.i1], vertexUv1[h.i2], h.w, h.wq, c.uv[1], c.dx[1], c.dy[1]);
#else
    c.uv[1] = c.uv[0];
    c.dx[1] = c.dx[0];
    c.dy[1] = c.dy[0];
#endif
    return c;
}

// The vertex colour (COLOR_0) at the hit; white where the scene has none.
vec4 triangleVertexColor(TriangleHit h) {
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
    return h.w.x * vertexColor[h.i0] + h.w.y * vertexColor[h.i1] + h.w.z * vertexColor[h.i2];
#else
    return vec4(1.0);
#endif
}

// The base colour's alpha of `triangle` (material m) at pixel p, in [0, 1]: what an alpha test
// compares with the cut-off (triangleSurface gives the same).
float triangleAlpha(uint triangle, Material m, ivec2 p) {
    TriangleHit h = triangleHit(triangle, p, m.info.z != 0u);
    return clamp(materialBaseColor(m, triangleCoords(h), triangleVertexColor(h)).a, 0.0, 1.0);
}

// The surface of `triangle` (material m) seen through pixel p, and its base colour's alpha.
// The position is the ray's hit (pixel_ray.glsl's pixelRayPoint, which the exact G-buffer layout
// rebuilds to the bit); the rest is the vertices' interpolation there, as a rasterizer's varyings.
SurfacePoint triangleSurface(uint triangle, Material m, ivec2 p, out float alpha) {
    TriangleHit h = triangleHit(triangle, p, m.info.z != 0u);
    vec3 w = h.w;
    MaterialCoords c = triangleCoords(h);
    vec4 color = triangleVertexColor(h);
    vec4 tangent = vec4(1.0, 0.0, 0.0, 1.0);
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
    tangent = w.x * vertexTangent[h.i0] + w.y * vertexTangent[h.i1] + w.z * vertexTangent[h.i2];
#endif
    vec3 normal = w.x * vertexNormal(h.i0) + w.y * vertexNormal(h.i1) + w.z * vertexNormal(h.i2);
    vec3 position = pixelRayPoint(vec2(p) + 0.5, h.t);
    vec4 base = materialBaseColor(m, c, color);
    alpha = clamp(base.a, 0.0, 1.0);
    SurfacePoint s = surfaceFromMaterial(m, position, normal, tangent, base, c);
    s.rayDistance = h.t;
    return s;
}
