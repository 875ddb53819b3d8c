// The interface every shading method implements. Methods are siblings over the same scene,
// lights, uniforms and targets, so switching method changes nothing else (style.md, practice 1).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "renderer/clustering/clustering_settings.h"
#include "renderer/frame_context.h"
#include "renderer/gbuffer_format.h"
#include "renderer/methods/visibility_raster.h"

namespace ml {

class ClusteredLighting;
class GlassFragments;

class ShadingMethod {
public:
    virtual ~ShadingMethod() = default;
    virtual std::string name() const = 0;
    // Leaves the shaded linear colour (or a debug view's display colour) in ctx.targets.hdr().
    virtual void render(const FrameContext& ctx) = 0;
    // The light lists of a clustered method (null for naive).
    virtual const ClusteredLighting* clustering() const { return nullptr; }
    // Whether the frame's depth target needs a stencil (FrameTargets::configure).
    virtual bool needsStencil() const { return false; }
    // Bytes of screen-sized targets the method owns beyond FrameTargets (the G-buffer).
    virtual std::size_t extraTargetBytes() const { return 0; }
    // The transparent pass's capture of the last frame (null with --msaa or without BLEND).
    virtual const GlassFragments* transparentCapture() const { return nullptr; }
};

enum class MethodKind { Naive, ForwardPlus, Deferred, Visibility };

// The lighting pass of clustered deferred: a full-screen fragment pass or a compute pass.
enum class Resolve { Fragment, Compute };
Resolve parseResolve(const std::string& text);  // throws std::invalid_argument
const char* resolveName(Resolve resolve);

struct MethodSettings {
    MethodKind kind = MethodKind::Naive;
    ClusteringSettings clustering;
    Resolve resolve = Resolve::Compute;
    // Deferred and visibility. Exact by default: the only layout that holds the accuracy contract
    // on real content (docs/accuracy-and-stability.md#g-buffer-precision-on-glossy-normal-mapped-surfaces).
    GBufferFormat gbuffer = GBufferFormat::Exact;
    // Forward+ and deferred: a depth pre-pass, then the shading (Forward+) or the G-buffer
    // (deferred) with EQUAL, each pixel once; off: one depth-tested pass over every fragment.
    bool prepass = true;
    // --msaa: samples per pixel of the colour and depth the method draws into (1, 2, 4, 8).
    int msaa = 1;
    // Bytes the transparent pass's capture may take (renderer/passes/glass_fragments.h); 0: this
    // GPU's storage-buffer limit. Tests lower it to see a frame refused.
    std::size_t transparentCaptureBudget = 0;
    // The most workgroups the transparent shading splits a deep tile over (glsl/glass_shade.comp:
    // a tile with a pixel of two fragments or more, in as many parts as its deepest pixel has
    // fragments, up to this; 1: no split, as tests set it to hold the split to the one pass, bit
    // for bit). Measured on an H200: docs/bench/nvidia-h200/glass-layers/.
    std::uint32_t glassLayerGroups = 4;
    // Visibility: --vis-raster (auto: the hardware raster for now; ComputeRaster::resolve says why).
    VisibilityRaster visibilityRaster = VisibilityRaster::Auto;
};

// Why a method cannot draw with --msaa above 1, or null where it can (naive, forward-plus).
const char* msaaRefusal(MethodKind kind);
// --msaa N: 1, 2, 4 or 8 (GL's sample counts; the GPU's own limit is checked by FrameTargets).
// Throws std::invalid_argument naming the flag and the value.
int validMsaa(long long samples);

// Names as the command line spells them.
const std::vector<std::string>& methodNames();
// Throws std::invalid_argument naming the value.
MethodKind parseMethod(const std::string& text);
std::string methodName(MethodKind kind);

// materialFeatures: SceneGpu::materialFeatures() of the scene the method will draw.
std::unique_ptr<ShadingMethod> createMethod(const MethodSettings& settings, std::uint32_t materialFeatures);

}  // namespace ml
