#version 450 core
// Visibility resolve: for each pixel, the triangle id from the raster pass gives three
// vertices; the pixel-centre ray through the triangle gives perspective-correct barycentrics
// (what the rasterizer interpolates with), and the rays through the next pixel right and up
// give the UV gradients the rasterizer's 2x2 quads would. The surface is written to the
// G-buffer images, which deferred_lighting.comp then lights.
//
// Textures cannot be chosen per pixel without bindless textures, so the pass runs once per
// base-colour texture (u_textureGroup) plus once for untextured materials (-1); each pixel is
// written by exactly the one dispatch whose group is its material's.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/gbuffer_layout.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_VISIBILITY) uniform usampler2D u_visibility;
layout(std430, binding = ML_SSBO_VERTICES) readonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
layout(std430, binding = ML_SSBO_INDICES) readonly buffer Indices { uint indexData[]; };
layout(std430, binding = ML_SSBO_TRIANGLE_MATERIALS) readonly buffer TriangleMaterials { uint triangleMaterial[]; };
#if ML_GBUFFER_FLOAT_TARGETS == 0
layout(binding = ML_IMG_GBUFFER0, rgba32ui) uniform writeonly uimage2D u_gPackedOut;
#else
layout(binding = ML_IMG_GBUFFER0, rgba16f) uniform writeonly image2D u_gTarget0Out;
layout(binding = ML_IMG_GBUFFER1, rgba16f) uniform writeonly image2D u_gTarget1Out;
#if ML_GBUFFER_FLOAT_TARGETS == 3
layout(binding = ML_IMG_GBUFFER2, rgba16f) uniform writeonly image2D u_gTarget2Out;
#endif
#endif
uniform int u_textureGroup;

void storeGBuffer(ivec2 p, GBufferTexel t) {
#if ML_GBUFFER_FLOAT_TARGETS == 0
    imageStore(u_gPackedOut, p, t.bits);
#else
    imageStore(u_gTarget0Out, p, t.target[0]);
    imageStore(u_gTarget1Out, p, t.target[1]);
#if ML_GBUFFER_FLOAT_TARGETS == 3
    imageStore(u_gTarget2Out, p, t.target[2]);
#endif
#endif
}

vec3 vertexPosition(uint v) { return vec3(vertexData[8u * v], vertexData[8u * v + 1u], vertexData[8u * v + 2u]); }
vec3 vertexNormal(uint v) { return vec3(vertexData[8u * v + 3u], vertexData[8u * v + 4u], vertexData[8u * v + 5u]); }
vec2 vertexUv(uint v) { return vec2(vertexData[8u * v + 6u], vertexData[8u * v + 7u]); }

// World-space ray through a window position.
void pixelRay(vec2 windowPos, out vec3 origin, out vec3 direction) {
    vec2 ndc = windowPos * u_viewport.zw * 2.0 - 1.0;
    vec4 farView = u_invProj * vec4(ndc, 1.0, 1.0);
    vec3 dirView = farView.xyz / farView.w;
    origin = u_cameraPos.xyz;
    direction = normalize(mat3(u_invView) * dirView);
}

// Barycentrics (b1, b2) of the ray's hit on the triangle's plane (Moller-Trumbore, unclipped).
vec2 rayBarycentrics(vec3 origin, vec3 direction, vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    vec3 pv = cross(direction, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-20) return vec2(1.0 / 3.0);
    float inv = 1.0 / det;
    vec3 tv = origin - p0;
    vec3 qv = cross(tv, e1);
    return vec2(dot(tv, pv), dot(direction, qv)) * inv;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    uint id = texelFetch(u_visibility, p, 0).r;
    if (id == 0u) return;
    uint triangle = id - 1u;
    uint materialIndex = triangleMaterial[triangle];
    Material m = materials[materialIndex];
    int group = m.params.z > 0.5 ? int(m.params.w) : -1;
    if (group != u_textureGroup) return;

    uint i0 = indexData[3u * triangle], i1 = indexData[3u * triangle + 1u], i2 = indexData[3u * triangle + 2u];
    vec3 p0 = vertexPosition(i0), p1 = vertexPosition(i1), p2 = vertexPosition(i2);
    vec3 origin, direction;
    pixelRay(vec2(p) + 0.5, origin, direction);
    vec2 b = rayBarycentrics(origin, direction, p0, p1, p2);
    vec3 w = vec3(1.0 - b.x - b.y, b.x, b.y);

    SurfacePoint s;
    s.normal = normalize(w.x * vertexNormal(i0) + w.y * vertexNormal(i1) + w.z * vertexNormal(i2));
    vec4 base = m.baseColorFactor;
    if (group >= 0) {
        vec2 uv0 = vertexUv(i0), uv1 = vertexUv(i1), uv2 = vertexUv(i2);
        vec2 uv = w.x * uv0 + w.y * uv1 + w.z * uv2;
        // Gradients as a rasterizer's 2x2 quad takes them (coarse): differences across the
        // quad's first row and column, the triangle's plane extended past its edges.
        vec2 quad = vec2(p & ~1) + 0.5;
        vec2 uvq[3];
        for (int k = 0; k < 3; ++k) {
            pixelRay(quad + vec2(k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0), origin, direction);
            vec2 bq = rayBarycentrics(origin, direction, p0, p1, p2);
            uvq[k] = (1.0 - bq.x - bq.y) * uv0 + bq.x * uv1 + bq.y * uv2;
        }
        base *= textureGrad(u_baseColorTexture, uv, uvq[1] - uvq[0], uvq[2] - uvq[0]);
    }
    s.albedo = base.rgb;
    s.specularStrength = m.params.x;
    s.shininess = m.params.y;
    storeGBuffer(p, encodeGBuffer(s));
}
