// The screen-sized targets every method shares: linear HDR colour, depth, and the tonemapped
// 8-bit result. Re-created by resize(); methods keep their own extra targets (G-buffer).
//
// With --msaa the colour and depth the methods draw into are multisampled; with --supersample
// they are K times the output size. Either way the resolve (renderer/passes/resolve_pass.h) averages
// them into outputHdr(), one linear value per output pixel, before bloom and the tonemap:
//
//   methods ──> hdr() + depth()   [N samples, or K*W x K*H]  ──resolve──> outputHdr() ──> ldr()
//   (plain: hdr() is outputHdr(), no resolve)
#pragma once

#include <cstddef>

#include "renderer/gl/buffer.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/texture.h"

namespace ml {

// How the methods' targets sample an output pixel.
struct TargetSampling {
    int msaa = 1;         // --msaa: samples per pixel of the colour and depth the methods draw into
    int supersample = 1;  // --supersample: the methods draw at K*W x K*H, box-filtered down
    bool resolves() const { return msaa > 1 || supersample > 1; }
    bool operator==(const TargetSampling&) const = default;
};

// Where a raster that wrote the opaque depth left the least and greatest view depth of its drawn
// pixels (two words of `buffer` from word `word`, float bits), so that fitted slicing need not
// read the depth again (ClusteredLighting; the compute raster's finish). None: no buffer.
struct ViewDepthRange {
    const gl::Buffer* buffer = nullptr;
    unsigned word = 0;
};

class FrameTargets {
public:
    FrameTargets(int width, int height, bool stencil, TargetSampling sampling = {})
        : stencil_(stencil), sampling_(sampling) {
        resize(width, height);
    }
    // The output size; throws std::invalid_argument when the GPU cannot hold the drawn size.
    void resize(int width, int height);
    // What a method needs of the targets, re-created once where either changes. `stencil`: depth
    // with an 8-bit stencil (only Forward+'s pre-pass uses it), or 32-bit float depth alone, which
    // the raster passes of the other methods write faster. Throws std::invalid_argument naming
    // the flag (--msaa over this GPU's sample limits, --supersample past its texture size)
    // before allocating anything.
    void configure(bool stencil, TargetSampling sampling);

    // Where the methods draw: the output size times --supersample.
    int width() const { return width_ * sampling_.supersample; }
    int height() const { return height_ * sampling_.supersample; }
    int samples() const { return sampling_.msaa; }
    const TargetSampling& sampling() const { return sampling_; }
    // RGBA32F (multisampled with --msaa): what the methods shade into, and its depth.
    const gl::Texture2D& hdr() const { return hdr_; }
    const gl::Texture2D& depth() const { return depth_; }
    // The opaque depth as the passes that sample it read it: depth(), or, for the frame of a
    // method that rastered by compute (the visibility buffer's compute raster), its R32F depth.
    // FrameRenderer clears it before each method's frame.
    const gl::Texture2D& opaqueDepth() const { return computedDepth_ ? *computedDepth_ : depth_; }
    // Whether opaqueDepth() is a computed depth, not depth() (which then holds no opaque surface,
    // but where a raster copied some for passes that test in hardware: ComputeRaster::Extras).
    bool hasComputedDepth() const { return computedDepth_ != nullptr; }
    // The opaque depth's view depth range where the raster that wrote it reduced it (cleared with it).
    const ViewDepthRange& opaqueViewDepthRange() const { return opaqueRange_; }
    void setComputedDepth(const gl::Texture2D* depth, ViewDepthRange range = {}) {
        computedDepth_ = depth;
        opaqueRange_ = range;
    }
    const gl::Framebuffer& hdrFramebuffer() const { return hdrFbo_; }
    const gl::Framebuffer& hdrOnlyFramebuffer() const { return hdrOnlyFbo_; }

    // The image: one sample per output pixel. RGBA32F, the float output the accuracy numbers
    // are computed on; bloom and the tonemap work here.
    int outputWidth() const { return width_; }
    int outputHeight() const { return height_; }
    const gl::Texture2D& outputHdr() const { return sampling_.resolves() ? resolved_ : hdr_; }
    const gl::Texture2D& ldr() const { return ldr_; }
    const gl::Framebuffer& ldrFramebuffer() const { return ldrFbo_; }
    // Per drawn sample: hdr 16, depth 4 (8 with stencil); per output pixel: ldr 4, and the
    // resolved hdr 16 when there is a resolve.
    std::size_t bytes() const;

private:
    void create();

    int width_ = 0, height_ = 0;
    bool stencil_ = false;
    TargetSampling sampling_;
    gl::Texture2D hdr_, depth_, resolved_, ldr_;
    const gl::Texture2D* computedDepth_ = nullptr;
    ViewDepthRange opaqueRange_;
    gl::Framebuffer hdrFbo_, ldrFbo_, hdrOnlyFbo_;
};

// Throws std::invalid_argument with one line naming the flag when this GPU cannot draw
// `sampling` at width x height (GL_MAX_SAMPLES and the multisample texture limits; the texture
// and framebuffer size limits for the supersampled size).
void checkSamplingFits(const TargetSampling& sampling, int width, int height);

}  // namespace ml
