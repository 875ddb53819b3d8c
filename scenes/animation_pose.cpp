#include "scenes/animation_pose.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/animation_sampling.h"

namespace ml {
namespace {

// A node's local transform while a clip plays: its rest TRS with the channels' values over it.
struct NodeState {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
    std::vector<float> weights;
};

glm::dmat4 localMatrix(const AnimationNode& node, const NodeState& state) {
    if (node.matrix) return glm::dmat4(*node.matrix);
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(state.translation));
    m *= glm::mat4_cast(glm::dquat(state.rotation));
    return glm::scale(m, glm::dvec3(state.scale));
}

glm::vec3 safeNormalize(const glm::vec3& v) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return glm::vec3(0.0f, 1.0f, 0.0f);
    return v / length;
}

}  // namespace

AnimationPose poseAt(const SceneAnimation& animation, const AnimationClip* clip, double seconds) {
    std::vector<NodeState> states;
    states.reserve(animation.nodes.size());
    for (const AnimationNode& n : animation.nodes) states.push_back({n.translation, n.rotation, n.scale, n.weights});
    if (clip != nullptr) {
        const float t = clipTime(*clip, seconds);
        std::vector<float> value;
        for (const AnimationChannel& channel : clip->channels) {
            const AnimationSampler& sampler = clip->samplers[channel.sampler];
            value.assign(sampler.width, 0.0f);
            sampleAnimation(sampler, channel.property, t, value);
            NodeState& s = states[channel.node];
            switch (channel.property) {
            case AnimatedProperty::Translation: s.translation = glm::vec3(value[0], value[1], value[2]); break;
            case AnimatedProperty::Rotation: s.rotation = glm::quat(value[3], value[0], value[1], value[2]); break;
            case AnimatedProperty::Scale: s.scale = glm::vec3(value[0], value[1], value[2]); break;
            case AnimatedProperty::Weights: s.weights = value; break;
            }
        }
    }

    std::vector<glm::dmat4> world(animation.nodes.size(), glm::dmat4(1.0));
    for (std::size_t n : animation.nodeOrder) {
        const AnimationNode& node = animation.nodes[n];
        const glm::dmat4 local = localMatrix(node, states[n]);
        world[n] = node.parent >= 0 ? world[static_cast<std::size_t>(node.parent)] * local : local;
    }

    AnimationPose pose;
    pose.nodeWorld.assign(world.begin(), world.end());
    for (const DeformedMesh& mesh : animation.meshes) {
        pose.meshMatrices.push_back(glm::mat4(world[mesh.node] * glm::dmat4(mesh.instance)));
        const std::vector<float>& animated = states[mesh.node].weights;
        pose.morphWeights.push_back(animated.size() == mesh.morphTargets ? animated : mesh.restWeights);
    }
    for (const Skin& skin : animation.skins) {
        std::vector<glm::mat4> joints;
        joints.reserve(skin.joints.size());
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            joints.push_back(glm::mat4(world[skin.joints[j]] * glm::dmat4(skin.inverseBind[j])));
        pose.jointMatrices.push_back(std::move(joints));
    }
    return pose;
}

DeformedVertex deformVertex(const SceneAnimation& animation, const AnimationPose& pose, std::size_t m, std::size_t k) {
    const DeformedMesh& mesh = animation.meshes[m];
    const std::size_t rest = mesh.firstRest + k;
    glm::vec3 position = animation.restPositions[rest];
    glm::vec3 normal = animation.restNormals[rest];
    glm::vec4 tangent = animation.restTangents.empty() ? glm::vec4(1.0f, 0.0f, 0.0f, 1.0f) : animation.restTangents[rest];
    const std::vector<float>& weights = pose.morphWeights[m];
    for (std::size_t t = 0; t < mesh.morphTargets; ++t) {
        const float w = weights[t];
        if (w == 0.0f) continue;
        const MorphDelta& d = animation.morphDeltas[mesh.firstDelta + t * mesh.vertexCount + k];
        position += w * d.position;
        normal += w * d.normal;
        tangent += glm::vec4(w * d.tangent, 0.0f);
    }

    glm::mat4 matrix = pose.meshMatrices[m];
    if (mesh.skin >= 0) {
        const SkinInfluences& influence = animation.influences[rest];
        const std::vector<glm::mat4>& joints = pose.jointMatrices[static_cast<std::size_t>(mesh.skin)];
        glm::mat4 skinned(0.0f);
        bool any = false;
        for (int set = 0; set < 2; ++set)
            for (int c = 0; c < 4; ++c) {
                const float w = influence.weights[set][c];
                if (w == 0.0f) continue;
                skinned += joints[influence.joints[set][c]] * w;
                any = true;
            }
        if (any) matrix = skinned;
    }

    const glm::mat3 linear(matrix);
    // Cofactors: the inverse transpose times the determinant, whose sign is put back.
    glm::mat3 normalMatrix(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]), glm::cross(linear[0], linear[1]));
    const float det = glm::dot(linear[0], glm::cross(linear[1], linear[2]));
    if (det < 0.0f) normalMatrix = -normalMatrix;
    DeformedVertex out;
    out.position = glm::vec3(matrix * glm::vec4(position, 1.0f));
    out.normal = safeNormalize(normalMatrix * normal);
    const glm::vec3 direction = linear * glm::vec3(tangent);
    const float length = glm::length(direction);
    out.tangent = glm::vec4(length > 0.0f && std::isfinite(length) ? direction / length : glm::vec3(1.0f, 0.0f, 0.0f),
                            (tangent.w < 0.0f ? -1.0f : 1.0f) * (det < 0.0f ? -1.0f : 1.0f));
    return out;
}

void applyPose(Scene& scene, const AnimationPose& pose) {
    if (!scene.animation) return;
    const SceneAnimation& animation = *scene.animation;
    const bool tangents = !scene.tangents.empty() && !animation.restTangents.empty();
    for (std::size_t m = 0; m < animation.meshes.size(); ++m) {
        const DeformedMesh& mesh = animation.meshes[m];
        for (std::size_t k = 0; k < mesh.vertexCount; ++k) {
            const DeformedVertex v = deformVertex(animation, pose, m, k);
            Vertex& target = scene.vertices[mesh.firstVertex + k];
            target.position = v.position;
            target.normal = v.normal;
            if (tangents) scene.tangents[mesh.firstVertex + k] = v.tangent;
        }
    }
}

const AnimationClip* sceneClip(const Scene& scene, std::optional<std::size_t> clip) {
    if (!scene.animation || !clip || *clip >= scene.animation->clips.size()) return nullptr;
    return &scene.animation->clips[*clip];
}

Bounds posedBounds(const Scene& scene, std::optional<std::size_t> clip, double seconds) {
    if (!scene.animation) return scene.bounds;
    const SceneAnimation& animation = *scene.animation;
    const AnimationPose pose = poseAt(animation, sceneClip(scene, clip), seconds);
    // Vertices no animation moves keep their loaded place.
    std::vector<bool> deformed(scene.vertices.size(), false);
    for (const DeformedMesh& mesh : animation.meshes)
        std::fill_n(deformed.begin() + mesh.firstVertex, mesh.vertexCount, true);
    Bounds bounds;
    for (std::size_t i = 0; i < scene.vertices.size(); ++i)
        if (!deformed[i]) bounds.extend(scene.vertices[i].position);
    for (std::size_t m = 0; m < animation.meshes.size(); ++m)
        for (std::size_t k = 0; k < animation.meshes[m].vertexCount; ++k) bounds.extend(deformVertex(animation, pose, m, k).position);
    return bounds;
}

Bounds sweptBounds(const Scene& scene, std::optional<std::size_t> clip, double startSeconds, double frameSeconds,
                   std::size_t maxPoses) {
    const AnimationClip* c = sceneClip(scene, clip);
    if (c == nullptr) return scene.bounds;
    const std::size_t frames = static_cast<std::size_t>(std::min(std::ceil(c->duration / frameSeconds), 1e9)) + 1;
    // About 4 million vertex poses at most (half a second on one core): a big animated scene
    // is swept at fewer, evenly spread times.
    const std::size_t budget = std::max<std::size_t>(2, 4'000'000 / std::max<std::size_t>(1, scene.animation->restPositions.size()));
    const std::size_t poses = std::clamp<std::size_t>(frames, 1, std::max<std::size_t>(std::min(maxPoses, budget), 1));
    // Spread over the loop when it has more frames than poses allowed.
    const double step = c->duration > 0.0f ? std::max(frameSeconds, static_cast<double>(c->duration) / static_cast<double>(poses)) : 0.0;
    Bounds bounds;
    for (std::size_t i = 0; i < poses; ++i) {
        const Bounds b = posedBounds(scene, clip, startSeconds + static_cast<double>(i) * step);
        bounds.extend(b.min);
        bounds.extend(b.max);
    }
    return bounds;
}

}  // namespace ml
