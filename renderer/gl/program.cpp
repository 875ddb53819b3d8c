#include "renderer/gl/program.h"

#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

namespace ml::gl {

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log;
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log;
}

}  // namespace

Program::Program(std::string_view name, std::vector<ShaderStage> stages, const shaders::Defines& defines) {
    const GLuint program = glCreateProgram();
    handle_ = Handle<ProgramDeleter>(program);
    std::vector<GLuint> attached;
    for (const ShaderStage& stage : stages) {
        const std::string text = shaders::source(stage.name, defines);
        const GLuint shader = glCreateShader(stage.type);
        const char* ptr = text.c_str();
        glShaderSource(shader, 1, &ptr, nullptr);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = shaderLog(shader);
            glDeleteShader(shader);
            for (GLuint s : attached) glDeleteShader(s);
            throw std::runtime_error("shader " + std::string(stage.name) + " failed to compile:\n" + log +
                                     "(source ids: " + shaders::describeFileTable() + ")");
        }
        glAttachShader(program, shader);
        attached.push_back(shader);
    }
    glLinkProgram(program);
    for (GLuint s : attached) {
        glDetachShader(program, s);
        glDeleteShader(s);
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("program " + std::string(name) + " failed to link:\n" + programLog(program));
    label(GL_PROGRAM, program, name);
}

void Program::set(const char* name, float v) const { glProgramUniform1f(id(), location(name), v); }
void Program::set(const char* name, int v) const { glProgramUniform1i(id(), location(name), v); }
void Program::set(const char* name, unsigned v) const { glProgramUniform1ui(id(), location(name), v); }
void Program::set(const char* name, const glm::vec2& v) const { glProgramUniform2fv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::vec3& v) const { glProgramUniform3fv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::vec4& v) const { glProgramUniform4fv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::uvec2& v) const { glProgramUniform2uiv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::uvec3& v) const { glProgramUniform3uiv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::uvec4& v) const { glProgramUniform4uiv(id(), location(name), 1, glm::value_ptr(v)); }
void Program::set(const char* name, const glm::mat4& v) const {
    glProgramUniformMatrix4fv(id(), location(name), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace ml::gl
