#version 450 core
// --active-only and --normal-cones learn where samples are from the opaque depth buffer and
// G-buffer, which hold no transparent surface. This pass rasters the transparent draw ranges
// against the opaque depth (early tests: hidden fragments never run) and records each visible
// fragment as a sample: its clusters flagged active (ML_MARK_ACTIVE, phase 0) and its normal
// added to the (cluster, bin) lists (ML_NORMAL_CONES, both phases), with the same depth nudges
// as the opaque samples, so the transparent pass finds every light its fragments need. It
// writes no colour and no depth.
layout(early_fragment_tests) in;
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"
#include "include/cluster_grid.glsl"
#include "include/normal_bins.glsl"
#if defined(ML_NORMAL_CONES)
#include "include/normal_bin_marking.glsl"
#else
uniform uint u_phase;
#endif
#if defined(ML_MARK_ACTIVE)
layout(std430, binding = ML_SSBO_CLUSTER_ACTIVE) writeonly buffer ClusterActive { uint clusterActive[]; };
#endif

void main() {
    SurfacePoint s = fragmentSurface();  // the normal the transparent pass shades with
    float viewDepth = -(u_view * vec4(v_worldPos, 1.0)).z;
    uint c0 = clusterForFragment(gl_FragCoord.xy, viewDepth * (1.0 - 1e-5));
    uint c1 = clusterForFragment(gl_FragCoord.xy, viewDepth * (1.0 + 1e-5));
#if defined(ML_MARK_ACTIVE)
    if (u_phase == 0u) {
        clusterActive[c0] = 1u;
        clusterActive[c1] = 1u;
    }
#endif
#if defined(ML_NORMAL_CONES)
    markNormalSample(normalize(mat3(u_view) * s.normal), c0, c1);
#endif
}
