// What a glTF file's animation needs beyond the flattened scene: the node hierarchy at rest, the
// animation clips, the skins, and the rest data of every vertex that a node transform, a skin or
// a morph target moves. Only files with animations, skins or morph targets have one
// (Scene::animation); a static file keeps its flattened geometry and pays nothing.
//
// The deformed vertices stay in Scene::vertices (and Scene::tangents) where the loader put them,
// posed at rest; scenes/animation_pose.h poses them at a time, on the CPU, and
// renderer/scene/vertex_animation.h does the same on the GPU into the buffers every method reads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace ml {

// A node of the file: its parent and its rest transform.
struct AnimationNode {
    int parent = -1;  // index into SceneAnimation::nodes; -1 for a root
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit
    glm::vec3 scale{1.0f};
    // A node given by `matrix` (glTF forbids animating it): its local transform, used as is.
    std::optional<glm::mat4> matrix;
    std::vector<float> weights;  // morph weights at rest: the node's, else its mesh's (empty: none)
};

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimatedProperty { Translation, Rotation, Scale, Weights };

// Keyframes of one property: `times` non-decreasing; per key `width` floats (3 translation and
// scale, 4 rotation as x, y, z, w, the node's morph target count for weights), and for a cubic
// spline three such groups per key: in-tangent, value, out-tangent (glTF's order).
struct AnimationSampler {
    std::vector<float> times;
    std::vector<float> values;
    std::size_t width = 0;
    Interpolation interpolation = Interpolation::Linear;
};

struct AnimationChannel {
    std::size_t sampler = 0;  // into AnimationClip::samplers
    std::size_t node = 0;     // into SceneAnimation::nodes
    AnimatedProperty property = AnimatedProperty::Translation;
};

// One glTF animation. It plays from 0 to `duration` (its last keyframe time) and loops.
struct AnimationClip {
    std::string name;
    float duration = 0.0f;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
};

struct Skin {
    std::string name;
    std::vector<std::size_t> joints;        // nodes
    std::vector<glm::mat4> inverseBind;     // one per joint (identity where the file gives none)
};

// A skinned vertex's influences: up to eight joints (JOINTS_0/WEIGHTS_0, then _1), as indices
// into its skin's joints, weights summing to 1 (or all 0: the vertex follows its node instead).
struct SkinInfluences {
    glm::uvec4 joints[2]{glm::uvec4(0u), glm::uvec4(0u)};
    glm::vec4 weights[2]{glm::vec4(0.0f), glm::vec4(0.0f)};
};

// A mesh instance whose vertices move: Scene::vertices [firstVertex, firstVertex + vertexCount).
struct DeformedMesh {
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    std::size_t firstRest = 0;  // its first element in SceneAnimation's per-vertex arrays
    std::size_t node = 0;       // the node that places it
    // EXT_mesh_gpu_instancing: the instance's TRS inside the node (identity otherwise).
    glm::mat4 instance{1.0f};
    int skin = -1;  // into SceneAnimation::skins; a skinned mesh ignores its node's transform (glTF)
    // Morph targets: deltas of target t for vertex k at SceneAnimation::morphDeltas
    // [firstDelta + t * vertexCount + k]; weights at rest from the node (or the mesh).
    std::size_t morphTargets = 0;
    std::size_t firstDelta = 0;
    std::vector<float> restWeights;
};

struct MorphDelta {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 tangent{0.0f};
};

struct SceneAnimation {
    std::vector<AnimationNode> nodes;
    std::vector<std::size_t> nodeOrder;  // every node, each after its parent
    std::vector<AnimationClip> clips;
    std::vector<Skin> skins;
    std::vector<DeformedMesh> meshes;
    // Per deformed vertex (DeformedMesh::firstRest + k), in the mesh's own space: rest position,
    // normal and tangent (w the bitangent sign; only where Scene::tangents exists), influences.
    std::vector<glm::vec3> restPositions;
    std::vector<glm::vec3> restNormals;
    std::vector<glm::vec4> restTangents;
    std::vector<SkinInfluences> influences;  // empty where no mesh is skinned
    std::vector<MorphDelta> morphDeltas;
    std::size_t morphTargetMeshes = 0;  // glTF meshes with morph targets (`manylights info`)
};

}  // namespace ml
