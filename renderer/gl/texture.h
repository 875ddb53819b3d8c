// An immutable-storage 2D texture (glTextureStorage2D), or a multisampled one
// (glTextureStorage2DMultisample), labelled at creation.
#pragma once

#include <string_view>

#include "renderer/gl/gl_handle.h"

namespace ml::gl {

class Texture2D {
public:
    Texture2D() = default;
    Texture2D(std::string_view label, GLenum internalFormat, int width, int height, int levels = 1);
    // GL_TEXTURE_2D_MULTISAMPLE with fixed sample locations; samples 1 gives a plain texture.
    static Texture2D multisample(std::string_view label, GLenum internalFormat, int width, int height, int samples);

    GLuint id() const { return handle_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum format() const { return format_; }
    int samples() const { return samples_; }  // 1: not multisampled
    explicit operator bool() const { return static_cast<bool>(handle_); }

    void setSampling(GLenum minFilter, GLenum magFilter, GLenum wrap) const;

private:
    Handle<TextureDeleter> handle_;
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
    int samples_ = 1;
};

// Number of mip levels for a full chain down to 1x1.
int fullMipLevels(int width, int height);

}  // namespace ml::gl
