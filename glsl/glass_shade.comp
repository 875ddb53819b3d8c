#version 450 core
#if ML_FIXED_LIGHT_SUM  // include/light_sum.glsl
#extension GL_ARB_gpu_shader_int64 : require
#endif
// The transparent pass's shading (renderer/passes/transparent_pass.h): per pixel, its captured
// fragments (glass_capture.frag) sorted by depth, each surface rebuilt from its triangle as the
// visibility resolve rebuilds one (include/triangle_surface.glsl), shaded with the method's
// lights (ML_GLASS_ALL_LIGHTS: naive's every light; else the cluster lists) and blended back to
// front over the opaque HDR frame: colour * alpha + destination * (1 - alpha), the forward
// pass's blend, in linear HDR before the MSAA resolve, bloom and the tonemap.
//
// Textures cannot be chosen per fragment without bindless textures, so the pass runs once per
// texture set the glass binds (u_textureSet). With one set (the common case) the one dispatch
// sorts, shades and blends, and no colour is stored. With more, the first dispatch sorts,
// each stores the colours of its set's fragments, and the last blends them.
//
// Deep tiles (list rounds, one texture set): a workgroup's time is its longest chain of list
// rounds, and a tile whose pixels hold fragments at many depths serves one round per list of
// every depth, each by the few invocations it lights; on an H100 such tiles made the gas
// station's glass as slow as its whole opaque lighting at a sixth of its work
// (docs/bench/nvidia-h100/cooperative-rounds/). So a frame may be shaded in four programs
// (ML_GLASS_SPLIT): kListTiles sorts every tile's pixels and lists the tiles with a pixel of
// u_deepFragments fragments or more, each in as many parts as its deepest pixel has fragments (at
// most u_maxParts), and the other tiles that hold a fragment; then kShadeParts shades each listed
// part in a workgroup of its own, a contiguous run of every pixel's sorted fragments, storing
// their colours, while kShadeShallowTiles shades and blends the other listed tiles: the two touch
// different tiles and run side by side, no barrier between, so the deep tiles' long chains overlap
// the rest of the screen instead of following it; last kBlendParts blends the parts' colours back
// to front. The colours and the order are those of one dispatch, so the bits are too. Only the
// list runs a workgroup per screen tile: a shading workgroup holds the rounds' shared memory, so
// few fit an SM at once, and a screen of them, most without glass, cost the atrium's glass
// 0.03-0.04 ms on an H200 (docs/bench/nvidia-h200/glass-tiles/). Each is a program of its own,
// so that the one pass carries none of their code.
//
// Order: nearest first by depth, equal depths by triangle id, so every method (and naive)
// blends the same fragments in the same order, intersecting and interleaved panes included.
// --shadows sampled: each glass fragment draws its rays as the opaque pixels do and scales its
// lights by their raw ratio (no history or filter: a fragment is not there the next frame).
#if defined(ML_SHADOW_SAMPLES) && ML_SHADOW_RAYS
#define ML_SHADOW_SAMPLED_LIGHTING 1
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/shading.glsl"
#include "include/sun_lights.glsl"
#include "include/material.glsl"
#include "include/triangle_surface.glsl"
#include "include/glass_window.glsl"
// Here, not only inside the #if below: each include is resolved once per shader, where it first appears.
#include "include/light_sum.glsl"
#if ML_GLASS_ALL_LIGHTS
#include "include/every_light.glsl"
#else
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#define ML_ZBIN_LISTS_ONLY 1
#include "include/cluster_lists.glsl"
#endif
// With per-cluster lists, a tile's fragments are lit from lists staged in shared memory once per
// tile, as the opaque pixels are (include/list_rounds.glsl); the sums are those of the per-pixel loop.
#if !ML_GLASS_ALL_LIGHTS && !defined(ML_ZBIN)
#define ML_GLASS_LIST_ROUNDS 1
#if ML_HAS(ML_FEATURE_TRANSMISSION)
#define ML_LIST_ROUNDS_NORMAL_BOUND 0  // a transmissive surface is lit from behind as well
#endif
#include "include/spot_cone.glsl"
#include "include/list_rounds.glsl"
#else
#define ML_GLASS_LIST_ROUNDS 0
#endif

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_IMG_HDR, rgba32f) uniform image2D u_hdr;
// Where each pixel's fragments end, then the scan's block bases (renderer/passes/glass_fragments.h).
layout(std430, binding = ML_SSBO_GLASS_PIXELS) readonly buffer GlassPixels { uint glassEnds[]; };
// The fragments (two words each) and, from word u_colorBase, a colour per fragment (four words)
// where there is more than one set: one block, as llvmpipe offers a compute shader 16 and
// z-binning with every vertex stream and spot lights needs 15 with the pixels'.
layout(std430, binding = ML_SSBO_GLASS_FRAGMENTS) buffer GlassFragments { uint glassWords[]; };
uniform uint u_colorBase;
uniform int u_textureSet;
uniform uint u_sorts;        // 1: the first dispatch, which sorts each pixel's fragments in place
uniform uint u_blends;       // 1: the last dispatch, which blends them over the frame
uniform uint u_storesColors; // 1: more than one dispatch; colours go through the buffer
#define kOnePass 0        // ML_GLASS_SPLIT: no tile split
#define kListTiles 1
#define kShadeParts 2
#define kBlendParts 3
#define kShadeShallowTiles 4
#ifndef ML_GLASS_SPLIT
#define ML_GLASS_SPLIT kOnePass
#endif
#if ML_GLASS_SPLIT != kOnePass
uniform uint u_deepFragments;  // kListTiles: a pixel of this many fragments makes its tile deep
uniform uint u_maxParts;       // kListTiles: the most parts a deep tile is shaded in
uniform uint u_deepBase;       // the deep tiles' words in glassWords (ML_GLASS_DEEP_*)
uniform uint u_windowTiles;    // the glass window's tiles (glass_window.glsl): words of the tile list; the parts' follow it
shared uint s_mostFragments;
#endif

uvec2 fragmentAt(uint k) { return uvec2(glassWords[2u * k], glassWords[2u * k + 1u]); }
// Where a pixel's fragments start: where the pixel before it ends, or for the first pixel of one
// of the scan's blocks, the block's base (the blocks lie in any order in the fragment buffer).
// `pixel`: its word in the window (glassPixel).
uint glassBegin(uint pixel) {
    const uint kBlock = ML_SCAN_WORKGROUP * ML_SCAN_PER_INVOCATION;
    if (pixel % kBlock != 0u) return glassEnds[pixel - 1u];
    return glassEnds[glassWindowPixels() + pixel / kBlock];
}

void storeFragment(uint k, uvec2 f) {
    glassWords[2u * k] = f.x;
    glassWords[2u * k + 1u] = f.y;
}
vec4 colorAt(uint k) {
    uint w = u_colorBase + 4u * k;
    return uintBitsToFloat(uvec4(glassWords[w], glassWords[w + 1u], glassWords[w + 2u], glassWords[w + 3u]));
}
void storeColor(uint k, vec4 c) {
    uint w = u_colorBase + 4u * k;
    uvec4 bits = floatBitsToUint(c);
    glassWords[w] = bits.x;
    glassWords[w + 1u] = bits.y;
    glassWords[w + 2u] = bits.z;
    glassWords[w + 3u] = bits.w;
}

// Reversed depth (include/window_depth.glsl): the nearer fragment has the greater depth, and bits.
bool nearerThan(uvec2 a, uvec2 b) { return a.x > b.x || (a.x == b.x && a.y < b.y); }

// Insertion sort: a pixel holds a few fragments, mostly captured near-sorted already.
void sortFragments(uint begin, uint end) {
    for (uint i = begin + 1u; i < end; ++i) {
        uvec2 key = fragmentAt(i);
        uint j = i;
        for (; j > begin && nearerThan(key, fragmentAt(j - 1u)); --j) storeFragment(j, fragmentAt(j - 1u));
        if (j != i) storeFragment(j, key);
    }
}

#if ML_HAS(ML_FEATURE_TRANSMISSION)
// The opaque frame before the glass, with its mip chain (TransparentPass): what a transmissive
// surface sees through itself (shading.glsl's B).
layout(binding = ML_TEX_REFRACTION_SOURCE) uniform sampler2D u_refractionSource;
#endif

// A transmissive material's coverage (whole, or MASK's cut-off; a BLEND one keeps its alpha) and
// what it sees behind: the frame where the refracted view ray leaves its volume (the pixel itself
// where thin-walled), blurred by its roughness as the Sample Viewer blurs it.
void seeThrough(Material m, vec3 viewDir, inout SurfacePoint s, inout float alpha) {
#if ML_HAS(ML_FEATURE_TRANSMISSION)
    if ((m.info.w & ML_MATERIAL_TRANSMISSIVE_COVERAGE) != 0u) alpha = alpha >= m.emissiveCutoff.a ? 1.0 : 0.0;
    if (!transmissive(s)) return;
    float eta = max(s.transmissionIor, 1.0);
    vec3 exitPoint = s.position;
    if (s.thickness > 0.0) exitPoint += normalize(refract(-viewDir, s.normal, 1.0 / eta)) * s.thickness;
    vec4 clip = u_viewProj * vec4(exitPoint, 1.0);
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    float blur = clamp(s.roughness, 0.0, 1.0) * clamp(2.0 * eta - 2.0, 0.0, 1.0);
    s.behind = textureLod(u_refractionSource, uv, log2(u_viewport.x) * blur).rgb;
#endif
}

// The fragment's colour from its light sum: as shadeUnclustered adds, or, with --shadows sampled,
// the lights scaled by the fragment's drawn rays (begun with beginGlassSampling before its loop).
vec3 litGlassColor(SurfacePoint s, vec3 viewDir, vec3 lightSum) {
#ifdef ML_SHADOW_SAMPLED_LIGHTING
    return sampledShadowColor(s, viewDir, lightSum);
#else
    return shadeUnclustered(s, viewDir) + lightSum;
#endif
}
void beginGlassSampling(ivec2 p, uint triangle) {
#ifdef ML_SHADOW_SAMPLED_LIGHTING
    beginShadowSampling(p, triangle + 1u);
#endif
}

// The fragment's shaded colour and its alpha, as the forward pass's fragment shader gives them.
vec4 shadeFragment(uint triangle, Material m, ivec2 p) {
    float alpha;
    SurfacePoint s = triangleSurface(triangle, m, p, alpha);
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    seeThrough(m, viewDir, s, alpha);
    beginGlassSampling(p, triangle);
#if ML_GLASS_ALL_LIGHTS
    return vec4(litGlassColor(s, viewDir, shadeEveryLight(s, viewDir)), alpha);
#else
    float viewDepth = -(u_view * vec4(s.position, 1.0)).z;
    uint cluster = clusterForFragment(vec2(p) + 0.5, viewDepth);
    return vec4(litGlassColor(s, viewDir, shadeClusterLights(s, viewDir, cluster, viewDepth)), alpha);
#endif
}

vec3 over(vec4 c, vec3 destination) { return c.rgb * c.a + destination * (1.0 - c.a); }

#if ML_GLASS_LIST_ROUNDS
// Steps `k` (`end` to start) to the pixel's next fragment to shade, back to front (they are
// sorted nearest first); where the dispatch stores colours, to its texture set's alone. False
// when none is left.
bool nextFragment(uint begin, inout uint k) {
    while (k > begin) {
        --k;
        if (u_storesColors == 0u) return true;
        uint triangle = fragmentAt(k).y;
        if (int(materials[triangleMaterial[triangle]].info.z) - 1 == u_textureSet) return true;
    }
    return false;
}

#if ML_GLASS_SPLIT != kOnePass
uint deepWord(uint word) { return glassWords[u_deepBase + word]; }

// kShadeParts, kBlendParts, kShadeShallowTiles: this workgroup's listed tile and its part of each
// pixel's fragments (the others: all of them); false past the list's end.
bool listedTile(out ivec2 tile, out uint part, out uint parts) {
    uint listed = gl_WorkGroupID.y * uint(ML_GLASS_DEEP_ROW) + gl_WorkGroupID.x;
    uint tileIndex = listed;
    part = 0u;
    parts = 1u;
#if ML_GLASS_SPLIT == kShadeParts
    if (listed >= deepWord(ML_GLASS_DEEP_PART_COUNT)) return false;
    uint entry = deepWord(ML_GLASS_DEEP_TILES + u_windowTiles + listed);
    tileIndex = entry >> 8;
    part = (entry >> 4) & 15u;
    parts = (entry & 15u) + 1u;
#elif ML_GLASS_SPLIT == kShadeShallowTiles
    if (listed >= deepWord(ML_GLASS_SHALLOW_COUNT)) return false;
    tileIndex = u_windowTiles - 1u - listed;
#else
    if (listed >= deepWord(ML_GLASS_DEEP_TILE_COUNT)) return false;
#endif
    uint t = deepWord(ML_GLASS_DEEP_TILES + tileIndex);
    tile = ivec2(t & 0xFFFFu, t >> 16);
    return true;
}

// Grows an indirect dispatch of rows of ML_GLASS_DEEP_ROW workgroups to hold workgroup `last`.
void growDispatch(uint dispatch, uint last) {
    atomicMax(glassWords[u_deepBase + dispatch], min(last + 1u, uint(ML_GLASS_DEEP_ROW)));
    atomicMax(glassWords[u_deepBase + dispatch + 1u], last / uint(ML_GLASS_DEEP_ROW) + 1u);
}

// kListTiles: the most fragments a pixel of the tile holds. Every invocation calls it alike (barriers).
uint mostFragments(uint fragments) {
    if (gl_LocalInvocationIndex == 0u) s_mostFragments = 0u;
    barrier();
    if (fragments != 0u) atomicMax(s_mostFragments, fragments);
    barrier();
    return s_mostFragments;
}

// kListTiles: lists a tile with glass but none deep, from the tile list's back.
void listShallowTile(ivec2 tile) {
    uint listed = atomicAdd(glassWords[u_deepBase + ML_GLASS_SHALLOW_COUNT], 1u);
    glassWords[u_deepBase + ML_GLASS_DEEP_TILES + u_windowTiles - 1u - listed] = uint(tile.x) | (uint(tile.y) << 16);
    growDispatch(ML_GLASS_SHALLOW_DISPATCH, listed);
}

// kListTiles: lists a deep tile and its parts.
void listDeepTile(ivec2 tile, uint deepest) {
    uint listed = atomicAdd(glassWords[u_deepBase + ML_GLASS_DEEP_TILE_COUNT], 1u);
    glassWords[u_deepBase + ML_GLASS_DEEP_TILES + listed] = uint(tile.x) | (uint(tile.y) << 16);
    growDispatch(ML_GLASS_DEEP_BLEND_DISPATCH, listed);
    uint parts = min(deepest, u_maxParts);
    uint first = atomicAdd(glassWords[u_deepBase + ML_GLASS_DEEP_PART_COUNT], parts);
    for (uint part = 0u; part < parts; ++part)
        glassWords[u_deepBase + ML_GLASS_DEEP_TILES + u_windowTiles + first + part] = (listed << 8) | (part << 4) | (parts - 1u);
    growDispatch(ML_GLASS_DEEP_PARTS_DISPATCH, first + parts - 1u);
}

// kShadeParts: part `part` of `parts` of the pixel's sorted fragments, a contiguous run.
void takePart(uint part, uint parts, inout uint begin, inout uint end) {
    uint n = end - begin;
    end = begin + n * (part + 1u) / parts;
    begin = begin + n * part / parts;
}
#endif

// Fragment k's surface, view direction and alpha, and the list it waits for.
uint beginFragment(uint k, ivec2 p, out SurfacePoint s, out vec3 viewDir, out float alpha) {
    uint triangle = fragmentAt(k).y;
    Material m = materials[triangleMaterial[triangle]];
    s = triangleSurface(triangle, m, p, alpha);
    viewDir = normalize(u_cameraPos.xyz - s.position);
    seeThrough(m, viewDir, s, alpha);
    beginGlassSampling(p, triangle);
    float viewDepth = -(u_view * vec4(s.position, 1.0)).z;
    return clusterListKey(clusterForFragment(vec2(p) + 0.5, viewDepth), s.normal);
}
#endif

void main() {
#if ML_GLASS_SPLIT == kShadeParts || ML_GLASS_SPLIT == kBlendParts || ML_GLASS_SPLIT == kShadeShallowTiles
    ivec2 tile;
    uint part, parts;
    if (!listedTile(tile, part, parts)) return;  // the whole workgroup: no barrier is left waiting
    ivec2 p = tile * ML_SCREEN_TILE + ivec2(gl_LocalInvocationID.xy);
#else
    ivec2 p = ivec2(u_glassWindow.xy + gl_GlobalInvocationID.xy);  // a workgroup per tile of the window
#endif
    bool inside = all(lessThan(p, ivec2(u_viewport.xy)));
#if ML_GLASS_LIST_ROUNDS
    // Every invocation takes part in every round (they hold barriers), with fragments or not.
    uint begin = 0u, end = 0u;
    if (inside) {
        uint pixel = glassPixel(p);
        end = glassEnds[pixel];
        begin = glassBegin(pixel);
        if (begin != end && u_sorts != 0u) sortFragments(begin, end);
    }
#if ML_GLASS_SPLIT == kBlendParts
    if (begin == end) return;
    vec4 stored = imageLoad(u_hdr, p);
    vec3 blended = stored.rgb;
    for (uint j = end; j-- > begin;) blended = over(colorAt(j), blended);
    imageStore(u_hdr, p, vec4(blended, stored.a));
    return;
#elif ML_GLASS_SPLIT == kListTiles
    uint most = mostFragments(end - begin);
    if (gl_LocalInvocationIndex == 0u) {
        ivec2 tile = ivec2(u_glassWindow.xy / uint(ML_SCREEN_TILE) + gl_WorkGroupID.xy);
        if (most >= u_deepFragments) listDeepTile(tile, most);
        else if (most != 0u) listShallowTile(tile);
    }
    return;
#elif ML_GLASS_SPLIT == kShadeParts
    takePart(part, parts, begin, end);
#endif
    vec4 frame = begin != end ? imageLoad(u_hdr, p) : vec4(0.0);
    vec3 color = frame.rgb;
    uint k = end;
    bool shading = nextFragment(begin, k);
    SurfacePoint s;
    vec3 viewDir = vec3(0.0);
    float alpha = 0.0;
    uint pending = shading ? beginFragment(k, p, s, viewDir, alpha) : kNoList;
    LightSum lightSum = noLight();
    bool served;
    while (serveListRound(pending, s, viewDir, lightSum, served)) {
        if (!served) continue;
        vec4 c = vec4(litGlassColor(s, viewDir, lightSumValue(lightSum)), alpha);
        if (u_storesColors != 0u) storeColor(k, c);
        else color = over(c, color);
        lightSum = noLight();
        pending = kNoList;
        if (nextFragment(begin, k)) pending = beginFragment(k, p, s, viewDir, alpha);
    }
    if (begin == end) return;
    if (u_storesColors != 0u) {
        if (u_blends == 0u) return;
        for (uint j = end; j-- > begin;) color = over(colorAt(j), color);
    }
    imageStore(u_hdr, p, vec4(color, frame.a));
#else
    if (!inside) return;
    uint pixel = glassPixel(p);
    uint end = glassEnds[pixel];
    uint begin = glassBegin(pixel);
    if (begin == end) return;
    if (u_sorts != 0u) sortFragments(begin, end);
    vec4 frame = imageLoad(u_hdr, p);
    vec3 color = frame.rgb;
    if (u_storesColors == 0u) {
        for (uint k = end; k-- > begin;) {
            uint triangle = fragmentAt(k).y;
            color = over(shadeFragment(triangle, materials[triangleMaterial[triangle]], p), color);
        }
    } else {
        for (uint k = begin; k < end; ++k) {
            uint triangle = fragmentAt(k).y;
            Material m = materials[triangleMaterial[triangle]];
            if (int(m.info.z) - 1 == u_textureSet) storeColor(k, shadeFragment(triangle, m, p));
        }
        if (u_blends == 0u) return;
        for (uint k = end; k-- > begin;) color = over(colorAt(k), color);
    }
    // The frame's alpha stays as it was (1: the frame is opaque), as the forward blend leaves it.
    imageStore(u_hdr, p, vec4(color, frame.a));
#endif
}
