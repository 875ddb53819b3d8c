// A framebuffer object with its attachments named at creation.
#pragma once

#include <initializer_list>
#include <string_view>
#include <vector>

#include "renderer/gl/gl_handle.h"
#include "renderer/gl/texture.h"

namespace ml::gl {

class Framebuffer {
public:
    Framebuffer() = default;
    // colors: attached to GL_COLOR_ATTACHMENT0.. in order; depth may be null.
    Framebuffer(std::string_view label, std::initializer_list<const Texture2D*> colors, const Texture2D* depth)
        : Framebuffer(label, std::vector<const Texture2D*>(colors), depth) {}
    Framebuffer(std::string_view label, const std::vector<const Texture2D*>& colors, const Texture2D* depth);

    GLuint id() const { return handle_.id(); }
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, handle_.id()); }

private:
    Handle<FramebufferDeleter> handle_;
};

}  // namespace ml::gl
