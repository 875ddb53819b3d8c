#include "renderer/scene_gpu.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <stdexcept>

#include "glsl/include/bindings.h"
#include "renderer/gpu_types.h"
#include "renderer/shading_reference.h"

namespace ml {
namespace {

// GL's layout of one multi-draw-indirect command.
struct DrawElementsIndirectCommand {
    std::uint32_t count, instanceCount, firstIndex, baseVertex, baseInstance;
};
static_assert(sizeof(DrawElementsIndirectCommand) == 20, "GL's indirect command layout");

}  // namespace

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
        const int texture = m.baseColorTexture.image;
        const bool textured = texture >= 0 && texture < static_cast<int>(textures_.size());
        const ShadingTerms t = shadingTerms(glm::vec3(m.baseColorFactor), m.metallic, m.roughness);
        materials.push_back({m.baseColorFactor, glm::vec4(t.specular.x, t.shininess, textured ? 1.0f : 0.0f,
                                                          textured ? float(texture) : -1.0f)});
        materialTexture_.push_back(textured ? texture : -1);
        materialDoubleSided_.push_back(m.doubleSided ? 1 : 0);
    }
    if (materials.empty()) materials.push_back({glm::vec4(1.0f), glm::vec4(0.25f, 32.0f, 0.0f, -1.0f)});
    materials_ = gl::Buffer::fromSpan<GpuMaterial>("scene.materials", materials, 0);

    std::vector<std::uint32_t> triangleMaterials(scene.indices.size() / 3, 0u);
    for (const DrawRange& d : scene.draws) {
        const std::uint32_t material = d.material < scene.materials.size() ? d.material : 0u;
        std::fill_n(triangleMaterials.begin() + d.firstIndex / 3, d.indexCount / 3, material);
    }
    triangleMaterials_ = gl::Buffer::fromSpan<std::uint32_t>("scene.triangle-materials", triangleMaterials, 0);

    // Draw ranges in (base-colour texture, sidedness) order, for both submissions: where
    // surfaces tie in depth the first drawn wins, so direct and indirect must draw in the same
    // order to give the same image. Range i is drawn with baseInstance i, so the per-draw
    // attribute (divisor 1) reads element i.
    const auto groupOf = [&](const DrawRange& d) {
        return std::pair(d.material < materialTexture_.size() ? materialTexture_[d.material] : -1, doubleSided(d));
    };
    std::stable_sort(draws_.begin(), draws_.end(), [&](const DrawRange& a, const DrawRange& b) { return groupOf(a) < groupOf(b); });
    std::vector<glm::uvec2> params;
    std::map<std::pair<int, bool>, std::vector<std::uint32_t>> byGroup;
    for (std::uint32_t i = 0; i < draws_.size(); ++i) {
        const DrawRange& d = draws_[i];
        const std::uint32_t material = d.material < materialTexture_.size() ? d.material : 0u;
        params.emplace_back(material, d.firstIndex / 3);
        byGroup[groupOf(d)].push_back(i);
    }
    if (params.empty()) params.emplace_back(0u, 0u);
    drawParams_ = gl::Buffer::fromSpan<glm::uvec2>("scene.draw-params", params, 0);
    glVertexArrayVertexBuffer(vao, 1, drawParams_.id(), 0, sizeof(glm::uvec2));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glEnableVertexArrayAttrib(vao, 3);
    glVertexArrayAttribIFormat(vao, 3, 2, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, 3, 1);

    std::vector<DrawElementsIndirectCommand> commands;
    for (const auto& [group, ranges] : byGroup) {
        groups_.push_back({group.first, group.second, static_cast<std::uint32_t>(commands.size()), static_cast<std::uint32_t>(ranges.size())});
        for (std::uint32_t i : ranges) commands.push_back({draws_[i].indexCount, 1, draws_[i].firstIndex, 0, i});
    }
    if (commands.empty()) commands.push_back({0, 0, 0, 0, 0});
    commands_ = gl::Buffer::fromSpan<DrawElementsIndirectCommand>("scene.draw-commands", commands, 0);
}

DrawSubmission parseDrawSubmission(const std::string& text) {
    if (text == "direct") return DrawSubmission::Direct;
    if (text == "indirect") return DrawSubmission::Indirect;
    throw std::invalid_argument("--draw '" + text + "': expected direct or indirect");
}

const char* drawSubmissionName(DrawSubmission submission) {
    return submission == DrawSubmission::Indirect ? "indirect" : "direct";
}

void SceneGpu::bindGroupTexture(int texture) const {
    glBindTextureUnit(ML_TEX_BASE_COLOR, texture >= 0 ? textures_[static_cast<std::size_t>(texture)].id() : white_.id());
}

std::size_t SceneGpu::drawCallsPerPass() const {
    return submission_ == DrawSubmission::Indirect ? groups_.size() : draws_.size();
}

void SceneGpu::setCullState(bool doubleSided) const {
    if (backfaceCulling_ && !doubleSided) glEnable(GL_CULL_FACE);  // GL's defaults: CCW front, cull back
    else glDisable(GL_CULL_FACE);
}

void SceneGpu::draw() const {
    glBindVertexArray(vao_.id());
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MATERIALS);
    if (submission_ == DrawSubmission::Indirect) {
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
        for (const TextureGroup& g : groups_) {
            bindGroupTexture(g.texture);
            setCullState(g.doubleSided);
            glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                        reinterpret_cast<const void*>(std::uintptr_t(g.firstCommand) * sizeof(DrawElementsIndirectCommand)),
                                        static_cast<GLsizei>(g.commandCount), 0);
        }
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    } else {
        for (std::uint32_t i = 0; i < draws_.size(); ++i) {
            const DrawRange& d = draws_[i];
            bindGroupTexture(d.material < materialTexture_.size() ? materialTexture_[d.material] : -1);
            setCullState(doubleSided(d));
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                                                reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)), 1, i);
        }
    }
    glDisable(GL_CULL_FACE);
}

void SceneGpu::drawUntextured() const {
    glBindVertexArray(vao_.id());
    if (submission_ == DrawSubmission::Indirect) {
        // No textures here: one call per run of groups with the same cull state.
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
        for (std::size_t first = 0; first < groups_.size();) {
            std::size_t end = first + 1;
            std::uint32_t commands = groups_[first].commandCount;
            while (end < groups_.size() && groups_[end].doubleSided == groups_[first].doubleSided) commands += groups_[end++].commandCount;
            setCullState(groups_[first].doubleSided);
            glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                        reinterpret_cast<const void*>(std::uintptr_t(groups_[first].firstCommand) * sizeof(DrawElementsIndirectCommand)),
                                        static_cast<GLsizei>(commands), 0);
            first = end;
        }
        glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    } else {
        for (std::uint32_t i = 0; i < draws_.size(); ++i) {
            const DrawRange& d = draws_[i];
            setCullState(doubleSided(d));
            glDrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                                                reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)), 1, i);
        }
    }
    glDisable(GL_CULL_FACE);
}

void SceneGpu::bindGeometryForCompute() const {
    vertices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTICES);
    indices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_INDICES);
    triangleMaterials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_TRIANGLE_MATERIALS);
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MATERIALS);
}

std::size_t SceneGpu::bytes() const {
    return vertices_.size() + indices_.size() + materials_.size() + triangleMaterials_.size();
}

}  // namespace ml
