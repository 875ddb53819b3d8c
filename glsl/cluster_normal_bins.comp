#version 450 core
// --normal-cones: which normal bins (include/normal_bins.glsl) each cluster's visible opaque
// samples occupy, and per occupied (cluster, bin) list the cone of its samples' normals, in the
// two phases of include/normal_bin_marking.glsl over the pixels (u_phase). A wall's cluster gets a cone of about zero width around the wall's normal, so lights behind
// the wall's plane drop out; a cluster holding a corner keeps a bin per wall. The cluster is
// taken at the sample's depth nudged both ways by a relative 1e-5, so rounding in the resolve
// (same expressions as include/deferred_resolve.glsl and cluster_lists.glsl) can never pick a
// list its normal did not go into.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/cluster_grid.glsl"
#include "include/window_depth.glsl"
#include "include/normal_bins.glsl"
#include "include/normal_bin_marking.glsl"
#include "include/shading.glsl"
#include "include/gbuffer_layout.glsl"
#include "include/gbuffer_fetch.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(u_viewport.xy)))) return;
    float depth = texelFetch(u_depth, p, 0).r;
    if (isBackgroundDepth(depth)) return;
    vec3 viewPos = viewPositionAtWindow(vec2(p) + 0.5, depth);
    SurfacePoint s;  // the normal decoded as the resolve decodes it, in every --gbuffer layout
    s.position = vec3(0.0);  // decodeGBuffer fills the rest; the bins need no position
    decodeGBuffer(fetchGBuffer(p), s);
    float viewDepth = -viewPos.z;
    uint c0 = clusterForFragment(vec2(p) + 0.5, viewDepth * (1.0 - 1e-5));
    uint c1 = clusterForFragment(vec2(p) + 0.5, viewDepth * (1.0 + 1e-5));
    markNormalSample(normalize(mat3(u_view) * s.normal), c0, c1);
}
