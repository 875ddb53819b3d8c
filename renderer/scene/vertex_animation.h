// The vertex animation pre-pass (glsl/animate_vertices.comp): each frame the CPU samples the
// scene's clip at the frame's time into node, joint and morph-weight values (scenes/animation_pose.h)
// and uploads them in one small buffer; a compute pass poses every deformed vertex into
// SceneGpu's vertex and tangent buffers, which every method, the clustering and the visibility
// buffer's rebuilt attributes read. Only a scene with a clip to play builds one: a static scene
// has no such pass, buffer or per-frame work.
//
// Buffers, per deformed vertex 128 B (rest position, normal, tangent, indices, eight influences),
// per deformed mesh 32 B, per morph delta 48 B, and per frame 64 B per mesh and joint plus the
// morph weights.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/scene/scene_gpu.h"
#include "scenes/animation_pose.h"

namespace ml {

class VertexAnimationPass {
public:
    // `clip` indexes scene.animation->clips.
    VertexAnimationPass(const Scene& scene, std::size_t clip, bool tangents);

    // Poses the vertices at `seconds` into the clip (looping). The same time gives the same
    // vertices. Every frame dispatches, at a repeated time too, so `bench` times the pass.
    void run(const SceneGpu& scene, double seconds);
    const AnimationPose& pose() const { return pose_; }
    // Scene vertex `vertex` as last posed (the CPU mirror), or `loaded` where nothing moves it.
    glm::vec3 posedPosition(std::uint32_t vertex, const glm::vec3& loaded) const;
    std::size_t vertexCount() const { return vertexCount_; }
    std::size_t bytes() const;

private:
    std::shared_ptr<const SceneAnimation> animation_;
    const AnimationClip* clip_;
    gl::Program program_;
    gl::Buffer vertices_, meshes_, deltas_, poseBuffer_;
    std::vector<glm::vec4> poseData_;  // staging for poseBuffer_
    AnimationPose pose_;
    std::size_t vertexCount_ = 0;
};

}  // namespace ml
