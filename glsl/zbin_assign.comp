#version 450 core
// Z-binning (--assign zbin), the passes around the radix sort:
//   ML_ZBIN_KEYS   per light: cull to the view (lightClusterRange, as exact assignment does);
//                  key = the view depth of its near extent as order-preserving uint bits, culled
//                  lights get ~0u and sort after every listed one; count the listed lights
//   [radix sort of (key, light index)]
//   ML_ZBIN_BINS   per listed sorted light: gather its view-space sphere into sorted order and
//                  widen [first, last] of every bin its depth extent reaches (atomic min/max)
//   ML_ZBIN_TILE_MASKS  per (tile, word): 32 sorted lights against the tile's four side planes
//                  (a spot: its bounding sphere, then its sector's support along each plane)
//   ML_ZBIN_STATS  per pixel (--stats): lights walked (the bin's range) and passing the tile bit
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/lights.glsl"
#include "include/cluster_grid.glsl"
#include "include/window_depth.glsl"
#include "include/spot_cone.glsl"
#define ML_ZBIN_WRITABLE
#include "include/zbin.glsl"

layout(std430, binding = ML_SSBO_LIGHT_VIEW) buffer LightView { vec4 lightView[]; };  // bounding sphere (a spot's sector's): centre, radius (view space)
layout(std430, binding = ML_SSBO_ZBIN_SORTED_VIEW) buffer ZBinSortedView { vec4 sortedView[]; };
layout(std430, binding = ML_SSBO_RADIX_KEYS_IN) buffer Keys { uint keys[]; };

#if defined(ML_ZBIN_STATS)
layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
#else
layout(local_size_x = ML_ZBIN_WORKGROUP) in;
#endif

// A light's depth extent, widened a little so float rounding of a fragment's depth cannot
// leave the bins of a light that reaches it (its contribution there is ~0, W = 0 at r).
vec2 depthExtent(vec4 v) {
    float slack = v.w * 1e-4 + abs(v.z) * 1e-6;
    return vec2(-v.z - v.w - slack, -v.z + v.w + slack);
}

#if defined(ML_ZBIN_KEYS)
#include "include/light_cluster_range.glsl"

// Floats as uints in the same order (negatives flipped whole, positives get the sign bit).
uint orderedBits(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= lightCount()) return;
    ClusterRange range;
    uint key = ~0u;
    if (lightClusterRange(i, range)) {
        vec4 v = vec4(range.center, range.radius);
        lightView[i] = v;
        key = orderedBits(depthExtent(v).x);
        atomicAdd(zbinParams.y, 1u);
    }
    keys[i] = key;
    zbinSortedLights[i] = i;  // the sort's values: light indices, sorted in place
}

#elif defined(ML_ZBIN_BINS)
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= zbinParams.y) return;
    vec4 v = lightView[zbinSortedLights[i]];
    sortedView[i] = v;
    vec2 z = depthExtent(v);
    uint b0 = zbinForDepth(max(z.x, 1e-7)), b1 = zbinForDepth(z.y);
    for (uint b = b0; b <= b1; ++b) {
        atomicMin(zbinRanges[b].x, i);
        atomicMax(zbinRanges[b].y, i);
    }
}

#elif defined(ML_ZBIN_TILE_MASKS)
// View-space direction through a pixel-space point (its point on the near plane).
vec3 viewRay(vec2 px) { return viewPositionAtWindow(px, 1.0); }

// Does a spot's sector reach the inner side of every plane (through the eye, unit normals
// pointing in)? Its support along each normal, with slack. Always true for a point light.
bool spotSectorInsidePlanes(uint light, vec3 planes[4]) {
    vec4 directionCosOuter = lightCone(light);
    if (!isSpotCone(directionCosOuter.w)) return true;
    vec4 positionRadius = lights[light].positionRadius;
    vec3 apex = (u_view * vec4(positionRadius.xyz, 1.0)).xyz;
    vec3 axis = mat3(u_view) * directionCosOuter.xyz;
    float slack = kSpotSlack * (positionRadius.w + length(apex));
    for (int k = 0; k < 4; ++k)
        if (dot(planes[k], apex) + spotReach(planes[k], axis, directionCosOuter.w, positionRadius.w) < -slack) return false;
    return true;
}

void main() {
    uint w = gl_GlobalInvocationID.x;
    uint tile = gl_GlobalInvocationID.y;
    uint words = zbinParams.x;
    if (w >= words) return;
    // The tile's frustum: four planes through the eye. Tiles at the right and top edges reach
    // past the viewport; a wider frustum is still conservative.
    uvec2 t = uvec2(tile % grid.dims.x, tile / grid.dims.x);
    vec2 lo = vec2(t) * grid.tile.x, hi = vec2(t + 1u) * grid.tile.x;
    vec3 c00 = viewRay(lo), c10 = viewRay(vec2(hi.x, lo.y)), c11 = viewRay(hi), c01 = viewRay(vec2(lo.x, hi.y));
    vec3 mid = c00 + c10 + c11 + c01;
    vec3 planes[4] = vec3[4](cross(c00, c10), cross(c10, c11), cross(c11, c01), cross(c01, c00));
    for (int k = 0; k < 4; ++k) {
        planes[k] = normalize(planes[k]);
        if (dot(planes[k], mid) < 0.0) planes[k] = -planes[k];  // inward
    }
    uint bits = 0u;
    uint first = w * 32u, last = min(first + 32u, zbinParams.y);
    for (uint i = first; i < last; ++i) {
        vec4 v = sortedView[i];
        // Slack for float error in the planes: a sphere just outside by rounding stays in.
        float reach = -(v.w * (1.0 + 1e-4) + length(v.xyz) * 1e-5);
        bool inside = dot(planes[0], v.xyz) >= reach && dot(planes[1], v.xyz) >= reach &&
                      dot(planes[2], v.xyz) >= reach && dot(planes[3], v.xyz) >= reach;
        if (inside && !spotSectorInsidePlanes(zbinSortedLights[i], planes)) inside = false;
        if (inside) bits |= 1u << (i - first);
    }
    zbinTileMasks[tile * words + w] = bits;
}

#elif defined(ML_ZBIN_STATS)
#include "include/depth_samples.glsl"
// Per workgroup: visible samples (pixels without --msaa), lights walked, lights passing the tile bit.
layout(std430, binding = ML_SSBO_ZBIN_STATS) writeonly buffer ZBinStats { uvec4 groupStats[]; };
shared uint s_pixels, s_walked, s_passed;

void main() {
    if (gl_LocalInvocationIndex == 0u) { s_pixels = 0u; s_walked = 0u; s_passed = 0u; }
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(p, ivec2(u_viewport.xy)))) {
        for (int i = 0; i < ML_MSAA_SAMPLES; ++i) {
            float depth = depthSample(p, i);
            if (isBackgroundDepth(depth)) continue;
            float viewDepth = viewDepthFromWindowDepth(depth);
            uvec2 t = tileForPixel(vec2(p) + 0.5);
            uvec2 range = zbinRanges[zbinForDepth(viewDepth)];
            uint passed = 0u;
            if (range.x <= range.y) {
                for (uint w = range.x >> 5; w <= range.y >> 5; ++w)
                    passed += bitCount(zbinWordBits(t.x + grid.dims.x * t.y, range, w));
                atomicAdd(s_walked, range.y - range.x + 1u);
            }
            atomicAdd(s_pixels, 1u);
            atomicAdd(s_passed, passed);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u)
        groupStats[gl_WorkGroupID.x + gl_NumWorkGroups.x * gl_WorkGroupID.y] = uvec4(s_pixels, s_walked, s_passed, 0u);
}
#endif
