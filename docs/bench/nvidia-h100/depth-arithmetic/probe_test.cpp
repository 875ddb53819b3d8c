// PROBE (not for commit): dumps the hardware's depth of random triangles with their clip
// positions, for an offline search of the arithmetic that gives the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gpu_test.h"
#include "renderer/gl/gl_api.h"

namespace ml::test {
namespace {

GLuint compile(GLenum type, const char* src) {
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    char log[2000] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    EXPECT_TRUE(ok) << log;
    return s;
}

const char* kVert = R"(#version 450 core
layout(std430, binding = 0) readonly buffer Clip { vec4 clip[]; };
flat out uint v_id;
void main() { gl_Position = clip[gl_VertexID]; v_id = uint(gl_VertexID) / 3u + 1u; }
)";
const char* kFrag = R"(#version 450 core
flat in uint v_id;
layout(location = 0) out uint o_id;
layout(location = 1) out uint o_z;
void main() { o_id = v_id; o_z = floatBitsToUint(gl_FragCoord.z); }
)";

TEST_F(GpuTest, DepthProbeDump) {
    const char* dir = std::getenv("ML_DEPTH_PROBE");
    if (!dir) GTEST_SKIP();
    const int W = 640, H = 360, N = 600, B = 8;
    GLuint prog = glCreateProgram();
    glAttachShader(prog, compile(GL_VERTEX_SHADER, kVert));
    glAttachShader(prog, compile(GL_FRAGMENT_SHADER, kFrag));
    glLinkProgram(prog);
    GLuint tex[3], fbo, vao, buf;
    glCreateTextures(GL_TEXTURE_2D, 3, tex);
    glTextureStorage2D(tex[0], 1, GL_R32UI, W, H);
    glTextureStorage2D(tex[1], 1, GL_R32UI, W, H);
    glTextureStorage2D(tex[2], 1, GL_DEPTH_COMPONENT32F, W, H);
    glCreateFramebuffers(1, &fbo);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, tex[0], 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, tex[1], 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, tex[2], 0);
    const GLenum bufs[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo, 2, bufs);
    glCreateVertexArrays(1, &vao);
    glCreateBuffers(1, &buf);
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> u01(0.f, 1.f);
    for (int b = 0; b < B; ++b) {
        const float nearZ = b % 2 ? 0.05f : 0.5f, farZ = b % 4 < 2 ? 300.f : 60.f;
        const glm::mat4 proj = glm::perspective(glm::radians(60.f), float(W) / H, nearZ, farZ);
        std::vector<glm::vec4> clip;
        for (int t = 0; t < N; ++t) {
            const float d = nearZ * 2 * std::pow(farZ / (nearZ * 2), u01(rng));
            const float px = std::pow(300.f, u01(rng)) * (t % 7 == 0 ? 3.f : 1.f);  // size in pixels
            const float world = px * d / (H * 0.5f / std::tan(glm::radians(30.f)));
            const glm::vec3 c((u01(rng) * 2 - 1) * d * 0.75f, (u01(rng) * 2 - 1) * d * 0.6f, -d);
            for (int k = 0; k < 3; ++k) {
                glm::vec3 p = c + world * glm::vec3(u01(rng) * 2 - 1, u01(rng) * 2 - 1, u01(rng) * 2 - 1);
                p.z = std::min(p.z, -nearZ * 1.01f);
                clip.push_back(proj * glm::vec4(p, 1.f));
            }
        }
        glNamedBufferData(buf, GLsizeiptr(clip.size() * sizeof(glm::vec4)), clip.data(), GL_STATIC_DRAW);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buf);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, W, H);
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferuiv(fbo, GL_COLOR, 0, zero);
        glClearNamedFramebufferuiv(fbo, GL_COLOR, 1, zero);
        const float one = 1.f;
        glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &one);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE);
        glUseProgram(prog);
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(clip.size()));
        std::vector<std::uint32_t> ids(W * H), z(W * H);
        std::vector<float> depth(W * H);
        glGetTextureImage(tex[0], 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(ids.size() * 4), ids.data());
        glGetTextureImage(tex[1], 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(z.size() * 4), z.data());
        glGetTextureImage(tex[2], 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * 4), depth.data());
        const std::string stem = std::string(dir) + "/b" + std::to_string(b);
        std::ofstream(stem + ".clip", std::ios::binary).write(reinterpret_cast<const char*>(clip.data()), std::streamsize(clip.size() * 16));
        std::ofstream(stem + ".ids", std::ios::binary).write(reinterpret_cast<const char*>(ids.data()), std::streamsize(ids.size() * 4));
        std::ofstream(stem + ".fragz", std::ios::binary).write(reinterpret_cast<const char*>(z.data()), std::streamsize(z.size() * 4));
        std::ofstream(stem + ".depth", std::ios::binary).write(reinterpret_cast<const char*>(depth.data()), std::streamsize(depth.size() * 4));
        std::ofstream(stem + ".proj", std::ios::binary).write(reinterpret_cast<const char*>(&proj), 64);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace ml::test
