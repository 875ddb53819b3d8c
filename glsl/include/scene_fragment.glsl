// The fragment side of scene.vert: its outputs, and the material's surface at this fragment,
// rebuilt from the fragment's triangle and pixel exactly as the visibility resolve rebuilds it
// (include/triangle_surface.glsl says why), so every method shades the same surface to the last
// bit. Needs material.glsl. With ML_ALPHA_TEST (the program variant for alpha-tested draw ranges,
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

layout(location = 0) in vec3 v_worldPos;  // where the fragment is for the cluster grid, not for shading
layout(location = 3) flat in uint v_materialIndex;
layout(location = 4) flat in uint v_firstTriangle;  // the draw range's first triangle

uint fragmentTriangle() { return v_firstTriangle + uint(gl_PrimitiveID); }

// Coverage only, for passes that write no colour (depth pre-pass, visibility raster).
void alphaTestFragment() {
#if ML_ALPHA_TEST
    Material m = materials[v_materialIndex];
    if (!alphaCovered(m, triangleAlpha(fragmentTriangle(), m, ivec2(gl_FragCoord.xy)))) discard;
#endif
}

// The surface, and its coverage alpha (what a transparent pass blends with).
SurfacePoint fragmentSurfaceAndAlpha(out float alpha) {
    Material m = materials[v_materialIndex];
    SurfacePoint s = triangleSurface(fragmentTriangle(), m, ivec2(gl_FragCoord.xy), alpha);
#if ML_ALPHA_TEST
    if (!alphaCovered(m, alpha)) discard;
#endif
    return s;
}

SurfacePoint fragmentSurface() {
    float alpha;
    return fragmentSurfaceAndAlpha(alpha);
}
