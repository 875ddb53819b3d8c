// glTF animations and skins into the scene's animation model (scenes/scene_animation.h): the
// node hierarchy with its rest transforms, the clips (samplers and channels), the skins, and
// which mesh instances they move. Read only for a file that has animations, skins or morph
// targets. Internal to scenes/gltf_*.cpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scenes/gltf_accessors.h"
#include "scenes/gltf_nodes.h"
#include "scenes/scene_animation.h"

namespace ml::gltf {

// Whether the file has anything that moves vertices: animations, skins or morph targets.
bool hasAnimation(const tinygltf::Model& model);

// The morph targets of a mesh (the most any of its primitives has), checked against the mesh's
// weights.
std::size_t morphTargetCount(const std::string& path, const tinygltf::Model& model, std::size_t mesh);

// Reads the nodes, skins and clips of the file, checking every index, count and value:
// keyframe times must not decrease (equal times are kept: a jump), and every number must be
// finite; each fault is one line naming the animation, sampler, channel or skin.
class AnimationReader {
public:
    AnimationReader(const std::string& path, const tinygltf::Model& model, const AccessorReader& reader);

    // Whether the instance's vertices move: its node is skinned, its mesh has morph targets, or
    // a channel of some clip animates its node or an ancestor's translation, rotation or scale.
    bool deforms(const MeshInstance& instance) const;
    // Whether a channel moves the node (or an ancestor).
    bool moves(std::size_t node) const { return moved_[node]; }

    SceneAnimation& animation() { return animation_; }
    // Channels left out (KHR_animation_pointer and other paths, or no target node), one line.
    std::vector<std::string> warnings() const;

private:
    void readNodes();
    void readSkins();
    void readClip(std::size_t index);
    AnimationSampler readSampler(std::size_t animation, std::size_t sampler, AnimatedProperty property, std::size_t width);

    const std::string& path_;
    const tinygltf::Model& model_;
    const AccessorReader& reader_;
    SceneAnimation animation_;
    std::vector<bool> moved_;
    std::vector<std::size_t> morphTargets_;  // per mesh
    std::size_t skippedChannels_ = 0;
    std::string skippedPaths_;  // the first path skipped, for the warning
    std::size_t keyframeFloats_ = 0;  // all samplers together, bounded by kMaxKeyframeFloats
};

}  // namespace ml::gltf
