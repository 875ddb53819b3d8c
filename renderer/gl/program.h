// A linked GLSL program built from embedded shaders (glsl/), labelled with the shader names.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/gl_handle.h"
#include "renderer/gl/shader_sources.h"

namespace ml::gl {

struct ShaderStage {
    GLenum type;
    std::string_view name;  // embedded shader name
};

class Program {
public:
    Program() = default;
    // Throws std::runtime_error with the compiler's log and the shader's name on failure.
    Program(std::string_view label, std::vector<ShaderStage> stages, const shaders::Defines& defines = {});

    static Program compute(std::string_view name, const shaders::Defines& defines = {}) {
        return Program(name, {{GL_COMPUTE_SHADER, name}}, defines);
    }

    GLuint id() const { return handle_.id(); }
    void use() const { glUseProgram(handle_.id()); }
    explicit operator bool() const { return static_cast<bool>(handle_); }

    // Uniform setters by name (DSA: no need to bind the program). Unknown names are ignored
    // (a uniform the compiler removed as unused is not an error).
    void set(const char* name, float v) const;
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::uvec2& v) const;
    void set(const char* name, const glm::uvec3& v) const;
    void set(const char* name, const glm::uvec4& v) const;
    void set(const char* name, const glm::mat4& v) const;

private:
    GLint location(const char* name) const { return glGetUniformLocation(handle_.id(), name); }
    Handle<ProgramDeleter> handle_;
};

// Dispatch enough workgroups of `groupSize` to cover `count` items.
inline GLuint groupsFor(std::size_t count, std::size_t groupSize) {
    return static_cast<GLuint>((count + groupSize - 1) / groupSize);
}

// The device's limit on compute workgroups along x (GL_MAX_COMPUTE_WORK_GROUP_COUNT); a dispatch
// past it goes on in y.
inline std::uint32_t maxWorkGroupsX() {
    GLint groups = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &groups);
    return static_cast<std::uint32_t>(std::max(groups, 1));
}

}  // namespace ml::gl
