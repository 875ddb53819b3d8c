// A scene's geometry, materials and textures on the GPU, uploaded once.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/scene/raster_program.h"
#include "renderer/scene/triangle_order.h"
#include "scenes/scene.h"

namespace ml {

// How raster passes submit the scene (--draw): one glDrawElements call per draw range, or
// multi-draw indirect, GL's counterpart of seed 001's render bundles: the draw ranges live in a
// GPU command buffer and one glMultiDrawElementsIndirect call per draw group (texture set,
// alpha test, sidedness) draws them all, so the CPU cost per pass follows the number of texture
// sets, not of meshes. (GL 4.5 core has no bindless textures, so a texture change still needs
// its own call.)
enum class DrawSubmission { Direct, Indirect };
DrawSubmission parseDrawSubmission(const std::string& text);  // throws std::invalid_argument
const char* drawSubmissionName(DrawSubmission submission);

class SceneGpu {
public:
    // `order`: each draw range's triangles as loaded or reordered at upload (renderer/scene/triangle_order.h).
    explicit SceneGpu(const Scene& scene, TriangleOrder order = TriangleOrder::Overdraw);

    // ML_FEATURE_* bits of what the drawn materials use (renderer/scene/material_features.h): every
    // program that reads a material or a G-buffer is built with them.
    std::uint32_t materialFeatures() const { return features_; }

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
    // Draws every draw range that is not transparent: opaque ranges first with the program's
    // opaque variant, then the alpha-tested ones with its masked variant. Textures are bound where
    // the program reads the material, and for masked ranges always (coverage needs the base
    // colour's alpha). `which` draws the opaque ranges or the alpha-tested ones alone, for a pass
    // that treats them differently (the visibility raster: image atomics behind an early depth
    // test for the opaque ones, which a discard would break).
    enum class Ranges { All, Opaque, AlphaTested };
    void draw(const RasterProgram& program, Ranges which = Ranges::All) const;
    bool hasAlphaTestedRanges() const { return !alphaTestedSpans_.empty(); }
    // Triangles of the ranges draw(Ranges::Opaque) draws: the index buffer's first ones, since
    // opaque ranges come first (the visibility buffer's compute raster reads them as one list).
    std::size_t opaqueTriangleCount() const { return opaqueTriangles_; }
    // The alpha-tested triangles, one span per texture set (the index buffer holds each set's
    // alpha-tested ranges together, after the opaque ones): what a compute pass that tests
    // coverage binds its textures for (GL 4.5 has no bindless textures).
    struct TriangleSpan {
        int textureSet = -1;
        std::uint32_t first = 0;  // triangle index
        std::uint32_t count = 0;
    };
    const std::vector<TriangleSpan>& alphaTestedSpans() const { return alphaTestedSpans_; }

    // Transparent (glTF BLEND) draw ranges, drawn after the opaque frame by drawTransparent and by
    // nothing else. Off (--transparency off), the scene draws as if it had none.
    void setTransparency(bool on) { transparency_ = on; }
    bool transparency() const { return transparency_; }
    bool hasTransparent() const { return transparency_ && !transparent_.empty(); }
    std::size_t transparentRangeCount() const { return transparent_.size(); }
    // The order transparent ranges are drawn in, as indices into them: back to front by the
    // distance from the eye to the centre of each range's bounding box, the farthest first; equal
    // distances keep scene order. Within a range, triangles blend in index order. Every method
    // (and the naive reference) draws this order, so they blend the same colours.
    std::vector<std::uint32_t> transparentOrder(const glm::vec3& eye) const;
    // The texture sets the transparent ranges bind (-1: untextured), each once, ascending: a
    // compute pass that shades them binds each set in turn (GL 4.5 has no bindless textures).
    std::vector<int> transparentTextureSets() const;
    // Draws the transparent ranges in transparentOrder(eye), one direct call each, with the
    // program's opaque variant and each range's textures and cull state. Blend and depth state
    // are the caller's.
    void drawTransparent(const RasterProgram& program, const glm::vec3& eye) const;
    // View depth range [near, far] (positive, clamped to the camera's) that the transparent
    // ranges' bounding boxes span: the clustered methods' fitted depth range must hold it, since
    // the opaque depth buffer does not see those surfaces. Empty without transparent ranges or
    // when they all lie outside the camera's range.
    std::optional<glm::vec2> transparentDepthRange(const glm::mat4& view, float cameraNear, float cameraFar) const;
    // The window rectangle (x, y, width, height) within a width x height target that holds every
    // transparent range's projected bounding box; the whole target where a box reaches behind the
    // eye. Empty without transparent ranges or where they all project outside it.
    std::optional<glm::ivec4> transparentScreenRect(const glm::mat4& viewProj, int width, int height) const;
    // An animated scene's transparent ranges move with their vertices: refits each range's box to
    // posed(vertex, its loaded position) over its vertices (kept for an animated scene only).
    void refitTransparentBounds(const std::function<glm::vec3(std::uint32_t, const glm::vec3&)>& posed);
    // Draw calls one pass issues with the current submission.
    std::size_t drawCallsPerPass() const;
    std::size_t drawRangeCount() const { return draws_.size(); }

    // For passes that rebuild surfaces from triangle ids (the visibility resolve, the glass, and
    // every raster pass's texture coordinates): vertices, indices, the material of every
    // triangle, the materials, and the optional vertex streams, at their ML_SSBO_* points.
    void bindGeometryStorage() const;
    // The vertex animation (renderer/scene/vertex_animation.h) writes posed vertices in place:
    // the vertices at ML_SSBO_VERTICES, the tangents (where the scene's shading reads them) at
    // ML_SSBO_VERTEX_TANGENTS.
    void bindVertexStreamsForWriting() const;
    bool hasTangentStream() const { return static_cast<bool>(tangents_); }
    // The vertex and tangent buffers as they are now (a GPU sync): the vertex animation's tests.
    std::vector<Vertex> downloadVertices() const { return vertices_.downloadAll<Vertex>(); }
    std::vector<glm::vec4> downloadTangents() const { return tangents_ ? tangents_.downloadAll<glm::vec4>() : std::vector<glm::vec4>{}; }
    // Texture sets: the distinct (texture, sampler) tuples over a material's slots. Materials name
    // theirs (GpuMaterial::info.z); -1 is "no texture". Binds a set's textures at ML_TEX_*.
    std::size_t textureSetCount() const { return textureSets_.size(); }
    void bindTextureSet(int set) const;
    // Unbinds the sampler objects bindTextureSet left on the material units, so later passes
    // sample those units with their textures' own parameters.
    void unbindSamplers() const;

    std::size_t triangleCount() const { return indexCount_ / 3; }
    std::size_t bytes() const;

private:
    // One texture unit's binding: image index into textures_ (-1: white) and sampler (-1: default).
    struct SlotBinding {
        int texture = -1;
        int sampler = -1;
        auto operator<=>(const SlotBinding&) const = default;
    };
    using TextureSet = std::array<SlotBinding, ML_TEXTURE_SLOTS>;

    // Draw ranges with the same program variant, textures and cull state.
    struct DrawGroup {
        bool alphaTested = false;
        int textureSet = -1;
        bool doubleSided = false;
        std::uint32_t firstRange = 0;  // into draws_ (and the indirect commands, in the same order)
        std::uint32_t rangeCount = 0;
        std::tuple<bool, int, bool> key() const { return {alphaTested, textureSet, doubleSided}; }
    };

    // A transparent draw range: where it is in draws_, how it is drawn, and its world bounds.
    struct TransparentRange {
        std::uint32_t range = 0;
        int textureSet = -1;
        bool doubleSided = false;
        Bounds bounds;
        // An animated scene's only: the range's vertices and their loaded positions.
        std::vector<std::uint32_t> vertices;
        std::vector<glm::vec3> loaded;
    };

    void setCullState(bool doubleSided) const;
    void bindDrawState() const;
    void drawGroups(std::size_t first, std::size_t end) const;

    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::Buffer tangents_, uv1_, colors_;  // optional streams: empty where the scene has none
    gl::Buffer materials_;
    gl::Buffer triangleMaterials_;  // 4 B per triangle
    gl::Handle<gl::VertexArrayDeleter> vao_;
    std::vector<gl::Texture2D> textures_;
    std::vector<gl::Handle<gl::SamplerDeleter>> samplers_;
    gl::Handle<gl::SamplerDeleter> defaultSampler_;
    gl::Texture2D white_;
    std::vector<TextureSet> textureSets_;
    std::uint32_t features_ = 0;

    std::vector<DrawRange> draws_;  // in group order, the transparent ranges last
    std::vector<DrawGroup> groups_;  // of the ranges that are not transparent
    std::vector<TransparentRange> transparent_;
    std::vector<TriangleSpan> alphaTestedSpans_;
    bool transparency_ = true;
    gl::Buffer drawParams_;  // per draw range: material, first triangle (8 B)
    gl::Buffer commands_;    // DrawElementsIndirectCommand per draw range, in group order (20 B)
    std::size_t indexCount_ = 0;
    std::size_t opaqueTriangles_ = 0;
    DrawSubmission submission_ = DrawSubmission::Direct;
    bool backfaceCulling_ = true;
};

}  // namespace ml
