#version 450 core
// --normal-cones: which normal bins (include/normal_bins.glsl) each cluster's visible samples
// occupy, and per occupied (cluster, bin) list the cone of its samples' normals, in two phases
// over the pixels (u_phase):
//   0: set the cluster's bit of the sample's bin (and of the bins the normal, nudged by 1e-4
//      along each axis, falls in: the resolve's rounding may pick those), and add the normal to
//      each such list's sum (fixed point);
//   1: with the list's axis (its normalised sum), raise the list's 1 - cos(angle to the axis).
// A wall's cluster gets a cone of about zero width around the wall's normal, so lights behind
// the wall's plane drop out; a cluster holding a corner keeps a bin per wall. The cluster is
// taken at the sample's depth nudged both ways by a relative 1e-5, so rounding in the resolve
// (same expressions as include/deferred_resolve.glsl and cluster_lists.glsl) can never pick a
// list its normal did not go into.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#include "include/shading.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/gbuffer_fetch.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(std430, binding = ML_SSBO_NORMAL_BIN_MASKS) buffer NormalBinMasks { uint normalBinMasks[]; };
layout(std430, binding = ML_SSBO_NORMAL_CONES) buffer NormalCones { ivec4 normalCones[]; };  // xyz: normal sum, w: 1 - min cos (float bits)
uniform uint u_phase;

void addToList(uint key, vec3 n) {
    if (u_phase == 0u) {
        ivec3 q = ivec3(round(n * ML_NORMAL_SUM_SCALE));
        atomicAdd(normalCones[key].x, q.x);
        atomicAdd(normalCones[key].y, q.y);
        atomicAdd(normalCones[key].z, q.z);
    } else {
        vec3 axis = normalConeAxis(normalCones[key].xyz);
        atomicMax(normalCones[key].w, floatBitsToInt(max(1.0 - dot(n, axis), 0.0)));
    }
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    float depth = texelFetch(u_depth, p, 0).r;
    if (depth >= 1.0) return;
    vec2 ndc = (vec2(p) + 0.5) * u_viewport.zw * 2.0 - 1.0;
    vec4 viewPos = u_invProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    viewPos /= viewPos.w;
    SurfacePoint s;  // the normal decoded as the resolve decodes it, in every --gbuffer layout
    s.position = vec3(0.0);  // decodeGBuffer fills the rest; the bins need no position
    decodeGBuffer(fetchGBuffer(p), s);
    vec3 n = normalize(mat3(u_view) * s.normal);
    uint mask = 1u << normalBin(n);
    for (int axis = 0; axis < 3; ++axis) {
        vec3 nudge = vec3(0.0);
        nudge[axis] = 1e-4;
        mask |= (1u << normalBin(normalize(n + nudge))) | (1u << normalBin(normalize(n - nudge)));
    }
    float viewDepth = -viewPos.z;
    uint c0 = clusterForFragment(vec2(p) + 0.5, viewDepth * (1.0 - 1e-5));
    uint c1 = clusterForFragment(vec2(p) + 0.5, viewDepth * (1.0 + 1e-5));
    if (u_phase == 0u) {
        atomicOr(normalBinMasks[c0], mask);
        if (c1 != c0) atomicOr(normalBinMasks[c1], mask);
    }
    for (uint bits = mask; bits != 0u; bits &= bits - 1u) {
        uint b = uint(findLSB(bits));
        addToList(c0 * uint(ML_NORMAL_BINS) + b, n);
        if (c1 != c0) addToList(c1 * uint(ML_NORMAL_BINS) + b, n);
    }
}
