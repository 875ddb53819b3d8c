// Binding points and constants shared by C++ and GLSL: the one source of truth for both.
// C++ includes this file directly; shaders include it through the project's resolver.
// Only #define lines may live here, so it stays valid in both languages.
#ifndef ML_BINDINGS_H
#define ML_BINDINGS_H

// Uniform buffers
#define ML_UBO_FRAME 0
#define ML_UBO_SUN_LIGHTS 1        // directional lights: shaded everywhere, never clustered

// Shader storage buffers
#define ML_SSBO_LIGHTS 0           // animated lights, read by shading
#define ML_SSBO_LIGHTS_BASE 1      // lights at time 0, read by the animation pass
#define ML_SSBO_MATERIALS 2
#define ML_SSBO_CLUSTER_GRID 3     // grid dimensions and the depth range sliced this frame
#define ML_SSBO_CLUSTER_AABBS 4    // view-space bounds of every cluster
#define ML_SSBO_CLUSTER_COUNTS 5   // lights per cluster
#define ML_SSBO_CLUSTER_OFFSETS 6  // first entry of each cluster's list (exact lists: prefix sum of counts)
#define ML_SSBO_LIGHT_INDICES 7    // the light lists, one after another
#define ML_SSBO_CLUSTER_ACTIVE 8   // 1 where a visible sample falls in the cluster (--active-only)
#define ML_SSBO_ASSIGN_STATS 9     // overflow counters of capped lists
#define ML_SSBO_SCAN_DATA 10       // prefix sum: the values, scanned in place
#define ML_SSBO_SCAN_BLOCKS 11     // prefix sum: the ticket, and each block's published sums
// --shadows rays: the occluders' BVH, a ray-count header, nodes, triangles, then the MASK
// triangles' UVs and materials (glsl/include/shadow_rays.glsl). Bound
// by every shading pass as it starts (FrameContext::bindLightsForShading); only the light
// assignment's prefix sum, which runs before, uses the point for its blocks.
#define ML_SSBO_SHADOW_BVH 11
// prefix sum: where the total goes (the scan writes it, rather than a buffer copy after the scan).
// It shares the vertices' point below: every pass binds what it reads before it runs.
#define ML_SSBO_SCAN_TOTAL 12
// Scene geometry for compute passes that rebuild surfaces from triangle ids (the visibility
// resolve, the transparent pass's shading), away from the spot cones, which the transparent
// shading reads with them.
#define ML_SSBO_VERTICES 12        // scene vertices as floats
#define ML_SSBO_INDICES 14         // scene triangle indices
// Spot cones (where the light set has spots): animated, read with the lights; at time 0, read by
// the animation. The animation reads no geometry, so the base cones share the indices' point.
#define ML_SSBO_LIGHT_CONES 13
#define ML_SSBO_LIGHT_CONES_BASE 14
#define ML_SSBO_TRIANGLE_MATERIALS 15  // material of every triangle (visibility resolve, transparent shading)
#define ML_SSBO_LIGHT_RANGES 16    // exact assignment: each light's block of candidate clusters
#define ML_SSBO_LIGHT_VIEW 17      // exact assignment: each light's view-space centre and radius
#define ML_SSBO_CANDIDATE_OFFSETS 18   // exact assignment: prefix sum of candidates per light
#define ML_SSBO_DISPATCH 19        // exact assignment: indirect dispatch arguments of the test passes
// exact assignment: the candidates and their wrap flag, for the CPU (a mapped buffer); the point
// of the radix sort's keys and the vertex tangents, which no pass of the assignment reads
#define ML_SSBO_ASSIGN_CANDIDATES 20
#define ML_SSBO_SORT_WORK 16       // list sort: the lists of two or more entries and their dispatches (after assignment)
#define ML_SSBO_SORT_SCRATCH 17    // list sort: lists longer than shared memory, merged, before they are copied back
// The visibility resolve's tile lists (renderer/methods/visibility_buffer.h); free in that pass.
#define ML_SSBO_RESOLVE_TILES 16       // per texture set slot, the screen tiles holding its pixels
#define ML_SSBO_RESOLVE_DISPATCH 17    // per slot, the indirect dispatch of its resolve: tiles, 1, 1
#define ML_RESOLVE_MAX_SLOTS 32        // slots a tile's mask holds (texture sets + untextured); more: full-screen dispatches
// The transparent pass's captured fragments (renderer/passes/glass_fragments.h), on the exact
// assignment's points: the capture and its shading run after the lists are built.
#define ML_SSBO_GLASS_PIXELS 16        // per pixel of the glass's window (glass_window.glsl): its fragment count, then (scanned, filled) where its fragments end
#define ML_SSBO_GLASS_FRAGMENTS 17     // per fragment: depth bits, triangle id; then, where colours are stored, its colour; then the deep tiles
// The glass shading's deep tiles (glsl/glass_shade.comp): words of the fragment buffer after the
// colours, as llvmpipe offers a compute shader no block to spare.
#define ML_GLASS_DEEP_PARTS_DISPATCH 0  // the parts' indirect dispatch: parts per row, rows, 1 (words 0-2)
#define ML_GLASS_DEEP_BLEND_DISPATCH 3  // the blend's: tiles per row, rows, 1 (words 3-5)
#define ML_GLASS_DEEP_TILE_COUNT 6      // deep tiles listed
#define ML_GLASS_DEEP_PART_COUNT 7      // parts listed
#define ML_GLASS_SHALLOW_DISPATCH 8     // the other tiles with glass: their shading's dispatch (words 8-10)
#define ML_GLASS_SHALLOW_COUNT 11       // and how many are listed
#define ML_GLASS_DEEP_TILES 12          // then a word per tile of the window: the tiles, x | y << 16, the deep ones from the
                                        // front, the shallow ones from the back; then the parts, as many words per
                                        // tile of the window as a tile's most parts: tile index << 8 | part << 4 | parts - 1
#define ML_GLASS_DEEP_MAX_PARTS 16      // the most parts a tile may take (4 bits of its part words)
#define ML_GLASS_DEEP_ROW 65535         // tiles per dispatch row: GL's least maximum work-group count
// The visibility buffer's compute raster (renderer/passes/compute_raster.h), before anything else
// of the frame binds these points.
#define ML_SSBO_RASTER_DEPTH_IDS 16    // per pixel: nearest depth and triangle (one 64-bit word, or two 32-bit arrays)
#define ML_SSBO_RASTER_WORK 17         // counters and indirect arguments (ML_RASTER_WORK_*)
#define ML_SSBO_RASTER_LARGE 18        // triangles for the tile pass: snapped vertices, depths, id, tile bounds (48 B)
#define ML_SSBO_RASTER_PAIRS 19        // (large triangle, screen tile) for the tile pass
#define ML_SSBO_RASTER_HARDWARE 23     // triangles the hardware rasters instead (where the GPU clips at the viewport)
#define ML_SSBO_RASTER_CLIPPED 24      // triangles that cross the eye plane, as homogeneous edge planes for the tile pass (80 B)
#define ML_RASTER_WORK_HARDWARE_DRAW 0   // DrawArraysIndirectCommand of the hardware's triangles (words 0-3)
#define ML_RASTER_WORK_BIN_DISPATCH 4    // the binning's dispatch (words 4-6)
#define ML_RASTER_WORK_TILE_DISPATCH 7   // the tile pass's dispatch (words 7-9)
#define ML_RASTER_WORK_LARGE_COUNT 10
#define ML_RASTER_WORK_PAIR_COUNT 11
#define ML_RASTER_WORK_CLIPPED_COUNT 12
#define ML_RASTER_WORK_ALPHA_BIN_DISPATCH 13   // the same four for the alpha-tested triangles' lists (words 13-15)
#define ML_RASTER_WORK_ALPHA_TILE_DISPATCH 16  // (words 16-18)
#define ML_RASTER_WORK_ALPHA_LARGE_COUNT 19
#define ML_RASTER_WORK_ALPHA_PAIR_COUNT 20
#define ML_RASTER_WORK_VIEW_DEPTH_RANGE 21     // the drawn pixels' least and greatest view depth, as bits (words 21-22;
                                               // the finish's, for fitted slicing: cluster_depth_range.comp)
#define ML_RASTER_WORK_PAIR_END 23             // where the written pairs end, and the alpha-tested ones'
#define ML_RASTER_WORK_ALPHA_PAIR_END 24       // (include/compute_raster_pairs.glsl; ~0u: no list overflowed)
#define ML_RASTER_WORK_WORDS 25                // then a DrawArraysIndirectCommand per alpha-tested span
#define ML_RASTER_CLIPPED_PAIR 0x80000000u  // a pair's triangle is in the clipped list
#define ML_RASTER_WORKGROUP 64       // triangles per workgroup of the setup pass
#define ML_RASTER_TILE 16            // the tile pass's screen tile edge
// A large triangle whose pixel bounds span at most ML_RASTER_FINE_EXTENT pixels each way is binned
// to 8x8 tiles (ML_RASTER_FINE_TILE), a pixel an invocation: it covers a sliver of most 16x16
// tiles it touches. Its pairs' tile words carry ML_RASTER_FINE_PAIR in the x bits. 64, 192 and
// 256 pixels measured no better than 128, every triangle 8x8 tiles worse
// (docs/bench/nvidia-h200/fine-tiles/).
#define ML_RASTER_FINE_TILE 8
#define ML_RASTER_FINE_EXTENT 128
#define ML_RASTER_FINE_PAIR 0x8000u
#define ML_RASTER_PAIR_TILE_X 0x7fffu  // a tile word's x bits (include/compute_raster.glsl, rasterTileWord)
// A large opaque triangle binned to at most this many 8x8 tiles is binned by its own setup
// invocation, which marks its record's upper tile word with ML_RASTER_BINNED (the binning skips it).
#ifndef ML_RASTER_SETUP_BIN_TILES
#define ML_RASTER_SETUP_BIN_TILES 64
#endif
#define ML_RASTER_BINNED 0x8000u
// The finish pass's workgroup: one row of 256 pixels, so each warp reads and resets 256
// consecutive bytes of the store (on an H100 at 2560x1440: 0.089 ms against 0.167 for 8x8 tiles;
// docs/bench/nvidia-h100/raster-finish/).
#define ML_RASTER_FINISH_ROW 256
// A store word (every 32-bit half) where nothing was drawn (include/compute_raster.glsl): past
// every key and id of a frame that resolves by atomicMin, below every inverted one.
#define ML_RASTER_STORE_EMPTY 0x7fffffffu
#define ML_RASTER_SMALL_EXTENT 64    // a triangle rastered by its own invocation spans at most this many pixels...
#define ML_RASTER_SMALL_PIXELS 64    // ...and at most this many pixel centres of its bounds
// Material::info.w bits.
#define ML_MATERIAL_DOUBLE_SIDED 1u
#define ML_MATERIAL_UNLIT 2u  // KHR_materials_unlit: the base colour, no lighting
// Drawn as glass for KHR_materials_transmission, not for BLEND: covers its pixel wholly (OPAQUE)
// or where alpha >= alphaCutoff (MASK), and the opaque scene behind shows through its lobes.
#define ML_MATERIAL_TRANSMISSIVE_COVERAGE 4u
// vec4s in a material (glsl/include/material.glsl, GpuMaterial); info is the fourth. A scene whose
// materials use an extension with maps of its own (ML_FEATURES_EXTENDED_RECORD: KHR_materials_specular
// or ior, KHR_materials_clearcoat, KHR_materials_sheen, KHR_materials_anisotropy,
// KHR_materials_iridescence, KHR_materials_transmission) has every slot's transforms and the
// extensions' vec4s (GpuMaterial::specular, clearcoat, sheen, anisotropy, iridescence,
// transmission, attenuation); every other scene's records
// keep the five core slots, so its shaders read what they read without the extensions.
#define ML_GPU_MATERIAL_VEC4S(extended) (4 + 2 * ((extended) ? ML_TEXTURE_SLOTS : ML_CORE_TEXTURE_SLOTS) + ((extended) ? 7 : 0))
// Radix sort (glsl/radix_sort.comp) and z-binning (--assign zbin, glsl/zbin_assign.comp). Kept
// below 32: llvmpipe offers 32 storage-buffer bindings.
#define ML_SSBO_RADIX_KEYS_IN 20       // keys to sort (one pass reads these...)
#define ML_SSBO_RADIX_VALUES_IN 21     // ...and their values
#define ML_SSBO_RADIX_KEYS_OUT 22      // (...and scatters them here)
#define ML_SSBO_RADIX_VALUES_OUT 23
// The visibility resolve's optional vertex streams (Scene::tangents, uv1, colors). It runs before
// any light assignment, and every pass binds what it reads before it runs, so these share the
// radix sort's points.
#define ML_SSBO_VERTEX_TANGENTS 20
#define ML_SSBO_VERTEX_UV1 21
#define ML_SSBO_VERTEX_COLORS 22
#define ML_SSBO_RADIX_HISTOGRAMS 24    // digit counts per workgroup, digit-major, then their prefix sum
#define ML_SSBO_ZBIN_PARAMS 25         // words per tile, visible lights
#define ML_SSBO_ZBIN_RANGES 26         // per z-bin: first and last sorted index of the lights reaching it
#define ML_SSBO_ZBIN_TILE_MASKS 27     // per tile: one bit per sorted light
#define ML_SSBO_ZBIN_SORTED_LIGHTS 28  // light index at each sorted position
#define ML_SSBO_ZBIN_SORTED_VIEW 29    // view-space centre and radius at each sorted position
#define ML_SSBO_ZBIN_STATS 30          // --stats: lights walked and passing, per workgroup
// --normal-cones (exact lists only, so never in the same frame as z-binning's passes). 30 is
// shared with ML_SSBO_ZBIN_STATS: every pass binds what it reads before it runs.
#define ML_SSBO_NORMAL_BIN_MASKS 31    // --normal-cones: per cluster, a bit per normal bin its visible samples fall in
#define ML_SSBO_NORMAL_CONES 30        // --normal-cones: per (cluster, bin) list, the cone of its samples' normals

// The vertex animation (glsl/animate_vertices.comp, renderer/scene/vertex_animation.h) runs
// first in a frame, before the lights' animation binds their buffers, and every pass binds what
// it reads before it runs, so its inputs share the lights' and the materials' points. It writes
// ML_SSBO_VERTICES and ML_SSBO_VERTEX_TANGENTS.
#define ML_SSBO_DEFORM_VERTICES 0      // per deformed vertex: rest position, normal, tangent, influences
#define ML_SSBO_DEFORM_MESHES 1        // per deformed mesh: where its matrix, joints, weights and deltas are
#define ML_SSBO_MORPH_DELTAS 2         // morph target deltas: position, normal, tangent per (target, vertex)
#define ML_SSBO_ANIMATION_POSE 3       // this frame's mesh and joint matrices and morph weights
#define ML_DEFORM_WORKGROUP 64
// The shadow BVH's refit (glsl/refit_shadow_bvh.comp, renderer/raytracing/shadow_bvh_refit.h)
// runs right after the vertex animation, so its inputs share the deformation's points; it reads
// ML_SSBO_VERTICES and rewrites ML_SSBO_SHADOW_BVH.
#define ML_SSBO_SHADOW_REFIT_CORNERS 0  // per BVH triangle: its three scene vertices
#define ML_SSBO_SHADOW_REFIT_ORDER 1    // the inner nodes, deepest level first
#define ML_SHADOW_REFIT_WORKGROUP 64
#define ML_DEFORM_NO_SKIN 0xFFFFFFFFu  // DeformMesh::pose.y of a mesh without a skin

// Texture units. A material's textures, one unit per slot (ML_SLOT_*): ML_TEX_MATERIAL + slot,
// except base colour, which kept unit 0.
#define ML_TEX_BASE_COLOR 0
#define ML_TEX_METALLIC_ROUGHNESS 6
#define ML_TEX_NORMAL 7
#define ML_TEX_OCCLUSION 8
#define ML_TEX_EMISSIVE 9
// KHR_materials_specular's maps share units with --shadows sampled's reuse and filter inputs: those
// passes sample no material, and every pass binds what it samples before it runs.
#define ML_TEX_SPECULAR 12
#define ML_TEX_SPECULAR_COLOR 13
// KHR_materials_clearcoat's maps share the G-buffer's units: the passes that sample a material
// write the G-buffer or read none, and the lighting, which reads it, samples no material.
#define ML_TEX_CLEARCOAT 2
#define ML_TEX_CLEARCOAT_ROUGHNESS 3
#define ML_TEX_CLEARCOAT_NORMAL 4
// KHR_materials_sheen's maps share the exact G-buffer's fourth target's unit (and the previous shadow
// guide's) and the shadow history's: only the deferred lighting and the --shadows sampled reuse and
// filter read those, and none of them samples a material.
#define ML_TEX_SHEEN_COLOR 14
#define ML_TEX_SHEEN_ROUGHNESS 15
// KHR_materials_anisotropy's map shares the MSAA and supersampling resolve's unit: the resolve
// samples no material, and every pass that does binds its units before it runs.
#define ML_TEX_ANISOTROPY 10
// KHR_materials_iridescence's two maps share one unit, the depth's: the passes that read a depth
// texture (the deferred lighting, the clustering's depth passes, the compute raster's depth copy,
// the glass capture's depth test) sample no material. Every other unit below 16 is taken where a
// material is sampled (11, the only other candidate, holds --shadows rays' alpha layers in the same
// passes), so a material whose iridescence and thickness textures differ is refused by the loader
// (scenes/gltf_materials.cpp); where they are one image, as in glTF's samples, each slot samples it
// with its own transform and texture coordinates.
#define ML_TEX_IRIDESCENCE 1

// KHR_materials_transmission's and KHR_materials_volume's maps, and the opaque frame the
// transmissive surfaces refract. Every unit below 16 is taken where a material is sampled, so the
// two maps take units 16 and 17: GL 4.5 guarantees 16 a stage, every GPU this was tried on
// (NVIDIA, Mesa's llvmpipe) offers 32, and a scene whose maps need them on a GPU with fewer is
// refused in one line (SceneGpu; tests/unit/binding_limits_test.cpp lists these two as the only
// units past the minimum). Only the transparent pass samples them: transmissive surfaces are
// drawn as glass. The opaque frame's copy takes the visibility buffer's unit, which no
// transparent pass reads.
#define ML_TEX_TRANSMISSION 16
#define ML_TEX_THICKNESS 17
#define ML_TEX_REFRACTION_SOURCE 5

#define ML_TEX_DEPTH 1
#define ML_TEX_GBUFFER0 2
#define ML_TEX_GBUFFER1 3
#define ML_TEX_GBUFFER2 4
#define ML_TEX_VISIBILITY 5
// The exact G-buffer's fourth target (specular, unlit), read by the lighting, which samples no
// material and no shadow history (shares the previous guide's unit, read only by the reuse pass).
#define ML_TEX_GBUFFER3 14
// Its fifth (clearcoat), read by the same lighting: it samples no metallic-roughness map either.
#define ML_TEX_GBUFFER4 6
// Its sixth (sheen), read by the same lighting: it samples no normal map either.
#define ML_TEX_GBUFFER5 7
// Its seventh (anisotropy), read by the same lighting: it samples no occlusion map either.
#define ML_TEX_GBUFFER6 8
// Its eighth (iridescence), read by the same lighting:
// it samples no emissive map either.
#define ML_TEX_GBUFFER7 9
#define ML_TEX_RESOLVE_SOURCE 10  // the methods' colour (multisampled or supersampled), read by the resolve
#define ML_TEX_SHADOW_ALPHA 11    // --shadows rays: the MASK images' alpha, a layer each (renderer/raytracing/shadow_alpha.h)
// --shadows sampled (renderer/raytracing/sampled_shadows.h): what the lighting pass left, read by
// the reuse and the filter, and the ratio each keeps.
#define ML_TEX_SHADOW_LIGHT 12            // rgb: the lights' part of the colour, unshadowed; a: the drawn rays' ratio
#define ML_TEX_SHADOW_GUIDE 13            // xyz: world position; w: octahedral normal bits
#define ML_TEX_SHADOW_GUIDE_PREVIOUS 14   // the previous frame's guide
#define ML_TEX_SHADOW_HISTORY 15          // r: a reused ratio, g: the frames it holds

// Image units: 0 to 7 only. GL 4.5 guarantees 8 (GL_MAX_IMAGE_UNITS) and NVIDIA's drivers expose
// exactly 8, so a unit past 7 compiles on Mesa and fails on the H100; passes that never run
// together share a unit (tests/unit/binding_limits_test.cpp holds every ML_IMG_* to it).
#define ML_IMG_HDR 0
#define ML_IMG_LDR 1
#define ML_IMG_GBUFFER0 2
#define ML_IMG_GBUFFER1 3
#define ML_IMG_GBUFFER2 4
#define ML_IMG_SHADOW_LIGHT 5     // --shadows sampled: written by the compute lighting (ML_TEX_SHADOW_LIGHT)...
#define ML_IMG_SHADOW_GUIDE 6     // ...and ML_TEX_SHADOW_GUIDE
#define ML_IMG_SHADOW_HISTORY 7   // the reused ratio this frame (shadow_temporal.comp)
// The exact G-buffer's fourth target, written by the visibility resolve, which runs after the
// compute raster's depth (unit 5) and before the lighting writes the shadow images.
#define ML_IMG_GBUFFER3 5
// And its fifth: the resolve writes no shadow image (the lighting, after it, does).
#define ML_IMG_GBUFFER4 6
// And its sixth: nor the shadow history or rays (the reuse and the sampled lighting write those).
#define ML_IMG_GBUFFER5 7
// And its seventh: the resolve writes no HDR image (the lighting, the resolve of samples, the
// transparent pass and the post passes write that, none of them with the visibility resolve).
#define ML_IMG_GBUFFER6 0
// And its eighth: the resolve writes no LDR image (the tonemap, after the lighting, does).
#define ML_IMG_GBUFFER7 1
// --shadows sampled: the rays the compute lighting drew, traced by glsl/shadow_trace.comp; rows of
// the frame's height a layer: the rays' origin, then each draw's target (sampled_shadow_lighting.glsl).
// Shares its unit with the history: the reuse pass, which writes that, reads no rays.
#define ML_IMG_SHADOW_RAYS 7

// A material's texture slots (Material::info bits, GpuMaterial::transforms).
#define ML_SLOT_BASE_COLOR 0
#define ML_SLOT_METALLIC_ROUGHNESS 1
#define ML_SLOT_NORMAL 2
#define ML_SLOT_OCCLUSION 3
#define ML_SLOT_EMISSIVE 4
#define ML_SLOT_SPECULAR 5        // KHR_materials_specular specularTexture (A)
#define ML_SLOT_SPECULAR_COLOR 6  // KHR_materials_specular specularColorTexture (RGB, sRGB)
#define ML_SLOT_CLEARCOAT 7            // KHR_materials_clearcoat clearcoatTexture (R)
#define ML_SLOT_CLEARCOAT_ROUGHNESS 8  // KHR_materials_clearcoat clearcoatRoughnessTexture (G)
#define ML_SLOT_CLEARCOAT_NORMAL 9     // KHR_materials_clearcoat clearcoatNormalTexture
#define ML_SLOT_SHEEN_COLOR 10          // KHR_materials_sheen sheenColorTexture (RGB, sRGB)
#define ML_SLOT_SHEEN_ROUGHNESS 11      // KHR_materials_sheen sheenRoughnessTexture (A)
#define ML_SLOT_ANISOTROPY 12          // KHR_materials_anisotropy anisotropyTexture (RG direction, B strength)
#define ML_SLOT_IRIDESCENCE 13            // KHR_materials_iridescence iridescenceTexture (R)
#define ML_SLOT_IRIDESCENCE_THICKNESS 14  // KHR_materials_iridescence iridescenceThicknessTexture (G)
#define ML_SLOT_TRANSMISSION 15          // KHR_materials_transmission transmissionTexture (R)
#define ML_SLOT_THICKNESS 16             // KHR_materials_volume thicknessTexture (G)
#define ML_TEXTURE_SLOTS 17
#define ML_CORE_TEXTURE_SLOTS 5   // the slots every material record holds (the rest: ML_FEATURES_EXTENDED_RECORD)

// What a scene's materials use (ML_MATERIAL_FEATURES, a bit mask): every shader that samples a
// material is compiled with only these paths, so a scene that uses none of them pays nothing.
#define ML_FEATURE_METALLIC_ROUGHNESS_MAP 1
#define ML_FEATURE_NORMAL_MAP 2            // also the tangent stream
#define ML_FEATURE_OCCLUSION_MAP 4
#define ML_FEATURE_EMISSIVE 8
#define ML_FEATURE_EMISSIVE_MAP 16
#define ML_FEATURE_TEXTURE_TRANSFORM 32
#define ML_FEATURE_UV1 64                  // some texture reads TEXCOORD_1
#define ML_FEATURE_VERTEX_COLOR 128        // COLOR_0
#define ML_FEATURE_ALPHA_TEST 256          // some material is MASK
#define ML_FEATURE_BLEND 512               // some material is BLEND: the transparent pass exists
#define ML_FEATURE_UNLIT 1024              // some material is KHR_materials_unlit
#define ML_FEATURE_SPECULAR 2048           // some material sets KHR_materials_specular or KHR_materials_ior
#define ML_FEATURE_SPECULAR_MAP 4096       // ...with a specularTexture or specularColorTexture
#define ML_FEATURE_CLEARCOAT 8192          // some material has KHR_materials_clearcoat with a factor above 0
#define ML_FEATURE_CLEARCOAT_MAP 16384     // ...with a clearcoat, clearcoat roughness or clearcoat normal texture
#define ML_FEATURE_SHEEN 32768             // some material has KHR_materials_sheen with a colour above 0
#define ML_FEATURE_SHEEN_MAP 65536         // ...with a sheen colour or sheen roughness texture
#define ML_FEATURE_ANISOTROPY 131072       // some material has KHR_materials_anisotropy with a strength above 0
                                           // (and the tangent stream: ML_FEATURE_NORMAL_MAP with it)
#define ML_FEATURE_ANISOTROPY_MAP 262144   // ...with an anisotropy texture
#define ML_FEATURE_IRIDESCENCE 524288      // some material has KHR_materials_iridescence with a factor above 0
#define ML_FEATURE_IRIDESCENCE_MAP 1048576 // ...with an iridescence or thickness texture
#define ML_FEATURE_TRANSMISSION 2097152    // some material has KHR_materials_transmission with a factor above 0
                                           // (drawn as glass: ML_FEATURE_BLEND with it; KHR_materials_volume too)
#define ML_FEATURE_TRANSMISSION_MAP 4194304 // ...with a transmission or thickness texture
// The features whose materials need the whole record (every slot, the extensions' vec4s).
#define ML_FEATURES_EXTENDED_RECORD \
    (ML_FEATURE_SPECULAR | ML_FEATURE_CLEARCOAT | ML_FEATURE_SHEEN | ML_FEATURE_ANISOTROPY | ML_FEATURE_IRIDESCENCE | ML_FEATURE_TRANSMISSION)

// Light types (docs/lights-and-shading.md). A point light stores this as its cone cosines: below
// any cosine, so the spot test passes everywhere and the cone tests never reject it.
#define ML_POINT_LIGHT_CONE_COS -2.0
// Directional lights ("suns") sit in a uniform block of this many; every shaded point loops over them.
#define ML_MAX_SUN_LIGHTS 16
// Shadow rays: the traversal stack's entries; the builder refuses a tree whose traversal could
// need more (renderer/raytracing/shadow_bvh.h).
#define ML_SHADOW_STACK 64
// The BVH's children per node (--shadow-bvh-width): 2, or 4 and 8 in groups of four children of
// ML_SHADOW_WIDE_GROUP_VEC4S vec4s each (renderer/raytracing/shadow_bvh_layout.h).
#define ML_SHADOW_WIDE_GROUP_VEC4S 7
// A BVH child reference with this bit set is a leaf: (count - 1) in bits 28-30, its first
// triangle in bits 0-27.
#define ML_SHADOW_LEAF_BIT 0x80000000u
// A triangle's material word for one that always blocks (not alpha-tested).
#define ML_SHADOW_OPAQUE 0xFFFFFFFFu
// Spot lights turn about +y as they drift: radians per metre of drift, times a per-light factor in [-1, 1).
#define ML_SPOT_TURN_PER_METRE 0.4

// The light animation's compute workgroup size.
#define ML_ANIMATE_WORKGROUP 256
// Prefix sum: threads per workgroup, and the consecutive elements each sums (a block is their product).
#define ML_SCAN_WORKGROUP 256
#define ML_SCAN_PER_INVOCATION 16
// Screen-space compute passes (depth reduction, active clusters, compute resolve): tile edge.
#define ML_SCREEN_TILE 8
// Fitted slicing's depth reduction: pixels per invocation along each axis.
#define ML_DEPTH_RANGE_BLOCK 4
// Cluster AABB pass workgroup size.
#define ML_CLUSTER_WORKGROUP 64
// Default light-assignment workgroup size (--workgroup overrides it).
#define ML_ASSIGN_WORKGROUP 64
// Exact assignment's count and fill: rounds of candidates a workgroup takes, one an invocation
// a round. An invocation finds its first light by binary search over the lights' candidate
// offsets, the later ones by short forward searches; a 20-step search for every candidate (a
// million lights) took the two passes 0.69-0.85 ms on an H100, now 0.46-0.75 (docs/architecture.md).
#define ML_ASSIGN_CANDIDATE_RUN 8
// Light-list sort, in two dispatches by list length so that short lists (most of them) do not
// hold a long list's threads and shared memory: lists up to ML_SORT_SHORT_MAX entries sort in
// workgroups of ML_SORT_SHORT_WORKGROUP (a rank sort up to ML_SORT_RANK_MAX, bitonic beyond);
// longer ones a workgroup of ML_SORT_LONG_WORKGROUP per chunk of ML_SORT_SHARED_CAPACITY (16 KiB),
// bitonic in shared memory, and the chunks of a list of several merged by rank, a workgroup each.
#define ML_SORT_SHORT_WORKGROUP 64
#define ML_SORT_RANK_MAX 128
#define ML_SORT_SHORT_MAX 256
#define ML_SORT_LONG_WORKGROUP 256
#define ML_SORT_SHARED_CAPACITY 4096
// Radix sort: 8-bit digits (256 buckets, one per thread), each workgroup sorts a block of
// ML_RADIX_WORKGROUP x ML_RADIX_ROUNDS keys.
#define ML_RADIX_WORKGROUP 256
#define ML_RADIX_ROUNDS 4
// Z-binning: z-bins per cluster slice (the bins split each slice of the grid's slicing evenly in f(z)).
#define ML_ZBIN_PER_SLICE 8
// Z-binning: workgroup size of the per-light passes and of the tile-mask pass (words per group).
#define ML_ZBIN_WORKGROUP 64

// --slicing modes, as stored in the cluster grid buffer.
#define ML_SLICING_LINEAR 0
#define ML_SLICING_LOG 1
#define ML_SLICING_FITTED 2

// --view debug modes.
#define ML_VIEW_SHADED 0
#define ML_VIEW_LIGHT_COUNT 1
#define ML_VIEW_SLICES 2
#define ML_VIEW_CLUSTERS 3
#define ML_VIEW_OVERFLOW 4
#define ML_VIEW_ALBEDO 5
#define ML_VIEW_NORMAL 6
#define ML_VIEW_DEPTH 7
#define ML_VIEW_OVERDRAW 8  // fragments shaded per pixel in the raster passes' draw order (renderer/passes/overdraw_pass.h)

// --cull: the light-vs-cluster test of the assignment (the ML_CULL define of its shaders).
#define ML_CULL_AABB 0    // sphere against the cluster's view-space AABB
#define ML_CULL_SPHERE 1  // sphere against the cluster's six frustum planes
#define ML_CULL_CONE 2    // seed 001: the tile's cone against the sphere's, then spherical depth slices

// --normal-cones (Olsson et al. 2012): view-space normal directions quantised on a cube, each
// face cut into CELLS x CELLS cells; a cluster's lists are kept per (cluster, bin). 6 * 2 * 2
// = 24 bins fit one uint mask per cluster.
#define ML_NORMAL_BIN_CELLS 2
#define ML_NORMAL_BINS 24
// Sample normals are summed per list in fixed point, this many units per unit length.
#define ML_NORMAL_SUM_SCALE 1024.0

// Tonemap compute tile.
#define ML_TONEMAP_TILE 8

// Automatic exposure (--exposure auto, renderer/passes/auto_exposure_pass.h): the log-average
// reduction's tile edge, the workgroup that sums the tiles' partials, and the luminance below
// which a pixel counts as empty (the black background around an object is left out). It runs
// after every method and before the tonemap, and every pass binds what it reads before it runs,
// so its buffers share the prefix sum's points.
#define ML_EXPOSURE_TILE 64        // pixels a side of the exposure reduction's tile, summed by
#define ML_EXPOSURE_WORKGROUP 16   // this many invocations a side (16 pixels each)
#define ML_EXPOSURE_MIN_LUMINANCE 1e-6
#define ML_SSBO_EXPOSURE_PARTIALS 10   // per tile: sum of log2 luminance over its lit pixels, their count
#define ML_SSBO_EXPOSURE 11            // the exposure the tonemap applies, and what it was computed from

// Frame uniforms u_counts.y: switches of the shading model (--specular, --brdf).
#define ML_SHADING_SPECULAR 1u
#define ML_SHADING_GGX 2u  // glTF's metallic-roughness BRDF (GGX); without it, normalized Blinn-Phong
// GGX's smallest alpha (roughness^2): roughness 0 is a mirror, whose D is a delta no pixel samples;
// Filament's floor (perceptual roughness 0.045), a highlight of a few pixels that fp32 holds.
#define ML_GGX_MIN_ALPHA 0.002

// Frame uniforms u_counts.z: the falloff of point and spot lights (renderer/lights/light_model.h).
#define ML_FALLOFF_SMOOTH 0       // saturate(1 - (d/r)^4)^2 / (d^2 + 1): the seeds' model (--light-radius, overlap:K)
#define ML_FALLOFF_GLTF 1         // saturate(1 - (d/r)^4) / max(d, dmin)^2: glTF's, r its range or the cut-off radius
#define ML_FALLOFF_STOCHASTIC 2   // max(1 / max(d, dmin)^2, E / I) inside a range drawn per light and frame
#define ML_FALLOFF_UNTRUNCATED 3  // 1 / max(d, dmin)^2 at every distance: the physical reference (naive)
// The guard against inverse square's singularity at the light, in scene units (metres in glTF):
// every falloff but the seeds' divides by max(d, this)^2, so a surface touching a light sees
// at most 10^4 times its intensity. The same in every method and the CPU mirror.
#define ML_LIGHT_MIN_DISTANCE 0.01

// --gbuffer layouts, as the ML_GBUFFER_FORMAT define of the shaders that write or read it.
#define ML_GBUFFER_STANDARD 0       // normal, albedo, specular: three RGBA16F targets (24 B per pixel)
#define ML_GBUFFER_PACKED 1         // one RGBA32UI: octahedral normal 2x16, albedo RGBA8, specular 2x16F (16 B)
#define ML_GBUFFER_TWO_COMPONENT 2  // normal xy + specular, albedo: two RGBA16F (16 B); z = +sqrt(1-x^2-y^2)
#define ML_GBUFFER_EXACT 3          // ray distance, octahedral normal, material: three RGBA32F (48 B), lossless

// Bloom (--bloom): compute tile, and the separable Gaussian's taps each side at half resolution.
#define ML_BLOOM_TILE 8
#define ML_BLOOM_RADIUS 8
#define ML_IMG_BLOOM_IN 5
#define ML_IMG_BLOOM_OUT 6
#define ML_IMG_RASTER_DEPTH 5    // the compute raster's depth (R32F), shared with bloom's input
#define ML_IMG_VISIBILITY_IDS 7  // the visibility raster's triangle ids, written by image atomics (visibility.frag)
#define ML_TEX_OVERDRAW_COUNTS 10 // --view overdraw: the per-pixel fragment counts, read by its colour pass

#endif
