// A scene's animation at one time: the clip sampled into node transforms, joint matrices and
// morph weights (the pose), and the CPU mirror of glsl/animate_vertices.comp that deforms the
// vertices with it, for the bounds, the transparent ranges' order and the tests. The same time
// always gives the same pose, so a frame is reproducible.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "scenes/scene.h"
#include "scenes/scene_animation.h"

namespace ml {

struct AnimationPose {
    std::vector<glm::mat4> nodeWorld;                // per node
    std::vector<glm::mat4> meshMatrices;             // per deformed mesh: node world x instance
    std::vector<std::vector<glm::mat4>> jointMatrices;  // per skin: world(joint) x inverse bind
    std::vector<std::vector<float>> morphWeights;    // per deformed mesh, one per target
};

// The pose at `seconds` into `clip` (looping; nullptr: the rest pose).
AnimationPose poseAt(const SceneAnimation& animation, const AnimationClip* clip, double seconds);

struct DeformedVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec4 tangent;  // w the bitangent's sign, flipped where the pose mirrors
};

// Vertex k of deformed mesh m, in world space: morph targets added in the mesh's space, then the
// skin (the weighted joint matrices) or the node's matrix; the normal by the inverse transpose
// (as cofactors, which keep the direction of a singular matrix) and renormalised, the tangent by
// the matrix. Float arithmetic in the shader's order.
DeformedVertex deformVertex(const SceneAnimation& animation, const AnimationPose& pose, std::size_t mesh, std::size_t k);

// Writes every deformed vertex of `scene` (positions, normals, and tangents where the scene has
// them) as posed.
void applyPose(Scene& scene, const AnimationPose& pose);

// The scene's clip by index, or nullptr (no animation, or an index past the clips).
const AnimationClip* sceneClip(const Scene& scene, std::optional<std::size_t> clip);

// The bounds of the scene's vertices with the deformed ones posed at `seconds`.
Bounds posedBounds(const Scene& scene, std::optional<std::size_t> clip, double seconds);

// The bounds over the frames `render --frames` shows from `startSeconds`, one every
// `frameSeconds` (the light animation's step) over one loop of the clip (at most `maxPoses`
// poses, spread over the loop), so clip planes and the light volume fitted to them hold the
// figure wherever it moves; a scene with many moving vertices at fewer poses (about 4 million
// vertex poses in all). The scene's own bounds without a clip.
Bounds sweptBounds(const Scene& scene, std::optional<std::size_t> clip, double startSeconds, double frameSeconds,
                   std::size_t maxPoses = 600);

}  // namespace ml
