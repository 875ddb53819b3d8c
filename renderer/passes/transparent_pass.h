// The transparent pass (glTF alphaMode BLEND). After a method has left its opaque frame in the
// HDR target, the transparent draw ranges are shaded with the same lights and blended over it
// ("over": colour * alpha + destination * (1 - alpha)), depth-tested against the opaque depth.
//
// One sample per pixel (every method without --msaa): captured, then shaded in compute.
//   [<method>.transparent-count]  once the opaque depth is final (countFragments): the fragments
//                                 that pass it, counted per pixel (renderer/passes/glass_fragments.h)
//   [<method>.transparent-scan]   the counts scanned into where each pixel's fragments start
//   [<method>.transparent-fill]   the fragments stored: depth and triangle, 8 B each
//   [<method>.transparent]        glsl/glass_shade.comp: per pixel, sort by depth, rebuild each
//                                 surface from its triangle, shade, blend back to front; with
//                                 the cluster lists' rounds, tiles with a pixel of two fragments
//                                 or more are split over up to MethodSettings::glassLayerGroups
//                                 workgroups, in four programs (the shader's header says why)
// Deferred and visibility count right after their raster, so the total is long known when the
// fill needs it (read behind a fence, no pipeline drain).
// On GPUs where few SMs run graphics work a fragment shader runs ~30x slower than compute
// (design.md), and the glass's shading was the frame's largest pass; the capture's fragment
// shader is one atomic. Fragments blend in per-pixel depth order, so intersecting and
// interleaved panes blend right from every side.
//
// With --msaa above 1 (naive and Forward+), the forward pass: the ranges shaded in a fragment
// shader and blended by the ROPs into every covered sample, in SceneGpu::transparentOrder (back
// to front per range). The capture keeps one fragment per pixel, not per sample; the forward
// pass is what multisampled glass needs, and naive and Forward+ at the same sample count draw
// the same ranges in the same order, so they stay comparable.
//
// Transmissive materials (KHR_materials_transmission) are drawn here too: they cover their pixel
// (alpha 1, or MASK's cut-off) and show the opaque frame behind them, copied with a mip chain
// before the shading ([<method>.transparent-behind]) and sampled where the refracted view ray
// leaves the volume (docs/lights-and-shading.md). The forward pass (--msaa) does not model them:
// a transmissive scene with --msaa is refused in one line.
//
// Naive's pass loops over every light; the clustered methods' (Forward+, deferred, visibility)
// over the cluster lists, which ClusteredLighting builds to hold every light a transparent
// fragment needs as well (the fitted depth range, --active-only and --normal-cones take the
// transparent surfaces into account). Debug views leave the pass out.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "renderer/clustering/clustering_settings.h"
#include "renderer/frame_context.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/passes/glass_fragments.h"
#include "renderer/scene/raster_program.h"

namespace ml {

class ClusteredLighting;

// How a method draws its glass: samples per pixel (above 1: the forward pass) and the bytes the
// capture may take (0: this GPU's storage-buffer limit).
struct TransparencySettings {
    int msaa = 1;
    std::size_t captureBudget = 0;
    // Workgroups a deep tile's glass is split over (1: none is; MethodSettings::glassLayerGroups).
    std::uint32_t layerGroups = 1;
};

// Whether render() copies the opaque frame the transmissive surfaces see (copyOpaqueFrame) or a
// method that draws its glass in parts (naive's bands) copied it before the first part.
enum class OpaqueFrame { CopyNow, AlreadyCopied };

class TransparentPass {
public:
    // Naive's pass: every fragment loops over every light. `lights`: spots and the light sum alone.
    static TransparentPass overAllLights(std::string timerName, std::uint32_t materialFeatures, const ClusteringSettings& lights,
                                         const TransparencySettings& transparency);
    // A clustered method's pass: each fragment loops over its cluster's list.
    static TransparentPass overClusterLists(std::string timerName, std::uint32_t materialFeatures, const ClusteringSettings& settings,
                                            const TransparencySettings& transparency);

    // The capture's first half, for a method to call as soon as its opaque depth is final (else
    // render() does it). `view`: the frame's debug view (debug views leave the pass out).
    void countFragments(const FrameContext& ctx, DebugView view = DebugView::Shaded);
    // Shades and blends the transparent ranges into the HDR target; nothing where the scene has
    // none (or --transparency off). `lists` is null for naive. Throws std::runtime_error when
    // the capture does not fit (GlassFragments::fill).
    void render(const FrameContext& ctx, const ClusteredLighting* lists, OpaqueFrame opaqueFrame = OpaqueFrame::CopyNow);
    // KHR_materials_transmission: the opaque frame copied, with its mip chain, to be seen through
    // the transmissive surfaces (glass_shade.comp's seeThrough) and bound at ML_TEX_REFRACTION_SOURCE;
    // nothing where no material transmits, the pass draws nothing or the forward pass draws it.
    void copyOpaqueFrame(const FrameContext& ctx);

    // The capture of the last frame (null with --msaa or without BLEND materials).
    const GlassFragments* capture() const { return capture_.get(); }

private:
    TransparentPass(std::string timerName, std::uint32_t materialFeatures, const TransparencySettings& transparency,
                    const char* forwardShader, const shaders::Defines& defines, bool listRounds);
    void renderForward(const FrameContext& ctx, const ClusteredLighting* lists) const;
    void renderCaptured(const FrameContext& ctx, const ClusteredLighting* lists, OpaqueFrame opaqueFrame);
    // The four dispatches of a split frame (glass_shade.comp's kListTiles, then kShadeParts
    // beside kShadeShallowTiles, then kBlendParts).
    void shadeSplittingDeepTiles(const FrameContext& ctx, int textureSet);

    std::string timerName_;
    RasterProgram forward_;                   // --msaa only; empty otherwise or without BLEND
    std::unique_ptr<GlassFragments> capture_;  // one sample per pixel and BLEND only
    gl::Program shade_;
    // The glass's tiles that hold deep pixels are split in up to this many parts (0: the
    // program has no list rounds, or the settings ask for no split).
    std::uint32_t layerGroups_ = 0;
    shaders::Defines splitDefines_;       // shade_'s, for the split's programs
    // glass_shade.comp's kListTiles, kShadeParts, kBlendParts, kShadeShallowTiles
    std::array<gl::Program, 4> splitPrograms_;
    bool seesThrough_ = false;  // some material is transmissive (ML_FEATURE_TRANSMISSION)
    gl::Texture2D opaqueFrame_;  // its copy, full mip chain (RGBA32F, as the HDR target)
};

}  // namespace ml
