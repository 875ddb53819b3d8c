#version 450 core
// Visibility resolve: for each pixel, the triangle id from the raster pass gives the surface
// (include/triangle_surface.glsl rebuilds it as the rasterizer would have interpolated it),
// written to the G-buffer images, which deferred_lighting.comp then lights.
//
// Textures cannot be chosen per pixel without bindless textures, so the pass runs once per
// texture set (the textures a material binds, SceneGpu's grouping; u_textureSet) plus once for
// untextured materials (-1); each pixel is written by exactly the one dispatch whose set is its
// material's. Each dispatch visits the 8x8 tiles visibility_classify.comp listed for its set
// (a workgroup per tile), or, where a scene has more sets than a tile's mask holds, the screen.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/triangle_surface.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_VISIBILITY) uniform usampler2D u_visibility;
#if ML_GBUFFER_FLOAT_TARGETS == 0
layout(binding = ML_IMG_GBUFFER0, rgba32ui) uniform writeonly uimage2D u_gPackedOut;
#else
layout(binding = ML_IMG_GBUFFER0, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget0Out;
layout(binding = ML_IMG_GBUFFER1, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget1Out;
#if ML_GBUFFER_FLOAT_TARGETS >= 3
layout(binding = ML_IMG_GBUFFER2, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget2Out;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
layout(binding = ML_IMG_GBUFFER3, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget3Out;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
layout(binding = ML_IMG_GBUFFER4, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget4Out;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
layout(binding = ML_IMG_GBUFFER5, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget5Out;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
layout(binding = ML_IMG_GBUFFER6, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget6Out;
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
layout(binding = ML_IMG_GBUFFER7, ML_GBUFFER_FLOAT_IMAGE) uniform writeonly image2D u_gTarget7Out;
#endif
#endif
uniform int u_textureSet;
uniform uint u_tileLists;  // 1: a workgroup per tile of the set's list; 0: the whole screen
uniform uint u_tileCount;  // tiles on screen (each slot's list holds up to this many)
uniform uint u_tilesX;
layout(std430, binding = ML_SSBO_RESOLVE_TILES) readonly buffer ResolveTiles { uint resolveTiles[]; };

ivec2 resolvedPixel() {
    if (u_tileLists == 0u) return ivec2(gl_GlobalInvocationID.xy);
    uint tile = resolveTiles[uint(u_textureSet + 1) * u_tileCount + gl_WorkGroupID.x];
    return ivec2(tile % u_tilesX, tile / u_tilesX) * ML_SCREEN_TILE + ivec2(gl_LocalInvocationID.xy);
}

void storeGBuffer(ivec2 p, GBufferTexel t) {
#if ML_GBUFFER_FLOAT_TARGETS == 0
    imageStore(u_gPackedOut, p, t.bits);
#else
    imageStore(u_gTarget0Out, p, t.target[0]);
    imageStore(u_gTarget1Out, p, t.target[1]);
#if ML_GBUFFER_FLOAT_TARGETS >= 3
    if (gbufferUsesTarget2(t)) imageStore(u_gTarget2Out, p, t.target[2]);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
    if (gbufferUsesTarget3(t)) imageStore(u_gTarget3Out, p, t.target[3]);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
    if (gbufferUsesTarget4(t)) imageStore(u_gTarget4Out, p, t.target[4]);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
    if (gbufferUsesTarget5(t)) imageStore(u_gTarget5Out, p, t.target[5]);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
    if (gbufferUsesTarget6(t)) imageStore(u_gTarget6Out, p, t.target[6]);
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
    if (gbufferUsesTarget7(t)) imageStore(u_gTarget7Out, p, t.target[7]);
#endif
#endif
}

void main() {
    ivec2 p = resolvedPixel();
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    uint id = texelFetch(u_visibility, p, 0).r;
    if (id == 0u) return;
    uint triangle = id - 1u;
    uint materialIndex = triangleMaterial[triangle];
    Material m = materials[materialIndex];
    int textureSet = int(m.info.z) - 1;
    if (textureSet != u_textureSet) return;

    // The G-buffer stores no position (the lighting rebuilds it from depth) nor alpha.
    float alpha;
    SurfacePoint s = triangleSurface(triangle, m, p, alpha);
    storeGBuffer(p, encodeGBuffer(s));
}
