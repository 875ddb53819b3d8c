// A scene's geometry, materials and textures on the GPU, uploaded once.
#pragma once

#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "scenes/scene.h"

namespace ml {

class SceneGpu {
public:
    explicit SceneGpu(const Scene& scene);

    // Draws every draw range with `program` (which reads u_materialIndex and the base-colour texture).
    void draw(const gl::Program& program) const;
    // Draws positions only, for depth-only passes (no material state changes).
    void drawDepthOnly() const;
    // Draws every range with `program`, setting u_firstTriangle to the range's first triangle,
    // so gl_PrimitiveID + u_firstTriangle is the triangle's index in the scene (visibility buffer).
    void drawTriangleIds(const gl::Program& program) const;

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
    std::vector<DrawRange> draws_;
    std::vector<int> materialTexture_;
    std::size_t indexCount_ = 0;
};

}  // namespace ml
