#include "renderer/frame_targets.h"

namespace ml {

void FrameTargets::resize(int width, int height) {
    width_ = width;
    height_ = height;
    hdr_ = gl::Texture2D("frame.hdr", GL_RGBA32F, width, height);
    // Depth with stencil: Forward+ marks each pixel's first nearest fragment in the stencil so
    // exactly that one is shaded, as with naive's single depth-tested pass (ties included).
    depth_ = gl::Texture2D("frame.depth", GL_DEPTH32F_STENCIL8, width, height);
    ldr_ = gl::Texture2D("frame.ldr", GL_RGBA8, width, height);
    hdrFbo_ = gl::Framebuffer("frame.hdr+depth", {&hdr_}, &depth_);
    ldrFbo_ = gl::Framebuffer("frame.ldr", {&ldr_}, nullptr);
    hdrOnlyFbo_ = gl::Framebuffer("frame.hdr", {&hdr_}, nullptr);
}

}  // namespace ml
