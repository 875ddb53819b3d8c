#include "renderer/gbuffer.h"

#include <string>

#include "glsl/include/bindings.h"
#include "renderer/scene/material_features.h"

namespace ml {

namespace {
int glslFormat(GBufferFormat format) {
    switch (format) {
    case GBufferFormat::Standard: return ML_GBUFFER_STANDARD;
    case GBufferFormat::Packed: return ML_GBUFFER_PACKED;
    case GBufferFormat::TwoComponent: return ML_GBUFFER_TWO_COMPONENT;
    case GBufferFormat::Exact: return ML_GBUFFER_EXACT;
    }
    return ML_GBUFFER_STANDARD;
}
}  // namespace

shaders::Defines GBuffer::defines() const {
    shaders::Defines defines = materialFeatureDefines(materialFeatures_);
    defines.emplace_back("ML_GBUFFER_FORMAT", std::to_string(glslFormat(format_)));
    return defines;
}

const gl::Framebuffer& GBuffer::prepare(const FrameTargets& frame) {
    if (frame.width() != width_ || frame.height() != height_ || frame.depth().id() != depthId_) {
        width_ = frame.width();
        height_ = frame.height();
        depthId_ = frame.depth().id();
        targets_.clear();
        switch (format_) {
        case GBufferFormat::Standard:
            targets_.emplace_back("gbuffer.normal", GL_RGBA16F, width_, height_);
            targets_.emplace_back("gbuffer.albedo", GL_RGBA16F, width_, height_);
            targets_.emplace_back("gbuffer.specular", GL_RGBA16F, width_, height_);
            fbo_ = gl::Framebuffer("gbuffer", {&targets_[0], &targets_[1], &targets_[2]}, &frame.depth());
            break;
        case GBufferFormat::Exact: {
            // The optional targets only where the scene's materials need them (gbuffer_layout.glsl).
            static const char* const kNames[] = {"gbuffer.distance-normal-roughness", "gbuffer.albedo",
                                                 "gbuffer.emissive-occlusion", "gbuffer.specular-unlit", "gbuffer.clearcoat",
                                                 "gbuffer.sheen", "gbuffer.anisotropy", "gbuffer.iridescence"};
            const int count = gbufferExactTargets(materialFeatures_);
            targets_.reserve(count);
            for (int i = 0; i < count; ++i) targets_.emplace_back(kNames[i], GL_RGBA32F, width_, height_);
            std::vector<const gl::Texture2D*> attachments;
            for (const gl::Texture2D& target : targets_) attachments.push_back(&target);
            fbo_ = gl::Framebuffer("gbuffer", attachments, &frame.depth());
            break;
        }
        case GBufferFormat::Packed:
            targets_.emplace_back("gbuffer.packed", GL_RGBA32UI, width_, height_);
            fbo_ = gl::Framebuffer("gbuffer", {&targets_[0]}, &frame.depth());
            break;
        case GBufferFormat::TwoComponent:
            targets_.emplace_back("gbuffer.normal-xy-specular", GL_RGBA16F, width_, height_);
            targets_.emplace_back("gbuffer.albedo", GL_RGBA16F, width_, height_);
            fbo_ = gl::Framebuffer("gbuffer", {&targets_[0], &targets_[1]}, &frame.depth());
            break;
        }
    }
    return fbo_;
}

namespace {
// Targets 0 to 2 have consecutive units; the exact layout's fourth to eighth share units (bindings.h).
constexpr GLuint kTextureUnits[] = {ML_TEX_GBUFFER0, ML_TEX_GBUFFER1, ML_TEX_GBUFFER2, ML_TEX_GBUFFER3,
                                    ML_TEX_GBUFFER4, ML_TEX_GBUFFER5, ML_TEX_GBUFFER6, ML_TEX_GBUFFER7};
constexpr GLuint kImageUnits[] = {ML_IMG_GBUFFER0, ML_IMG_GBUFFER1, ML_IMG_GBUFFER2, ML_IMG_GBUFFER3,
                                  ML_IMG_GBUFFER4, ML_IMG_GBUFFER5, ML_IMG_GBUFFER6, ML_IMG_GBUFFER7};
}  // namespace

void GBuffer::bindForReading() const {
    for (std::size_t i = 0; i < targets_.size(); ++i)
        glBindTextureUnit(kTextureUnits[i], targets_[i].id());
}

void GBuffer::bindForWriting() const {
    for (std::size_t i = 0; i < targets_.size(); ++i)
        glBindImageTexture(kImageUnits[i], targets_[i].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, targets_[i].format());
}

}  // namespace ml
