// Move-only ownership of one GL object name; the deleter runs when the owner goes away.
#pragma once

#include <string_view>
#include <utility>

#include "renderer/gl/gl_api.h"

namespace ml::gl {

template <typename Deleter>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Deleter{}(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

struct BufferDeleter { void operator()(GLuint id) const { glDeleteBuffers(1, &id); } };
struct TextureDeleter { void operator()(GLuint id) const { glDeleteTextures(1, &id); } };
struct FramebufferDeleter { void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); } };
struct VertexArrayDeleter { void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); } };
struct ProgramDeleter { void operator()(GLuint id) const { glDeleteProgram(id); } };
struct QueryDeleter { void operator()(GLuint id) const { glDeleteQueries(1, &id); } };
struct SamplerDeleter { void operator()(GLuint id) const { glDeleteSamplers(1, &id); } };

// KHR_debug object label, so capture tools and debug messages show names, not numbers.
inline void label(GLenum identifier, GLuint id, std::string_view name) {
    glObjectLabel(identifier, id, static_cast<GLsizei>(name.size()), name.data());
}

// A scoped debug group: the name shows in capture tools around the commands it encloses.
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name) {
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
    }
    ~DebugGroup() { glPopDebugGroup(); }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace ml::gl
