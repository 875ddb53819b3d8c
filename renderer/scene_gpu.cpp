#include "renderer/scene_gpu.h"

#include <algorithm>
#include <cstddef>

#include "glsl/include/bindings.h"
#include "renderer/gpu_types.h"

namespace ml {

SceneGpu::SceneGpu(const Scene& scene) : draws_(scene.draws), indexCount_(scene.indices.size()) {
    vertices_ = gl::Buffer::fromSpan<Vertex>("scene.vertices", scene.vertices, 0);
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("scene.indices", scene.indices, 0);

    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    vao_ = gl::Handle<gl::VertexArrayDeleter>(vao);
    gl::label(GL_VERTEX_ARRAY, vao, "scene.vao");
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glVertexArrayElementBuffer(vao, indices_.id());
    const GLuint offsets[3] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, uv)};
    const GLint sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao, a);
        glVertexArrayAttribFormat(vao, a, sizes[a], GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao, a, 0);
    }

    // Base-colour textures: sRGB storage, so sampling returns linear values; full mip chains.
    for (const Image& image : scene.images) {
        gl::Texture2D tex("texture." + image.name, GL_SRGB8_ALPHA8, image.width, image.height,
                          gl::fullMipLevels(image.width, image.height));
        // Scene images are stored top row first; glTF UVs put v = 0 at the top, so upload as is.
        glTextureSubImage2D(tex.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
        glGenerateTextureMipmap(tex.id());
        tex.setSampling(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT);
        textures_.push_back(std::move(tex));
    }
    white_ = gl::Texture2D("texture.white", GL_SRGB8_ALPHA8, 1, 1);
    const std::uint8_t white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(white_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);

    std::vector<GpuMaterial> materials;
    for (const Material& m : scene.materials) {
        const bool textured = m.baseColorTexture >= 0 && m.baseColorTexture < static_cast<int>(textures_.size());
        materials.push_back({m.baseColorFactor, glm::vec4(m.specularStrength, m.shininess, textured ? 1.0f : 0.0f,
                                                          textured ? float(m.baseColorTexture) : -1.0f)});
        materialTexture_.push_back(textured ? m.baseColorTexture : -1);
    }
    if (materials.empty()) materials.push_back({glm::vec4(1.0f), glm::vec4(0.25f, 32.0f, 0.0f, -1.0f)});
    materials_ = gl::Buffer::fromSpan<GpuMaterial>("scene.materials", materials, 0);

    std::vector<std::uint32_t> triangleMaterials(scene.indices.size() / 3, 0u);
    for (const DrawRange& d : scene.draws) {
        const std::uint32_t material = d.material < scene.materials.size() ? d.material : 0u;
        std::fill_n(triangleMaterials.begin() + d.firstIndex / 3, d.indexCount / 3, material);
    }
    triangleMaterials_ = gl::Buffer::fromSpan<std::uint32_t>("scene.triangle-materials", triangleMaterials, 0);
}

void SceneGpu::draw(const gl::Program& program) const {
    glBindVertexArray(vao_.id());
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MATERIALS);
    const GLint materialLocation = glGetUniformLocation(program.id(), "u_materialIndex");
    for (const DrawRange& d : draws_) {
        const int texture = d.material < materialTexture_.size() ? materialTexture_[d.material] : -1;
        glBindTextureUnit(ML_TEX_BASE_COLOR, texture >= 0 ? textures_[static_cast<std::size_t>(texture)].id() : white_.id());
        glProgramUniform1ui(program.id(), materialLocation, d.material < materialTexture_.size() ? d.material : 0u);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(static_cast<std::uintptr_t>(d.firstIndex) * sizeof(std::uint32_t)));
    }
}

void SceneGpu::drawTriangleIds(const gl::Program& program) const {
    glBindVertexArray(vao_.id());
    const GLint firstTriangle = glGetUniformLocation(program.id(), "u_firstTriangle");
    for (const DrawRange& d : draws_) {
        glProgramUniform1ui(program.id(), firstTriangle, d.firstIndex / 3);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(static_cast<std::uintptr_t>(d.firstIndex) * sizeof(std::uint32_t)));
    }
}

void SceneGpu::bindGeometryForCompute() const {
    vertices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTICES);
    indices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_INDICES);
    triangleMaterials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_TRIANGLE_MATERIALS);
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MATERIALS);
}

void SceneGpu::drawDepthOnly() const {
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount_), GL_UNSIGNED_INT, nullptr);
}

std::size_t SceneGpu::bytes() const {
    return vertices_.size() + indices_.size() + materials_.size() + triangleMaterials_.size();
}

}  // namespace ml
