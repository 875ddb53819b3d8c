// An immutable-storage 2D texture (glTextureStorage2D), labelled at creation.
#pragma once

#include <string_view>

#include "renderer/gl/gl_handle.h"

namespace ml::gl {

class Texture2D {
public:
    Texture2D() = default;
    Texture2D(std::string_view label, GLenum internalFormat, int width, int height, int levels = 1);

    GLuint id() const { return handle_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    GLenum format() const { return format_; }
    explicit operator bool() const { return static_cast<bool>(handle_); }

    void setSampling(GLenum minFilter, GLenum magFilter, GLenum wrap) const;

private:
    Handle<TextureDeleter> handle_;
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

// Number of mip levels for a full chain down to 1x1.
int fullMipLevels(int width, int height);

}  // namespace ml::gl
