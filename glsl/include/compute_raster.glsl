// The visibility buffer's compute raster (renderer/passes/compute_raster.h): one rule for which
// pixels a triangle covers and at what depth, shared by its small-triangle, tile and hardware
// paths, and the per-pixel store that keeps the nearest triangle.
//
// Coverage follows the hardware's rules so that every method sees the same surfaces: vertices
// snapped to the rasterizer's sub-pixel grid (ML_SUBPIXEL_BITS, GL_SUBPIXEL_BITS), a pixel
// covered where its centre lies strictly inside all three edges, or on an edge the fill rule
// owns (ML_RASTER_EDGE_RULE: 0 top-left, 1 bottom-left, in GL's y-up window coordinates), so two
// triangles that share an edge cover each pixel on it once. Depth is the window depth's plane
// at the pixel centre, clipped to [0, 1) as the near and far planes and the depth clear would.
//
// The store keeps, per pixel, the nearest depth and on equal depths the smallest triangle id,
// which is the first drawn: what GL_LESS in draw order keeps. Where the GPU has 64-bit atomics
// (ML_RASTER_ATOMIC64) depth and id are one word, resolved by one atomicMin; otherwise two
// passes: the depth's bits first (ML_RASTER_PASS 0), then the id where the depth matches
// (ML_RASTER_PASS 1). Non-negative floats order as their bits, so both compare as integers.
// Needs frame_uniforms.glsl; the file must enable GL_ARB_gpu_shader_int64 (and with
// ML_RASTER_ATOMIC64, GL_NV_shader_atomic_int64).

// The program sets these (renderer/passes/compute_raster.cpp); the defaults let the build validate it.
#ifndef ML_SUBPIXEL_BITS
#define ML_SUBPIXEL_BITS 8
#endif
#ifndef ML_RASTER_EDGE_RULE
#define ML_RASTER_EDGE_RULE 0
#endif
#ifndef ML_RASTER_ATOMIC64
#define ML_RASTER_ATOMIC64 0
#endif
#ifndef ML_RASTER_PASS
#define ML_RASTER_PASS 0
#endif

#define ML_SUBPIXEL_ONE (1 << ML_SUBPIXEL_BITS)
#define ML_SUBPIXEL_HALF (1 << (ML_SUBPIXEL_BITS - 1))

#if ML_RASTER_ATOMIC64
layout(std430, binding = ML_SSBO_RASTER_DEPTH_IDS) coherent buffer RasterDepthIds { uint64_t depthIds[]; };
#else
// Depth bits of every pixel, then the id of every pixel.
layout(std430, binding = ML_SSBO_RASTER_DEPTH_IDS) coherent buffer RasterDepthIds { uint depthIds[]; };
#endif

uint rasterPixelCount() { return uint(u_viewport.x) * uint(u_viewport.y); }

// Keeps (depth, triangle) at the pixel where it is nearer than what is there (ties: smaller id).
void rasterStore(ivec2 pixel, float depth, uint triangle) {
    uint at = uint(pixel.y) * uint(u_viewport.x) + uint(pixel.x);
#if ML_RASTER_ATOMIC64
    uint64_t word = packUint2x32(uvec2(triangle, floatBitsToUint(depth)));
    if (word < depthIds[at]) atomicMin(depthIds[at], word);
#elif ML_RASTER_PASS == 0
    uint bits = floatBitsToUint(depth);
    if (bits < depthIds[at]) atomicMin(depthIds[at], bits);
#else
    if (depthIds[at] == floatBitsToUint(depth)) atomicMin(depthIds[rasterPixelCount() + at], triangle);
#endif
}

// A triangle ready to raster: window positions snapped to the sub-pixel grid and wound
// counter-clockwise (y up), window depth at each vertex.
struct RasterTriangle {
    ivec2 v0, v1, v2;
    vec3 z;
};

// The hardware's clip position of a world-space point: scene.vert's expression, term for term.
vec4 rasterClipPosition(vec3 world) { return u_proj * vec4(mat3(u_view) * (world - u_cameraPos.xyz), 1.0); }

// Whether an edge a->b of a counter-clockwise triangle owns the pixel centres that lie on it.
bool ownsEdge(ivec2 a, ivec2 b) {
    ivec2 d = b - a;
#if ML_RASTER_EDGE_RULE == 0
    return d.y < 0 || (d.y == 0 && d.x < 0);  // left edges, and top edges (interior below)
#else
    return d.y < 0 || (d.y == 0 && d.x > 0);  // left edges, and bottom edges (interior above)
#endif
}

// The window depth plane at a pixel centre from its three edge values (e0 opposite v0, ...),
// whose sum is twice the triangle's area.
float rasterDepth(RasterTriangle t, float e0, float e1, float e2) {
    float inv = 1.0 / (e0 + e1 + e2);
    return t.z.x + (e1 * inv) * (t.z.y - t.z.x) + (e2 * inv) * (t.z.z - t.z.x);
}

// The pixel window of a triangle's snapped bounds: the pixels whose centres may be covered,
// clamped to the viewport (empty where min > max).
void rasterPixelBounds(RasterTriangle t, out ivec2 lo, out ivec2 hi) {
    ivec2 mn = min(t.v0, min(t.v1, t.v2));
    ivec2 mx = max(t.v0, max(t.v1, t.v2));
    lo = max((mn - ML_SUBPIXEL_HALF + (ML_SUBPIXEL_ONE - 1)) >> ML_SUBPIXEL_BITS, ivec2(0));
    hi = min((mx - ML_SUBPIXEL_HALF) >> ML_SUBPIXEL_BITS, ivec2(u_viewport.xy) - 1);
}

// Coverage and depth at one pixel, in 64-bit edge arithmetic (any triangle within the guard band).
bool rasterCovers64(RasterTriangle t, ivec2 pixel, out float depth) {
    i64vec2 p = i64vec2(pixel) * ML_SUBPIXEL_ONE + ML_SUBPIXEL_HALF;
    i64vec2 a = i64vec2(t.v0), b = i64vec2(t.v1), c = i64vec2(t.v2);
    int64_t e2 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);  // edge v0->v1, opposite v2
    int64_t e0 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x);  // edge v1->v2, opposite v0
    int64_t e1 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x);  // edge v2->v0, opposite v1
    if (e0 + (ownsEdge(t.v1, t.v2) ? 1l : 0l) <= 0l || e1 + (ownsEdge(t.v2, t.v0) ? 1l : 0l) <= 0l ||
        e2 + (ownsEdge(t.v0, t.v1) ? 1l : 0l) <= 0l)
        return false;
    depth = rasterDepth(t, float(e0), float(e1), float(e2));
    return depth >= 0.0 && depth < 1.0;
}
