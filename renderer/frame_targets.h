// The screen-sized targets every method shares: linear HDR colour, depth, and the tonemapped
// 8-bit result. Re-created by resize(); methods keep their own extra targets (G-buffer).
#pragma once

#include "renderer/gl/framebuffer.h"
#include "renderer/gl/texture.h"

namespace ml {

class FrameTargets {
public:
    FrameTargets(int width, int height) { resize(width, height); }
    void resize(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    // RGBA32F: the float output the accuracy numbers are computed on.
    const gl::Texture2D& hdr() const { return hdr_; }
    const gl::Texture2D& depth() const { return depth_; }
    const gl::Texture2D& ldr() const { return ldr_; }
    const gl::Framebuffer& hdrFramebuffer() const { return hdrFbo_; }
    const gl::Framebuffer& ldrFramebuffer() const { return ldrFbo_; }
    const gl::Framebuffer& hdrOnlyFramebuffer() const { return hdrOnlyFbo_; }
    // hdr 16, depth-stencil 8, ldr 4 bytes per pixel.
    std::size_t bytes() const { return static_cast<std::size_t>(width_) * height_ * 28; }

private:
    int width_ = 0, height_ = 0;
    gl::Texture2D hdr_, depth_, ldr_;
    gl::Framebuffer hdrFbo_, ldrFbo_, hdrOnlyFbo_;
};

}  // namespace ml
