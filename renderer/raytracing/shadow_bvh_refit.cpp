#include "renderer/raytracing/shadow_bvh_refit.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "glsl/include/bindings.h"
#include "renderer/scene/scene_gpu.h"

namespace ml {

namespace {

// Every inner node's level (the root's 0), from the references the nodes hold.
std::vector<std::uint32_t> nodeLevels(const ShadowBvh& bvh) {
    std::vector<std::uint32_t> level(bvh.nodeCount(), 0);
    // Depth-first order puts every parent before its children (shadow_bvh.h).
    for (std::uint32_t n = 0; n < bvh.nodeCount(); ++n)
        for (std::uint32_t slot = 0; slot < bvh.width; ++slot) {
            const ShadowBvhChild child = shadowNodeChild(bvh.node(n), bvh.width, slot);
            if (child.present && !shadowReferenceIsLeaf(child.reference) && child.reference > n) level[child.reference] = level[n] + 1;
        }
    return level;
}

}  // namespace

ShadowBvhRefit::ShadowBvhRefit(const Scene& scene, const ShadowBvh& bvh, std::uint32_t firstTriangle)
    : program_(gl::Program::compute("refit_shadow_bvh.comp", shaders::Defines{{"ML_SHADOW_BVH_WIDTH", std::to_string(bvh.width)}})),
      triangles_(static_cast<std::uint32_t>(bvh.triangles.size())),
      nodes_(static_cast<std::uint32_t>(bvh.nodeCount())),
      firstTriangle_(firstTriangle) {
    // One invocation a triangle along x: past the device's workgroups along x, say so rather than
    // leave the rest at the loaded pose.
    if (gl::groupsFor(triangles_, ML_SHADOW_REFIT_WORKGROUP) > gl::maxWorkGroupsX())
        throw std::invalid_argument(scene.name + ": " + std::to_string(triangles_) +
                                    " animated casting triangles, more than the shadow refit's one dispatch holds on this GPU; "
                                    "--animation off draws and shadows the file at rest");
    std::vector<glm::uvec4> corners(bvh.triangles.size());
    for (std::size_t t = 0; t < bvh.triangles.size(); ++t) {
        const std::uint32_t s = glm::floatBitsToUint(bvh.triangles[t].v1.w);
        corners[t] = glm::uvec4(scene.indices[3 * s], scene.indices[3 * s + 1], scene.indices[3 * s + 2], 0u);
    }
    const std::vector<std::uint32_t> level = nodeLevels(bvh);
    const std::uint32_t deepest = level.empty() ? 0 : *std::max_element(level.begin(), level.end());
    std::vector<std::uint32_t> order;
    order.reserve(level.size());
    levelFirst_.push_back(0);
    for (std::uint32_t l = deepest + 1; l-- > 0;) {
        for (std::uint32_t n = 0; n < level.size(); ++n)
            if (level[n] == l) order.push_back(n);
        levelFirst_.push_back(static_cast<std::uint32_t>(order.size()));
    }
    corners_ = gl::Buffer::fromSpan<glm::uvec4>("shadows.refit.corners", corners, 0);
    order_ = gl::Buffer::fromSpan<std::uint32_t>("shadows.refit.order", order, 0);
}

void ShadowBvhRefit::run(const gl::Buffer& bvhBuffer, const SceneGpu& scene) const {
    if (triangles_ == 0) return;
    program_.use();
    program_.set("u_firstTriangle", firstTriangle_);
    program_.set("u_nodes", nodes_);
    bvhBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SHADOW_BVH);
    scene.bindGeometryStorage();
    corners_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SHADOW_REFIT_CORNERS);
    order_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SHADOW_REFIT_ORDER);
    program_.set("u_pass", 0u);
    program_.set("u_count", triangles_);
    glDispatchCompute(gl::groupsFor(triangles_, ML_SHADOW_REFIT_WORKGROUP), 1, 1);
    program_.set("u_pass", 1u);
    for (std::size_t l = 0; l + 1 < levelFirst_.size(); ++l) {
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        const std::uint32_t count = levelFirst_[l + 1] - levelFirst_[l];
        program_.set("u_first", levelFirst_[l]);
        program_.set("u_count", count);
        glDispatchCompute(gl::groupsFor(count, ML_SHADOW_REFIT_WORKGROUP), 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace ml
