#version 450 core
// Visibility buffer: the raster pass writes only depth and which triangle is nearest (index + 1;
// 0 is background). Everything else is rebuilt in compute (visibility_resolve.comp).
//
// Hardware raster (--vis-raster hardware): opaque ranges write the id by an image atomic behind
// an early depth test, not through the ROPs: on an H100, whose few graphics units write 4 bytes a
// pixel in 0.26 ms at 2560x1440, that takes the colour writes out of the pass (1.10 -> 0.85 ms on
// the atrium). A fragment passes GL_LESS at its turn only if it is nearer than every fragment
// before it at the pixel, so the last to pass is the one a colour write would have left; ids grow
// with the draw order (SceneGpu lays its index buffer out so), so it is the largest, kept by
// imageAtomicMax. The alpha-tested variant (ML_ALPHA_TEST) discards uncovered fragments, which
// needs the late depth test, so it writes its id as a colour output; those ranges are drawn last.
//
// Compute raster (ML_COMPUTE_RASTER, renderer/passes/compute_raster.h): the triangles it leaves
// to the hardware (its lists, compute_raster_hardware.vert: those the GPU clips where the compute
// raster cannot follow, or past its lists; with ML_ALPHA_TEST one texture set's alpha-tested
// ones) store depth and id into the compute raster's per-pixel store, with no depth buffer:
// nearest depth, then smallest id, wins (include/compute_raster.glsl).
#if ML_COMPUTE_RASTER
#extension GL_ARB_gpu_shader_int64 : require
#if ML_RASTER_ATOMIC64
#extension GL_NV_shader_atomic_int64 : require
#endif
#endif
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"

#if ML_COMPUTE_RASTER
#include "include/window_depth.glsl"
#include "include/compute_raster.glsl"
uniform uint u_cullBackFaces;
#elif ML_ALPHA_TEST
layout(location = 0) out uint o_triangle;
#else
layout(early_fragment_tests) in;
layout(binding = ML_IMG_VISIBILITY_IDS, r32ui) uniform coherent uimage2D u_ids;
#endif

void main() {
#if ML_COMPUTE_RASTER
    // Drawn without GL's culling, since a list mixes sidedness: culled here, as a raster pass would.
    if (u_cullBackFaces != 0u && !gl_FrontFacing && (materials[v_materialIndex].info.w & ML_MATERIAL_DOUBLE_SIDED) == 0u) discard;
    // The compute-rastered surfaces are in the store already: a fragment behind them needs no
    // alpha test (a manual early depth test; there is no depth buffer).
    if (rasterHidden(ivec2(gl_FragCoord.xy), gl_FragCoord.z)) discard;
    alphaTestFragment();
    // The hardware's own depth: the compute raster's plane at the pixel (which would make ties
    // with compute-rastered surfaces resolve alike) matched the hardware raster's ids worse on
    // Sponza, on llvmpipe and on the H100, since the hardware computes its depth its own way.
    if (isVisibleDepth(gl_FragCoord.z)) rasterStore(ivec2(gl_FragCoord.xy), gl_FragCoord.z, fragmentTriangle());
#else
    uint id = v_firstTriangle + uint(gl_PrimitiveID) + 1u;
#if ML_ALPHA_TEST
    alphaTestFragment();
    o_triangle = id;
#else
    imageAtomicMax(u_ids, ivec2(gl_FragCoord.xy), id);
#endif
#endif
}
