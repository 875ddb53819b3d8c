// The G-buffer of clustered deferred shading and the visibility buffer, in one of the --gbuffer
// layouts (gbuffer_format.h), plus the frame's depth; position comes back from depth.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/frame_targets.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/shader_sources.h"
#include "renderer/gl/texture.h"
#include "renderer/gbuffer_format.h"

namespace ml {

class GBuffer {
public:
    explicit GBuffer(GBufferFormat format = GBufferFormat::Packed, std::uint32_t materialFeatures = 0)
        : format_(format), materialFeatures_(materialFeatures) {}
    GBufferFormat format() const { return format_; }
    // ML_GBUFFER_FORMAT and ML_MATERIAL_FEATURES (what is stored: emissive only where the scene
    // has some) for the shaders that write or read this layout.
    shaders::Defines defines() const;
    // Re-creates the targets when the frame size changed; returns the framebuffer.
    const gl::Framebuffer& prepare(const FrameTargets& frame);
    // At ML_TEX_GBUFFER0.. (one texture per target); read with fetchGBuffer/decodeGBuffer
    // (include/gbuffer_fetch.glsl) by the lighting and by --normal-cones' normal bins.
    void bindForReading() const;
    void bindForWriting() const;  // as images at ML_IMG_GBUFFER0.. (compute writes)
    std::size_t bytes() const {
        return static_cast<std::size_t>(width_) * height_ * gbufferBytesPerPixel(format_, materialFeatures_);
    }

private:
    GBufferFormat format_;
    std::uint32_t materialFeatures_;
    int width_ = 0, height_ = 0;
    GLuint depthId_ = 0;
    std::vector<gl::Texture2D> targets_;
    gl::Framebuffer fbo_;
};

}  // namespace ml
