// What the compute raster's setup and tile passes store at a pixel a triangle covers
// (renderer/passes/compute_raster.h). Opaque triangles: their depth and id. With
// ML_RASTER_ALPHA_TEST (one texture set's alpha-tested triangles, its textures bound): only where
// nothing nearer is in the store and the material covers the pixel, tested by the function every
// raster pass tests coverage with (triangleAlpha), so the compute raster keeps the pixels the
// hardware raster keeps, to the bit. Needs compute_raster.glsl; with ML_RASTER_ALPHA_TEST brings
// the geometry buffers (triangle_surface.glsl), without it the file declares what it reads.
#if ML_RASTER_ALPHA_TEST
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/triangle_surface.glsl"
#endif

void rasterStoreCovered(ivec2 pixel, float depth, uint triangle) {
#if ML_RASTER_ALPHA_TEST
    if (rasterHidden(pixel, depth)) return;
    Material m = materials[triangleMaterial[triangle]];
    if (!alphaCovered(m, triangleAlpha(triangle, m, pixel))) return;
#endif
    rasterStore(pixel, depth, triangle);
}
