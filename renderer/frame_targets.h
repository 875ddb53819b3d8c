// The screen-sized targets every method shares: linear HDR colour, depth, and the tonemapped
// 8-bit result. Re-created by resize(); methods keep their own extra targets (G-buffer).
#pragma once

#include "renderer/gl/framebuffer.h"
#include "renderer/gl/texture.h"

namespace ml {

class FrameTargets {
public:
    FrameTargets(int width, int height, bool stencil) : stencil_(stencil) { resize(width, height); }
    void resize(int width, int height);
    // Depth with an 8-bit stencil (only Forward+'s pre-pass uses it), or 32-bit float depth
    // alone, which the raster passes of the other methods write faster. Re-creates on change.
    void setStencil(bool stencil);

    int width() const { return width_; }
    int height() const { return height_; }
    // RGBA32F: the float output the accuracy numbers are computed on.
    const gl::Texture2D& hdr() const { return hdr_; }
    const gl::Texture2D& depth() const { return depth_; }
    const gl::Texture2D& ldr() const { return ldr_; }
    const gl::Framebuffer& hdrFramebuffer() const { return hdrFbo_; }
    const gl::Framebuffer& ldrFramebuffer() const { return ldrFbo_; }
    const gl::Framebuffer& hdrOnlyFramebuffer() const { return hdrOnlyFbo_; }
    // hdr 16, depth 4 (8 with stencil), ldr 4 bytes per pixel.
    std::size_t bytes() const { return static_cast<std::size_t>(width_) * height_ * (stencil_ ? 28 : 24); }

private:
    int width_ = 0, height_ = 0;
    bool stencil_ = false;
    gl::Texture2D hdr_, depth_, ldr_;
    gl::Framebuffer hdrFbo_, ldrFbo_, hdrOnlyFbo_;
};

}  // namespace ml
