// The occluders of --shadows rays in GPU memory: the scene's BVH (built on the CPU by Embree,
// renderer/raytracing/shadow_bvh.h) as one storage buffer, a 16-byte header (a ray count), nodes,
// triangles, then what MASK triangles need to read their alpha (shadow_alpha.h), which every
// shading pass binds (FrameContext::bindLightsForShading) and glsl/include/shadow_rays.glsl
// traverses. Built once per scene: a static scene pays nothing per frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "renderer/gl/buffer.h"
#include "renderer/gl/gl_handle.h"
#include "renderer/raytracing/shadow_bvh_refit.h"
#include "scenes/scene.h"

namespace ml {

// What the structure holds and what it cost, for `--stats`, `info` and the benchmarks.
struct ShadowStructureStats {
    std::size_t triangles = 0;  // the triangles that cast shadows (BLEND surfaces do not)
    std::size_t maskTriangles = 0;  // of them, the alpha-tested ones (their alpha read at the hit)
    std::size_t width = 0;  // children per node (--shadow-bvh-width)
    std::size_t nodes = 0;
    std::size_t depth = 0;
    std::size_t bytes = 0;
    double buildSeconds = 0.0;  // Embree's build and the flattening, on the CPU
    std::size_t refitLevels = 0;  // an animated scene's refit: its dispatches of nodes (0: static)
};

class ShadowRays {
public:
    // Builds the BVH of `scene`, `width` children a node (shadow_bvh.h), and uploads it;
    // `followsPose` where the scene is animated: refit() then moves it to each frame's pose
    // (shadow_bvh_refit.h). A structure larger than this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE
    // throws std::invalid_argument in one line naming the scene.
    ShadowRays(const Scene& scene, std::uint32_t width, bool followsPose);

    // Nothing casts a shadow (no triangle, or only BLEND ones): the frame need not trace.
    bool empty() const { return stats_.nodes == 0; }
    std::uint32_t width() const { return static_cast<std::uint32_t>(stats_.width); }
    void bindForShading() const;
    // FrameUniforms::shadows: the first triangle's vec4 in the buffer, nodes, triangles, the first
    // MASK material record's vec4 (the MASK triangles' UVs lie between: shadow_alpha.h).
    glm::uvec4 uniforms() const;
    // A directional light's shadow ray: long enough to leave the occluders' bounds from any
    // point inside them (twice their diagonal).
    float directionalReach() const { return directionalReach_; }
    const ShadowStructureStats& stats() const { return stats_; }
    // After the vertex animation: the structure takes the posed vertices `scene` holds now.
    // Nothing where the scene does not move.
    void refit(const SceneGpu& scene) const;
    bool followsPose() const { return refit_ != nullptr; }

    // The rays that shaders compiled with ML_COUNT_SHADOW_RAYS traced since resetRayCount (a
    // 64-bit count in the buffer's header; FrameRenderer::countShadowRays).
    void resetRayCount() const;
    std::uint64_t rayCount() const;

private:
    static constexpr std::size_t kHeaderBytes = 16;  // shadow_rays.glsl: the ray count, then padding
    gl::Buffer buffer_;
    gl::Handle<gl::TextureDeleter> alphaLayers_;  // MASK images' alpha, a layer each (shadow_alpha.h)
    ShadowStructureStats stats_;
    std::uint32_t firstTriangle_ = 0;  // in vec4s
    std::uint32_t firstMaterial_ = 0;  // in vec4s
    float directionalReach_ = 0.0f;
    std::unique_ptr<ShadowBvhRefit> refit_;
};

}  // namespace ml
