#include "renderer/gl/texture.h"

#include <algorithm>

namespace ml::gl {

Texture2D::Texture2D(std::string_view name, GLenum internalFormat, int width, int height, int levels)
    : width_(width), height_(height), format_(internalFormat) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    handle_ = Handle<TextureDeleter>(id);
    glTextureStorage2D(id, levels, internalFormat, width, height);
    label(GL_TEXTURE, id, name);
    setSampling(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST, levels > 1 ? GL_LINEAR : GL_NEAREST,
                GL_CLAMP_TO_EDGE);
}

Texture2D Texture2D::multisample(std::string_view name, GLenum internalFormat, int width, int height, int samples) {
    if (samples <= 1) return Texture2D(name, internalFormat, width, height);
    Texture2D t;
    t.width_ = width;
    t.height_ = height;
    t.format_ = internalFormat;
    t.samples_ = samples;
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
    t.handle_ = Handle<TextureDeleter>(id);
    // Fixed locations: every pixel's samples sit alike, so a resolve weighs them alike.
    glTextureStorage2DMultisample(id, samples, internalFormat, width, height, GL_TRUE);
    label(GL_TEXTURE, id, name);
    return t;  // multisampled textures have no sampler state
}

void Texture2D::setSampling(GLenum minFilter, GLenum magFilter, GLenum wrap) const {
    glTextureParameteri(handle_.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(handle_.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glTextureParameteri(handle_.id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(handle_.id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
}

int fullMipLevels(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

}  // namespace ml::gl
