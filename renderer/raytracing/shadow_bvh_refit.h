// The shadow BVH of an animated scene follows its pose (glsl/refit_shadow_bvh.comp). The tree
// built by Embree on the loaded pose keeps its shape; each frame, after the vertex animation has
// posed SceneGpu's vertices, the GPU copies the posed corners into the BVH's triangles and
// recomputes every box from them, one level of nodes a dispatch, deepest first. A refit rather
// than a rebuild: it needs no read-back of the posed vertices and no CPU build in the frame, and
// a pose that moves triangles a little (a walking figure) loosens the boxes a little; the record
// compares it with a rebuild (docs/lights-and-shading.md). Static scenes have none.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/raytracing/shadow_bvh.h"
#include "scenes/scene.h"

namespace ml {

class SceneGpu;

class ShadowBvhRefit {
public:
    // `bvh` as built from `scene` (its triangles name their scene triangles), `firstTriangle` the
    // vec4 where its triangles start in the GPU buffer (ShadowRays::uniforms().x). More triangles
    // than one dispatch along x covers throws std::invalid_argument in one line naming the scene.
    ShadowBvhRefit(const Scene& scene, const ShadowBvh& bvh, std::uint32_t firstTriangle);

    // Refits `bvhBuffer` (shadow_rays.h's buffer) to the vertices `scene` holds now.
    void run(const gl::Buffer& bvhBuffer, const SceneGpu& scene) const;

    std::size_t levels() const { return levelFirst_.size() - 1; }
    std::size_t bytes() const { return corners_.size() + order_.size(); }

private:
    gl::Program program_;
    gl::Buffer corners_, order_;
    std::vector<std::uint32_t> levelFirst_;  // level L's nodes are order[levelFirst_[L], levelFirst_[L + 1]), deepest level first
    std::uint32_t triangles_ = 0, nodes_ = 0, firstTriangle_ = 0;
};

}  // namespace ml
