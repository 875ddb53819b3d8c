#version 450 core
// The compute raster's first pass (renderer/passes/compute_raster.h): one invocation per opaque
// triangle sets it up (clip, snap, cull) and rasters it itself where it is small, a pixel at a
// time; larger ones go to the tile pass's list, and the few the compute raster cannot snap
// (a vertex at or behind the eye plane, or past the guard band) to the tile pass as homogeneous
// planes (where the GPU clips at the viewport, as llvmpipe does: to the hardware's list). In the
// id pass of two-pass atomics (ML_RASTER_PASS 1) the lists are already made: it rasters the
// small ones again and appends nothing (include/compute_raster.glsl, ClippedTriangle: the planes).
//
// With ML_RASTER_ALPHA_TEST, one texture set's alpha-tested triangles (a dispatch per set, its
// textures bound; include/compute_raster_coverage.glsl): each pixel the store would take tested
// against the material's cut-off; large ones to the alpha-tested triangles' own tile list, those
// across the eye plane or past the guard band to the hardware, through this set's list and draw.
#extension GL_ARB_gpu_shader_int64 : require
#if ML_RASTER_ATOMIC64
#extension GL_NV_shader_atomic_int64 : require
#endif
#include "include/bindings.h"
#include "include/material_features.glsl"
#include "include/frame_uniforms.glsl"
#include "include/window_depth.glsl"
#include "include/compute_raster.glsl"
#include "include/compute_raster_coverage.glsl"

layout(local_size_x = ML_RASTER_WORKGROUP) in;

#if ML_RASTER_ALPHA_TEST
uint materialBits(uint triangle) { return materials[triangleMaterial[triangle]].info.w; }
#else
layout(std430, binding = ML_SSBO_VERTICES) readonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
layout(std430, binding = ML_SSBO_INDICES) readonly buffer Indices { uint indexData[]; };
layout(std430, binding = ML_SSBO_TRIANGLE_MATERIALS) readonly buffer TriangleMaterials { uint triangleMaterial[]; };
layout(std430, binding = ML_SSBO_MATERIALS) readonly buffer Materials { uvec4 materialWords[]; };  // GpuMaterial, info at +3
vec3 vertexPosition(uint v) { return vec3(vertexData[8u * v], vertexData[8u * v + 1u], vertexData[8u * v + 2u]); }
uint materialBits(uint triangle) { return materialWords[triangleMaterial[triangle] * ML_GPU_MATERIAL_VEC4S(ML_EXTENDED_MATERIAL_RECORD) + 3u].w; }
#endif
layout(std430, binding = ML_SSBO_RASTER_WORK) coherent buffer RasterWork { uint rasterWork[]; };
layout(std430, binding = ML_SSBO_RASTER_LARGE) writeonly buffer RasterLarge { uvec4 largeTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_HARDWARE) writeonly buffer RasterHardware { uint hardwareTriangles[]; };
layout(std430, binding = ML_SSBO_RASTER_CLIPPED) writeonly buffer RasterClipped { uvec4 clippedTriangles[]; };
#if !ML_RASTER_ALPHA_TEST
layout(std430, binding = ML_SSBO_RASTER_PAIRS) writeonly buffer RasterPairs { uvec2 pairs[]; };
uniform uint u_pairCapacity;   // entries pairs holds
#include "include/compute_raster_pairs.glsl"
#endif

uniform uint u_firstTriangle;  // the triangles set up: the opaque ones (the index buffer's first),
uniform uint u_triangles;      // or one texture set's alpha-tested span
#if ML_RASTER_ALPHA_TEST
uniform uint u_hardwareDraw;   // the span's DrawArraysIndirectCommand in rasterWork; its list starts at u_firstTriangle
#endif
uniform uint u_cullBackFaces;  // --backface-culling: cull single-sided materials' back faces
uniform uint u_largeCapacity;  // entries largeTriangles holds
uniform uint u_largeFirst;     // where this program's large triangles start in it (the alpha-tested ones: after the opaque ones)
uniform uint u_clipsToViewport;  // the GPU clips triangles at the viewport's sides (no guard band: Mesa's llvmpipe)

const float kGuardBand = float(1 << (30 - 2 * ML_SUBPIXEL_BITS));  // window units either side: 64-bit edges stay exact

void toHardware(uint triangle) {
#if ML_RASTER_PASS == 0
#if ML_RASTER_ALPHA_TEST
    uint at = u_firstTriangle + atomicAdd(rasterWork[u_hardwareDraw], 3u) / 3u;
#else
    uint at = atomicAdd(rasterWork[ML_RASTER_WORK_HARDWARE_DRAW], 3u) / 3u;
#endif
    hardwareTriangles[at] = triangle;
#endif
}

// Tile bounds of the part of a triangle in front of the near plane (z >= -w): the triangle clipped
// there (Sutherland-Hodgman, at most four corners), projected. False where none of it is.
bool nearClippedTiles(vec4 c[3], out uvec2 tileLo, out uvec2 tileHi) {
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    bool any_ = false;
    for (int i = 0; i < 3; ++i) {
        vec4 a = c[i], b = c[(i + 1) % 3];
        float da = a.z + a.w, db = b.z + b.w;
        if (da >= 0.0) {
            vec2 s = a.xy / a.w;
            lo = min(lo, s);
            hi = max(hi, s);
            any_ = true;
        }
        if ((da >= 0.0) != (db >= 0.0)) {
            vec4 m = mix(a, b, da / (da - db));
            vec2 s = m.xy / max(m.w, 1e-30);
            lo = min(lo, s);
            hi = max(hi, s);
            any_ = true;
        }
    }
    if (!any_) return false;
    vec2 half_ = 0.5 * u_viewport.xy;
    ivec2 pixelLo = max(ivec2(floor(clamp(lo * half_ + half_, vec2(-1.0), u_viewport.xy + 1.0))) - 1, ivec2(0));
    ivec2 pixelHi = min(ivec2(ceil(clamp(hi * half_ + half_, vec2(-1.0), u_viewport.xy + 1.0))) + 1, ivec2(u_viewport.xy) - 1);
    if (any(greaterThan(pixelLo, pixelHi))) return false;
    tileLo = uvec2(pixelLo / ML_RASTER_TILE);
    tileHi = uvec2(pixelHi / ML_RASTER_TILE);
    return true;
}

// A triangle with a vertex at or behind the eye plane, or past the guard band, to the tile pass as
// homogeneous planes.
void toClipped(uint triangle, vec4 c0, vec4 c1, vec4 c2) {
#if ML_RASTER_PASS == 0
    ClippedTriangle h;
    bool front;
    if (!rasterHomogeneous(c0, c1, c2, h, front)) return;  // seen edge-on
    if (!front) {
        if (u_cullBackFaces != 0u && (materialBits(triangle) & ML_MATERIAL_DOUBLE_SIDED) == 0u) return;
    }
    vec4 corners[3] = vec4[](c0, c1, c2);
    uvec2 tileLo, tileHi;
    if (!nearClippedTiles(corners, tileLo, tileHi)) return;
    uint at = atomicAdd(rasterWork[ML_RASTER_WORK_CLIPPED_COUNT], 1u);
    if (at >= u_largeCapacity) return;  // as many as the scene has triangles: never
    atomicMax(rasterWork[ML_RASTER_WORK_BIN_DISPATCH], min(at + 1u, 65535u));
    clippedTriangles[5u * at] = uvec4(floatBitsToUint(h.edge0), floatBitsToUint(h.edge1.x));
    clippedTriangles[5u * at + 1u] = uvec4(floatBitsToUint(h.edge1.yz), floatBitsToUint(h.edge2.xy));
    clippedTriangles[5u * at + 2u] = uvec4(floatBitsToUint(h.edge2.z), floatBitsToUint(h.depthNumerator));
    clippedTriangles[5u * at + 3u] = uvec4(floatBitsToUint(h.depthDenominator), triangle);
    clippedTriangles[5u * at + 4u] = uvec4(rasterTileWord(tileLo, 0u), rasterTileWord(tileHi, 0u), 0u, 0u);
#endif
}

#if ML_RASTER_PASS == 0 && !ML_RASTER_ALPHA_TEST
// The tile pass's pairs of a large triangle (index `large` in the large list) binned to the 8x8
// tiles lo..hi, listed here as the binning would list them (the same tiles, in its order within
// the triangle): a count, one atomic, the pairs. Where they do not fit, to the hardware.
void binFineTiles(RasterTriangle t, uint triangle, uint large, uvec2 lo, uvec2 hi) {
    ivec2 v[3] = ivec2[](t.v0, t.v1, t.v2);
    uint tiles = 0u;
    for (uint y = lo.y; y <= hi.y; ++y)
        for (uint x = lo.x; x <= hi.x; ++x)
            if (rasterTileTouches(v, uvec2(x, y), ML_RASTER_FINE_TILE)) ++tiles;
    uint first = rasterTakePairSlots(tiles);
    if (first == ~0u) {
        toHardware(triangle);
        return;
    }
    for (uint y = lo.y; y <= hi.y; ++y)
        for (uint x = lo.x; x <= hi.x; ++x)
            if (rasterTileTouches(v, uvec2(x, y), ML_RASTER_FINE_TILE)) pairs[first++] = uvec2(large, rasterTileWord(uvec2(x, y), ML_RASTER_FINE_PAIR));
}
#endif

void main() {
    if (gl_GlobalInvocationID.x >= u_triangles) return;
    uint triangle = u_firstTriangle + gl_GlobalInvocationID.x;
    vec4 c0 = rasterClipPosition(vertexPosition(indexData[3u * triangle]));
    vec4 c1 = rasterClipPosition(vertexPosition(indexData[3u * triangle + 1u]));
    vec4 c2 = rasterClipPosition(vertexPosition(indexData[3u * triangle + 2u]));
    // Wholly outside one clip plane: nothing to draw (and nothing for the hardware either).
    if ((c0.x > c0.w && c1.x > c1.w && c2.x > c2.w) || (c0.x < -c0.w && c1.x < -c1.w && c2.x < -c2.w) ||
        (c0.y > c0.w && c1.y > c1.w && c2.y > c2.w) || (c0.y < -c0.w && c1.y < -c1.w && c2.y < -c2.w) ||
        (c0.z > c0.w && c1.z > c1.w && c2.z > c2.w) || (c0.z < 0.0 && c1.z < 0.0 && c2.z < 0.0))
        return;
    if (c0.w <= 0.0 || c1.w <= 0.0 || c2.w <= 0.0) {
        // Where the GPU clips at the viewport, to the hardware (see below); else unclipped, as
        // homogeneous planes.
        if (u_clipsToViewport != 0u || ML_RASTER_ALPHA_TEST != 0) toHardware(triangle);
        else toClipped(triangle, c0, c1, c2);
        return;
    }
    vec2 s0, s1, s2;
    vec3 z;
    rasterWindow(c0, c1, c2, s0, s1, s2, z);
    if (any(greaterThan(abs(vec4(s0, s1)), vec4(kGuardBand))) || any(greaterThan(abs(s2), vec2(kGuardBand)))) {
        // Past the guard band (a floor that reaches far beside the eye): as homogeneous planes,
        // which need no window position, where the GPU does not clip at the viewport.
        if (u_clipsToViewport != 0u || ML_RASTER_ALPHA_TEST != 0) toHardware(triangle);
        else toClipped(triangle, c0, c1, c2);
        return;
    }
    // Where the GPU clips at the viewport, the clipped triangle's edges run through re-snapped
    // vertices: a triangle that crosses a side is left to the hardware, to cover what it covers.
    if (u_clipsToViewport != 0u && (any(lessThan(min(s0, min(s1, s2)), vec2(0.0))) || any(greaterThan(max(s0, max(s1, s2)), u_viewport.xy)))) {
        toHardware(triangle);
        return;
    }
    RasterTriangle t = rasterSnap(s0, s1, s2, z);
    int64_t area = rasterArea(t);
    if (area == 0l) return;  // no pixel of a degenerate triangle is drawn
    if (area < 0l) {
        // Clockwise: a back face. Wound the other way, it covers the same pixels.
        if (u_cullBackFaces != 0u && (materialBits(triangle) & ML_MATERIAL_DOUBLE_SIDED) == 0u) return;
        t = rasterReversed(t);
    }
    ivec2 lo, hi;
    rasterPixelBounds(t, lo, hi);
    if (any(greaterThan(lo, hi))) return;
    ivec2 extent = max(t.v0, max(t.v1, t.v2)) - min(t.v0, min(t.v1, t.v2));
    ivec2 pixels = hi - lo + 1;
    if (all(lessThanEqual(extent, ivec2(ML_RASTER_SMALL_EXTENT << ML_SUBPIXEL_BITS))) &&
        pixels.x * pixels.y <= ML_RASTER_SMALL_PIXELS) {
        // Small: edges relative to v0 stay within 32 bits ((2 * 64 * 2^8)^2 < 2^31).
        ivec2 a = ivec2(0), b = t.v1 - t.v0, c = t.v2 - t.v0;
        int bias0 = ownsEdge(t.v1, t.v2) ? 1 : 0, bias1 = ownsEdge(t.v2, t.v0) ? 1 : 0, bias2 = ownsEdge(t.v0, t.v1) ? 1 : 0;
        for (int y = lo.y; y <= hi.y; ++y) {
            int py = (y << ML_SUBPIXEL_BITS) + ML_SUBPIXEL_HALF - t.v0.y;
            for (int x = lo.x; x <= hi.x; ++x) {
                int px = (x << ML_SUBPIXEL_BITS) + ML_SUBPIXEL_HALF - t.v0.x;
                int e2 = b.x * py - b.y * px;
                int e0 = (c.x - b.x) * (py - b.y) - (c.y - b.y) * (px - b.x);
                int e1 = -c.x * (py - c.y) + c.y * (px - c.x);
                if (e0 + bias0 <= 0 || e1 + bias1 <= 0 || e2 + bias2 <= 0) continue;
                float depth = rasterDepth(t, float(e0), float(e1), float(e2));
                if (isVisibleDepth(depth)) rasterStoreCovered(ivec2(x, y), depth, triangle);
            }
        }
        return;
    }
#if ML_RASTER_PASS == 0
    // Large: the tile pass rasters it, a workgroup per screen tile it overlaps.
    uint at = u_largeFirst + atomicAdd(rasterWork[ML_RASTER_LARGE_COUNT], 1u);
    if (at >= u_largeCapacity) {
        toHardware(triangle);
        return;
    }
    atomicMax(rasterWork[ML_RASTER_BIN_DISPATCH], min(at - u_largeFirst + 1u, 65535u));
    bool fine = all(lessThanEqual(pixels, ivec2(ML_RASTER_FINE_EXTENT)));
    int tile = fine ? ML_RASTER_FINE_TILE : ML_RASTER_TILE;
    ivec2 tileLo = lo / tile, tileHi = hi / tile;
    ivec2 tileExtent = tileHi - tileLo + 1;
    // A few 8x8 tiles: listed here, the binning's workgroup (and its barriers) spared.
    bool binHere = ML_RASTER_ALPHA_TEST == 0 && fine && tileExtent.x * tileExtent.y <= ML_RASTER_SETUP_BIN_TILES;
    largeTriangles[3u * at] = uvec4(uvec2(t.v0), uvec2(t.v1));
    largeTriangles[3u * at + 1u] = uvec4(uvec2(t.v2), floatBitsToUint(t.z.xy));
    largeTriangles[3u * at + 2u] = uvec4(floatBitsToUint(t.z.z), triangle, rasterTileWord(uvec2(tileLo), fine ? ML_RASTER_FINE_PAIR : 0u),
                                         rasterTileWord(uvec2(tileHi), binHere ? ML_RASTER_BINNED : 0u));
#if !ML_RASTER_ALPHA_TEST
    if (binHere) binFineTiles(t, triangle, at, uvec2(tileLo), uvec2(tileHi));
#endif
#endif
}
