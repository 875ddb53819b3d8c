// The fragment side of scene.vert: its outputs, and the material's surface at this fragment.
// Needs material.glsl. With ML_ALPHA_TEST (the program variant for alpha-tested draw ranges,
// renderer/scene/raster_program.h) fragments outside the material's coverage are discarded; opaque
// ranges are drawn without it and keep early depth testing. With ML_TRANSPARENT (the transparent
// pass, renderer/passes/transparent_pass.h) the shading passes write the surface's alpha for blending.
#include "include/triangle_surface.glsl"

#ifndef ML_ALPHA_TEST
#define ML_ALPHA_TEST 0
#endif
#ifndef ML_TRANSPARENT
#define ML_TRANSPARENT 0
#endif

layout(location = 0) in vec3 v_worldPos;
layout(location = 1) in vec3 v_worldNormal;
layout(location = 3) flat in uint v_materialIndex;
layout(location = 4) flat in uint v_firstTriangle;  // the draw range's first triangle
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
layout(location = 5) in vec4 v_tangent;
#endif
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
layout(location = 7) in vec4 v_color;
#endif

// The fragment's texture coordinates, rebuilt from its triangle as the visibility resolve does
// (triangle_surface.glsl says why); a material without textures reads none.
MaterialCoords fragmentCoords(Material m) {
    MaterialCoords c;
    if (m.info.x == 0u) {
        c.uv[0] = c.uv[1] = c.dx[0] = c.dx[1] = c.dy[0] = c.dy[1] = vec2(0.0);
        return c;
    }
    return triangleCoords(triangleHit(v_firstTriangle + uint(gl_PrimitiveID), ivec2(gl_FragCoord.xy), true));
}

vec4 fragmentVertexColor() {
#if ML_HAS(ML_FEATURE_VERTEX_COLOR)
    return v_color;
#else
    return vec4(1.0);
#endif
}

vec4 fragmentTangent() {
#if ML_HAS(ML_FEATURE_NORMAL_MAP)
    return v_tangent;
#else
    return vec4(1.0, 0.0, 0.0, 1.0);
#endif
}

// Coverage only, for passes that write no colour (depth pre-pass, visibility raster).
void alphaTestFragment() {
#if ML_ALPHA_TEST
    Material m = materials[v_materialIndex];
    if (!alphaCovered(m, materialBaseColor(m, fragmentCoords(m), fragmentVertexColor()).a)) discard;
#endif
}

// The surface, and its coverage alpha (what a transparent pass blends with).
SurfacePoint fragmentSurfaceAndAlpha(out float alpha) {
    Material m = materials[v_materialIndex];
    MaterialCoords c = fragmentCoords(m);
    vec4 base = materialBaseColor(m, c, fragmentVertexColor());
#if ML_ALPHA_TEST
    if (!alphaCovered(m, base.a)) discard;
#endif
    alpha = clamp(base.a, 0.0, 1.0);
    return surfaceFromMaterial(m, v_worldPos, v_worldNormal, fragmentTangent(), base, c);
}

SurfacePoint fragmentSurface() {
    float alpha;
    return fragmentSurfaceAndAlpha(alpha);
}
