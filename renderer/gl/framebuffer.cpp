#include "renderer/gl/framebuffer.h"

#include <stdexcept>
#include <string>

namespace ml::gl {

Framebuffer::Framebuffer(std::string_view name, const std::vector<const Texture2D*>& colors, const Texture2D* depth) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    handle_ = Handle<FramebufferDeleter>(id);
    std::vector<GLenum> drawBuffers;
    GLenum attachment = GL_COLOR_ATTACHMENT0;
    for (const Texture2D* color : colors) {
        glNamedFramebufferTexture(id, attachment, color->id(), 0);
        drawBuffers.push_back(attachment++);
    }
    if (drawBuffers.empty()) {
        glNamedFramebufferDrawBuffer(id, GL_NONE);
    } else {
        glNamedFramebufferDrawBuffers(id, static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    }
    if (depth) {
        const bool hasStencil = depth->format() == GL_DEPTH32F_STENCIL8 || depth->format() == GL_DEPTH24_STENCIL8;
        glNamedFramebufferTexture(id, hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth->id(), 0);
    }
    label(GL_FRAMEBUFFER, id, name);
    const GLenum status = glCheckNamedFramebufferStatus(id, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("framebuffer '" + std::string(name) + "' is incomplete (status 0x" +
                                 std::to_string(status) + ")");
    }
}

}  // namespace ml::gl
