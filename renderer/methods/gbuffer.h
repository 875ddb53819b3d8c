// The G-buffer of clustered deferred shading: normal, albedo and specular parameters in three
// RGBA16F targets (24 B per pixel) plus the frame's depth; position comes back from depth.
#pragma once

#include "renderer/frame_targets.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/texture.h"

namespace ml {

class GBuffer {
public:
    // Re-creates the targets when the frame size changed; returns the framebuffer.
    const gl::Framebuffer& prepare(const FrameTargets& frame);
    void bindForReading() const;  // at ML_TEX_GBUFFER0..2
    void bindForWriting() const;  // as images at ML_IMG_GBUFFER0..2 (compute writes)
    const gl::Texture2D& normal() const { return normal_; }  // world-space normals (--normal-cones reads them)
    std::size_t bytes() const { return static_cast<std::size_t>(width_) * height_ * 24; }

private:
    int width_ = 0, height_ = 0;
    GLuint depthId_ = 0;
    gl::Texture2D normal_, albedo_, specular_;
    gl::Framebuffer fbo_;
};

}  // namespace ml
