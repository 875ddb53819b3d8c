#include "renderer/methods/gbuffer.h"

#include "glsl/include/bindings.h"

namespace ml {

const gl::Framebuffer& GBuffer::prepare(const FrameTargets& frame) {
    if (frame.width() != width_ || frame.height() != height_ || frame.depth().id() != depthId_) {
        width_ = frame.width();
        height_ = frame.height();
        depthId_ = frame.depth().id();
        normal_ = gl::Texture2D("gbuffer.normal", GL_RGBA16F, width_, height_);
        albedo_ = gl::Texture2D("gbuffer.albedo", GL_RGBA16F, width_, height_);
        specular_ = gl::Texture2D("gbuffer.specular", GL_RGBA16F, width_, height_);
        fbo_ = gl::Framebuffer("gbuffer", {&normal_, &albedo_, &specular_}, &frame.depth());
    }
    return fbo_;
}

void GBuffer::bindForReading() const {
    glBindTextureUnit(ML_TEX_GBUFFER0, normal_.id());
    glBindTextureUnit(ML_TEX_GBUFFER1, albedo_.id());
    glBindTextureUnit(ML_TEX_GBUFFER2, specular_.id());
}

void GBuffer::bindForWriting() const {
    glBindImageTexture(ML_IMG_GBUFFER0, normal_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(ML_IMG_GBUFFER1, albedo_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(ML_IMG_GBUFFER2, specular_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
}

}  // namespace ml
