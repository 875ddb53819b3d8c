// The visibility buffer's compute raster (renderer/passes/compute_raster.h): one rule for which
// pixels a triangle covers and at what depth, shared by its small-triangle, tile and hardware
// paths, and the per-pixel store that keeps the nearest triangle.
//
// Coverage follows the hardware's rules so that every method sees the same surfaces: vertices
// snapped to the rasterizer's sub-pixel grid (ML_SUBPIXEL_BITS, GL_SUBPIXEL_BITS), a pixel
// covered where its centre lies strictly inside all three edges, or on an edge the fill rule
// owns (ML_RASTER_EDGE_RULE: 0 top-left, 1 bottom-left, in GL's y-up window coordinates), so two
// triangles that share an edge cover each pixel on it once. Depth is the window depth's plane
// at the pixel centre, clipped to (0, 1] as the far and near planes and the depth clear would
// (the depth is reversed: include/window_depth.glsl).
//
// The store keeps, per pixel, the nearest depth and on equal depths the smallest triangle id,
// which is the first drawn: what the depth test (GL_GREATER) in draw order keeps. It holds each
// depth as a key that grows with distance: the depth's bits inverted, in 31 bits (non-negative
// floats order as their bits), so the nearest is the smallest key. Where the GPU has 64-bit
// atomics (ML_RASTER_ATOMIC64) key and id are one word, resolved by one atomicMin; otherwise two
// passes: the key first (ML_RASTER_PASS 0), then the id where the key matches (ML_RASTER_PASS 1).
//
// The store is not reset between frames. Every other frame (u_storeFlip ~0u) it holds each word
// inverted and resolves by atomicMax: a word of the frame before then has its top bit on the
// other side of every word this frame writes, and loses to it. The finish sets the pixels this
// frame left to ML_RASTER_STORE_EMPTY, which loses to a word of either order, so no word older
// than the frame before is ever read: it writes only those, not the whole store.
// Needs frame_uniforms.glsl and window_depth.glsl; the file must enable
// GL_ARB_gpu_shader_int64 (and with ML_RASTER_ATOMIC64, GL_NV_shader_atomic_int64).

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

#ifndef ML_RASTER_ALPHA_TEST
#define ML_RASTER_ALPHA_TEST 0
#endif

// The lists a program appends to and reads: the opaque triangles' or the alpha-tested ones'
// (ML_RASTER_ALPHA_TEST: their own counters, their large triangles after the opaque ones').
#if ML_RASTER_ALPHA_TEST
#define ML_RASTER_LARGE_COUNT ML_RASTER_WORK_ALPHA_LARGE_COUNT
#define ML_RASTER_PAIR_COUNT ML_RASTER_WORK_ALPHA_PAIR_COUNT
#define ML_RASTER_PAIR_END ML_RASTER_WORK_ALPHA_PAIR_END
#define ML_RASTER_BIN_DISPATCH ML_RASTER_WORK_ALPHA_BIN_DISPATCH
#define ML_RASTER_TILE_DISPATCH ML_RASTER_WORK_ALPHA_TILE_DISPATCH
#else
#define ML_RASTER_LARGE_COUNT ML_RASTER_WORK_LARGE_COUNT
#define ML_RASTER_PAIR_COUNT ML_RASTER_WORK_PAIR_COUNT
#define ML_RASTER_PAIR_END ML_RASTER_WORK_PAIR_END
#define ML_RASTER_BIN_DISPATCH ML_RASTER_WORK_BIN_DISPATCH
#define ML_RASTER_TILE_DISPATCH ML_RASTER_WORK_TILE_DISPATCH
#endif

#define ML_SUBPIXEL_ONE (1 << ML_SUBPIXEL_BITS)
#define ML_SUBPIXEL_HALF (1 << (ML_SUBPIXEL_BITS - 1))

#if ML_RASTER_ATOMIC64
layout(std430, binding = ML_SSBO_RASTER_DEPTH_IDS) coherent buffer RasterDepthIds { uint64_t depthIds[]; };
#else
// Depth bits of every pixel, then the id of every pixel.
layout(std430, binding = ML_SSBO_RASTER_DEPTH_IDS) coherent buffer RasterDepthIds { uint depthIds[]; };
#endif

uniform uint u_storeFlip;  // 0, or ~0u on the frames whose store words are inverted

uint rasterPixelCount() { return uint(u_viewport.x) * uint(u_viewport.y); }

// A depth's key in the store (smaller: nearer), and back. A drawn depth lies in (0, 1], so its key
// is below ML_RASTER_STORE_EMPTY, which reads as the background's depth 0.
uint rasterDepthKey(float depth) { return ~floatBitsToUint(depth) & 0x7fffffffu; }
float rasterKeyDepth(uint key) { return uintBitsToFloat(~key & 0x7fffffffu); }

// A store word as this frame orders it (the words of another frame: past every key and id).
#if ML_RASTER_ATOMIC64
uint64_t rasterStoreWord(uint at) { return depthIds[at] ^ packUint2x32(uvec2(u_storeFlip)); }
#else
uint rasterStoreWord(uint at) { return depthIds[at] ^ u_storeFlip; }
#endif

// Keeps (depth, triangle) at the pixel where it is nearer than what is there (ties: smaller id).
void rasterStore(ivec2 pixel, float depth, uint triangle) {
    uint at = uint(pixel.y) * uint(u_viewport.x) + uint(pixel.x);
#if ML_RASTER_ATOMIC64
    uint64_t word = packUint2x32(uvec2(triangle, rasterDepthKey(depth)));
    if (word >= rasterStoreWord(at)) return;
    if (u_storeFlip != 0u) atomicMax(depthIds[at], ~word);
    else atomicMin(depthIds[at], word);
#elif ML_RASTER_PASS == 0
    uint key = rasterDepthKey(depth);
    if (key >= rasterStoreWord(at)) return;
    if (u_storeFlip != 0u) atomicMax(depthIds[at], ~key);
    else atomicMin(depthIds[at], key);
#else
    if (rasterStoreWord(at) != rasterDepthKey(depth)) return;
    at += rasterPixelCount();
    if (u_storeFlip != 0u) atomicMax(depthIds[at], ~triangle);
    else atomicMin(depthIds[at], triangle);
#endif
}

// Whether the store already holds a nearer depth at the pixel than `depth` (the depth pass), or
// another depth than it (the id pass): a fragment the store will not take, tested before its
// costlier work (the hardware's share: an alpha test's texture read).
bool rasterHidden(ivec2 pixel, float depth) {
    uint at = uint(pixel.y) * uint(u_viewport.x) + uint(pixel.x);
#if ML_RASTER_ATOMIC64
    return unpackUint2x32(rasterStoreWord(at)).y < rasterDepthKey(depth);
#elif ML_RASTER_PASS == 0
    return rasterStoreWord(at) < rasterDepthKey(depth);
#else
    return rasterStoreWord(at) != rasterDepthKey(depth);
#endif
}

// A triangle ready to raster: window positions snapped to the sub-pixel grid and wound
// counter-clockwise (y up), window depth at each vertex.
struct RasterTriangle {
    ivec2 v0, v1, v2;
    vec3 z;
};

// The hardware's clip position of a world-space point: scene.vert's expression, term for term.
// `precise`, so that both programs of two-pass atomics set a triangle up to the same bits.
vec4 rasterClipPosition(vec3 world) {
    precise vec4 clip = u_proj * vec4(mat3(u_view) * (world - u_cameraPos.xyz), 1.0);
    return clip;
}

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
// whose sum is twice the triangle's area. `precise`: two-pass atomics compare the depth of the
// id pass with the depth pass's to the bit, from programs compiled apart.
float rasterDepth(RasterTriangle t, float e0, float e1, float e2) {
    precise float inv = 1.0 / (e0 + e1 + e2);
    precise float depth = t.z.x + (e1 * inv) * (t.z.y - t.z.x) + (e2 * inv) * (t.z.z - t.z.x);
    return depth;
}

// The pixel window of a triangle's snapped bounds: the pixels whose centres may be covered,
// clamped to the viewport (empty where min > max).
void rasterPixelBounds(RasterTriangle t, out ivec2 lo, out ivec2 hi) {
    ivec2 mn = min(t.v0, min(t.v1, t.v2));
    ivec2 mx = max(t.v0, max(t.v1, t.v2));
    lo = max((mn - ML_SUBPIXEL_HALF + (ML_SUBPIXEL_ONE - 1)) >> ML_SUBPIXEL_BITS, ivec2(0));
    hi = min((mx - ML_SUBPIXEL_HALF) >> ML_SUBPIXEL_BITS, ivec2(u_viewport.xy) - 1);
}

// Window positions (pixels) and depths of a triangle's clip positions, every w > 0.
void rasterWindow(vec4 c0, vec4 c1, vec4 c2, out vec2 s0, out vec2 s1, out vec2 s2, out vec3 z) {
    vec2 half_ = 0.5 * u_viewport.xy;
    precise vec3 w0 = c0.xyz / c0.w, w1 = c1.xyz / c1.w, w2 = c2.xyz / c2.w;
    precise vec2 p0 = w0.xy * half_ + half_, p1 = w1.xy * half_ + half_, p2 = w2.xy * half_ + half_;
    precise vec3 depth = vec3(w0.z, w1.z, w2.z);  // clip depth in [0, 1] is the window depth
    s0 = p0;
    s1 = p1;
    s2 = p2;
    z = depth;
}

// Snapped to the sub-pixel grid, in the winding given.
RasterTriangle rasterSnap(vec2 s0, vec2 s1, vec2 s2, vec3 z) {
    RasterTriangle t;
    t.v0 = ivec2(roundEven(s0 * float(ML_SUBPIXEL_ONE)));
    t.v1 = ivec2(roundEven(s1 * float(ML_SUBPIXEL_ONE)));
    t.v2 = ivec2(roundEven(s2 * float(ML_SUBPIXEL_ONE)));
    t.z = z;
    return t;
}

// Twice the signed area (positive: counter-clockwise, a front face).
int64_t rasterArea(RasterTriangle t) {
    return int64_t(t.v1.x - t.v0.x) * int64_t(t.v2.y - t.v0.y) - int64_t(t.v1.y - t.v0.y) * int64_t(t.v2.x - t.v0.x);
}

// The same triangle wound the other way: it covers the same pixels.
RasterTriangle rasterReversed(RasterTriangle t) {
    RasterTriangle r = t;
    r.v1 = t.v2;
    r.v2 = t.v1;
    r.z = t.z.xzy;
    return r;
}

// Coverage and depth at one pixel, in 64-bit edge arithmetic (any triangle within the guard band).
// The three edge values at a pixel centre (e0 opposite v0, ...), exact in 64 bits. Within the
// guard band every difference of two snapped positions (a pixel centre's among them) fits 32
// bits, so each product is of two 32-bit integers widened: one 32x32 -> 64-bit multiply, where
// 64-bit operands would take a full 64-bit one (the tile pass's invocations spend most of their
// time here: docs/bench/nvidia-h200/raster-tiles/).
int64_t rasterWideProduct(int x, int y) { return int64_t(x) * int64_t(y); }

// The value of the edge a->b at the sub-pixel position p (positive to its left: inside a
// counter-clockwise triangle).
int64_t rasterEdge64(ivec2 a, ivec2 b, ivec2 p) {
    ivec2 d = b - a, pa = p - a;
    return rasterWideProduct(d.x, pa.y) - rasterWideProduct(d.y, pa.x);
}

// A pixel centre's sub-pixel position.
ivec2 rasterPixelCentre(ivec2 pixel) { return pixel * ML_SUBPIXEL_ONE + ML_SUBPIXEL_HALF; }

// A tile word, as pairs and tile bounds hold a tile: x in bits 0-14, y in 16-31, and bit 15 a
// flag (ML_RASTER_FINE_PAIR: an 8x8 tile; ML_RASTER_BINNED on a record's upper bound).
uint rasterTileWord(uvec2 tile, uint flag) { return tile.x | flag | (tile.y << 16); }
uvec2 rasterWordTile(uint word) { return uvec2(word & ML_RASTER_PAIR_TILE_X, word >> 16); }

// Whether a screen tile (`size` pixels a side) may hold pixels of the triangle (wound
// counter-clockwise): no edge has every pixel centre of the tile outside it. Edges are linear, so
// an edge's largest value over the tile is at the corner its gradient points to: one value an edge.
bool rasterTileTouches(ivec2 v[3], uvec2 tile, int size) {
    ivec2 lo = ivec2(tile) * size, hi = lo + (size - 1);
    for (int k = 0; k < 3; ++k) {
        // Edge a->b: its value grows with x where d.y < 0 and with y where d.x > 0.
        ivec2 a = v[k], b = v[(k + 1) % 3], d = b - a;
        ivec2 corner = ivec2(d.y < 0 ? hi.x : lo.x, d.x > 0 ? hi.y : lo.y);
        if (rasterEdge64(a, b, rasterPixelCentre(corner)) < 0l) return false;
    }
    return true;
}

i64vec3 rasterEdges64(RasterTriangle t, ivec2 pixel) {
    ivec2 p = rasterPixelCentre(pixel);
    // e0 is the edge opposite v0 (v1->v2), and so on.
    return i64vec3(rasterEdge64(t.v1, t.v2, p), rasterEdge64(t.v2, t.v0, p), rasterEdge64(t.v0, t.v1, p));
}

// What rasterEdges64 adds when the pixel moves one row up: each edge's value is linear in the
// pixel centre, so rows stepped to are exact.
i64vec3 rasterEdgeStepsY(RasterTriangle t) {
    return i64vec3(t.v2.x - t.v1.x, t.v0.x - t.v2.x, t.v1.x - t.v0.x) * int64_t(ML_SUBPIXEL_ONE);
}

// Coverage and depth at a pixel centre from its edge values (rasterEdges64's).
bool rasterCoversEdges(RasterTriangle t, i64vec3 e, out float depth) {
    int64_t e0 = e.x, e1 = e.y, e2 = e.z;
    if (e0 + (ownsEdge(t.v1, t.v2) ? 1l : 0l) <= 0l || e1 + (ownsEdge(t.v2, t.v0) ? 1l : 0l) <= 0l ||
        e2 + (ownsEdge(t.v0, t.v1) ? 1l : 0l) <= 0l)
        return false;
    depth = rasterDepth(t, float(e0), float(e1), float(e2));
    return isVisibleDepth(depth);
}

// A triangle that crosses the eye plane, rastered without clipping (Olano and Greer's homogeneous
// rasterization): with V_i = (X_i, Y_i, W_i) its vertices' clip positions scaled to the viewport,
// a pixel p = (x, y, 1) has e_i = p . (V_j x V_k) = b_i det(V) / w, b its barycentrics on the
// triangle and w its clip w; so p is covered where every e_i, signed by det(V), is positive (the
// visible part, w > 0), and its clip depth is (e . z) / (e . W). The planes are stored signed.
struct ClippedTriangle {
    vec3 edge0, edge1, edge2;  // e_i's planes, times sign(det)
    vec3 depthNumerator;       // sum_i z_i * edge_i
    vec3 depthDenominator;     // sum_i W_i * edge_i
};

// Whether a pixel centre on an edge (e exactly 0) belongs to this side: one of two triangles that
// share the edge (whose planes are negations) owns it.
bool ownsHomogeneousEdge(vec3 edge) { return edge.x > 0.0 || (edge.x == 0.0 && edge.y > 0.0); }

// The planes of a triangle that crosses the eye plane; false where it is seen edge-on. `front`:
// whether it faces the eye (det(V) has the sign of the screen area where every w is positive).
bool rasterHomogeneous(vec4 c0, vec4 c1, vec4 c2, out ClippedTriangle t, out bool front) {
    vec2 half_ = 0.5 * u_viewport.xy;
    // Clip space scaled to the viewport: X / W is the window x.
    precise vec3 v0 = vec3(c0.xy * half_ + c0.w * half_, c0.w);
    precise vec3 v1 = vec3(c1.xy * half_ + c1.w * half_, c1.w);
    precise vec3 v2 = vec3(c2.xy * half_ + c2.w * half_, c2.w);
    precise vec3 e0 = cross(v1, v2), e1 = cross(v2, v0), e2 = cross(v0, v1);
    precise float det = dot(v0, e0);
    front = det > 0.0;
    if (det < 0.0) {
        e0 = -e0;
        e1 = -e1;
        e2 = -e2;
    }
    t.edge0 = e0;
    t.edge1 = e1;
    t.edge2 = e2;
    precise vec3 numerator = c0.z * e0 + c1.z * e1 + c2.z * e2;
    precise vec3 denominator = c0.w * e0 + c1.w * e1 + c2.w * e2;
    t.depthNumerator = numerator;
    t.depthDenominator = denominator;
    return det != 0.0;
}

// The window depth of the triangle's plane at a pixel centre, as the planes give it.
float rasterClippedDepth(ClippedTriangle t, ivec2 pixel) {
    vec3 p = vec3(vec2(pixel) + 0.5, 1.0);
    precise float z = dot(t.depthNumerator, p) / dot(t.depthDenominator, p);
    return z;
}

bool rasterCoversClipped(ClippedTriangle t, ivec2 pixel, out float depth) {
    vec3 p = vec3(vec2(pixel) + 0.5, 1.0);
    precise float e0 = dot(t.edge0, p), e1 = dot(t.edge1, p), e2 = dot(t.edge2, p);
    if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) return false;
    if ((e0 == 0.0 && !ownsHomogeneousEdge(t.edge0)) || (e1 == 0.0 && !ownsHomogeneousEdge(t.edge1)) ||
        (e2 == 0.0 && !ownsHomogeneousEdge(t.edge2)))
        return false;
    if (!(dot(t.depthDenominator, p) > 0.0)) return false;
    depth = rasterClippedDepth(t, pixel);
    return isVisibleDepth(depth);
}
