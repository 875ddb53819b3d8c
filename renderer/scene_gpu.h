// A scene's geometry, materials and textures on the GPU, uploaded once.
#pragma once

#include <string>
#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "scenes/scene.h"

namespace ml {

// How raster passes submit the scene (--draw): one glDrawElements call per draw range, or
// multi-draw indirect, GL's counterpart of seed 001's render bundles: the draw ranges live in a
// GPU command buffer and one glMultiDrawElementsIndirect call per base-colour texture draws
// them all, so the CPU cost per pass follows the number of textures, not of meshes. (GL 4.5 core
// has no bindless textures, so a texture change still needs its own call.)
enum class DrawSubmission { Direct, Indirect };
DrawSubmission parseDrawSubmission(const std::string& text);  // throws std::invalid_argument
const char* drawSubmissionName(DrawSubmission submission);

class SceneGpu {
public:
    explicit SceneGpu(const Scene& scene);

    // Every raster pass draws through scene.vert, whose per-draw attribute (location 3, one
    // value per draw range through the instance divisor and baseInstance) carries the range's
    // material and first triangle; so direct and indirect submission run the same shaders.
    void setSubmission(DrawSubmission submission) { submission_ = submission; }
    DrawSubmission submission() const { return submission_; }
    // On (--backface-culling, the default): every raster pass culls the back faces of ranges
    // whose material is single-sided (Material::doubleSided). Every pass culls alike, so the
    // methods still see the same surfaces.
    void setBackfaceCulling(bool on) { backfaceCulling_ = on; }
    bool backfaceCulling() const { return backfaceCulling_; }
    // Draws every draw range with the current program, binding each range's base-colour texture.
    void draw() const;
    // Draws every range without binding textures: depth-only passes, and the visibility
    // buffer's raster pass (which writes v_firstTriangle + gl_PrimitiveID, the triangle's
    // index in the scene).
    void drawUntextured() const;
    // Draw calls one textured raster pass issues with the current submission.
    std::size_t drawCallsPerPass() const;
    std::size_t drawRangeCount() const { return draws_.size(); }

    // For compute passes that rebuild surfaces from triangle ids: vertices, indices, the
    // material of every triangle, and the materials, at their ML_SSBO_* points.
    void bindGeometryForCompute() const;
    // Base-colour textures: materials name them by index (GpuMaterial::params.w, -1 for none).
    std::size_t textureCount() const { return textures_.size(); }
    void bindTexture(std::size_t index, GLuint unit) const { glBindTextureUnit(unit, textures_.at(index).id()); }

    std::size_t triangleCount() const { return indexCount_ / 3; }
    std::size_t bytes() const;

private:
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer materials_;
    gl::Buffer triangleMaterials_;  // 4 B per triangle
    gl::Handle<gl::VertexArrayDeleter> vao_;
    std::vector<gl::Texture2D> textures_;
    gl::Texture2D white_;
    // Indirect submission: one command per draw range, grouped by base-colour texture and
    // sidedness (a multi-draw call has one cull state).
    struct TextureGroup {
        int texture = -1;  // -1: untextured (the white texture)
        bool doubleSided = false;
        std::uint32_t firstCommand = 0;
        std::uint32_t commandCount = 0;
    };
    void bindGroupTexture(int texture) const;
    bool doubleSided(const DrawRange& d) const { return d.material < materialDoubleSided_.size() && materialDoubleSided_[d.material]; }
    void setCullState(bool doubleSided) const;

    std::vector<DrawRange> draws_;
    std::vector<int> materialTexture_;
    std::vector<std::uint8_t> materialDoubleSided_;
    std::vector<TextureGroup> groups_;
    gl::Buffer drawParams_;  // per draw range: material, first triangle (8 B)
    gl::Buffer commands_;    // DrawElementsIndirectCommand per draw range, in group order (20 B)
    std::size_t indexCount_ = 0;
    DrawSubmission submission_ = DrawSubmission::Direct;
    bool backfaceCulling_ = true;
};

}  // namespace ml
