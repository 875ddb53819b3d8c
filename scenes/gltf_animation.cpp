// glTF 2.0 animations (3.11) and skins (3.7.3).
#include "scenes/gltf_animation.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

const Format kTimeFormat{TINYGLTF_TYPE_SCALAR, "SCALAR FLOAT",
                         [](const tinygltf::Accessor& a, bool) { return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT; }};
const Format kVec3Format{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT",
                         [](const tinygltf::Accessor& a, bool) { return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT; }};
// Rotations and weights may be normalized integers (glTF 2.0, 3.11: "Animation samplers").
bool floatOrNormalized(const tinygltf::Accessor& a, bool) {
    return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
           (a.normalized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                      TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
}
const Format kRotationFormat{TINYGLTF_TYPE_VEC4, "VEC4 FLOAT, or normalized BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT",
                             floatOrNormalized};
const Format kWeightFormat{TINYGLTF_TYPE_SCALAR, "SCALAR FLOAT, or normalized BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT",
                           floatOrNormalized};
const Format kMatrixFormat{TINYGLTF_TYPE_MAT4, "MAT4 FLOAT",
                           [](const tinygltf::Accessor& a, bool) { return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT; }};

bool propertyOf(const std::string& path, AnimatedProperty& property) {
    if (path == "translation") property = AnimatedProperty::Translation;
    else if (path == "rotation") property = AnimatedProperty::Rotation;
    else if (path == "scale") property = AnimatedProperty::Scale;
    else if (path == "weights") property = AnimatedProperty::Weights;
    else return false;
    return true;
}

// An accessor index from the file, checked against the accessors.
int accessorIndex(const std::string& path, const tinygltf::Model& model, int index, const std::string& what) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        fail(path, what + " accessor index " + std::to_string(index) + " out of range (" + std::to_string(model.accessors.size()) +
                       " accessors)");
    return index;
}

void requireFinite(const std::string& path, const std::string& what, const std::vector<float>& values, std::size_t width) {
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            fail(path, what + ": non-finite value (NaN or infinity) at element " + std::to_string(i / width));
}

}  // namespace

bool hasAnimation(const tinygltf::Model& model) {
    if (!model.animations.empty() || !model.skins.empty()) return true;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& prim : mesh.primitives)
            if (!prim.targets.empty()) return true;
    return false;
}

std::size_t morphTargetCount(const std::string& path, const tinygltf::Model& model, std::size_t meshIndex) {
    const tinygltf::Mesh& mesh = model.meshes[meshIndex];
    // glTF asks every primitive for the same targets; one with fewer (a points primitive, say)
    // is taken to have zero deltas for the rest.
    std::size_t count = 0;
    for (const tinygltf::Primitive& prim : mesh.primitives) count = std::max(count, prim.targets.size());
    if (!mesh.weights.empty() && mesh.weights.size() != count)
        fail(path, named("meshes", meshIndex, mesh.name) + ": weights has " + std::to_string(mesh.weights.size()) +
                       " numbers for " + std::to_string(count) + " morph targets");
    return count;
}

AnimationReader::AnimationReader(const std::string& path, const tinygltf::Model& model, const AccessorReader& reader)
    : path_(path), model_(model), reader_(reader) {
    // Once per mesh, however many nodes place it.
    for (std::size_t m = 0; m < model.meshes.size(); ++m) morphTargets_.push_back(morphTargetCount(path, model, m));
    for (std::size_t targets : morphTargets_) animation_.morphTargetMeshes += targets > 0;
    readNodes();
    readSkins();
    for (std::size_t a = 0; a < model.animations.size(); ++a) readClip(a);
    moved_.assign(animation_.nodes.size(), false);
    for (const AnimationClip& clip : animation_.clips)
        for (const AnimationChannel& channel : clip.channels)
            if (channel.property != AnimatedProperty::Weights) moved_[channel.node] = true;
    for (std::size_t n : animation_.nodeOrder)
        if (const int parent = animation_.nodes[n].parent; parent >= 0 && moved_[static_cast<std::size_t>(parent)]) moved_[n] = true;
}

void AnimationReader::readNodes() {
    const std::size_t count = model_.nodes.size();
    animation_.nodes.resize(count);
    for (std::size_t n = 0; n < count; ++n) {
        const tinygltf::Node& node = model_.nodes[n];
        const std::string name = named("nodes", n, node.name);
        const NodeTransform t = nodeTransform(path_, node, n);
        AnimationNode& out = animation_.nodes[n];
        if (t.matrix) out.matrix = glm::mat4(*t.matrix);
        out.translation = glm::vec3(t.translation);
        out.rotation = glm::quat(t.rotation);
        out.scale = glm::vec3(t.scale);
        if (node.skin >= 0 && static_cast<std::size_t>(node.skin) >= model_.skins.size())
            fail(path_, name + ": skin index " + std::to_string(node.skin) + " out of range (" +
                            std::to_string(model_.skins.size()) + " skins)");
        // Morph weights at rest: the node's own, else its mesh's, else zero (glTF 3.7.2.2).
        if (node.mesh >= 0 && static_cast<std::size_t>(node.mesh) < model_.meshes.size()) {
            const std::size_t targets = morphTargets_[static_cast<std::size_t>(node.mesh)];
            const std::vector<double>& given = node.weights.empty() ? model_.meshes[static_cast<std::size_t>(node.mesh)].weights : node.weights;
            if (!node.weights.empty() && node.weights.size() != targets)
                fail(path_, name + ": weights has " + std::to_string(node.weights.size()) + " numbers for its mesh's " +
                                std::to_string(targets) + " morph targets");
            out.weights.assign(targets, 0.0f);
            for (std::size_t t = 0; t < given.size() && t < targets; ++t) {
                if (!std::isfinite(given[t])) fail(path_, name + ": morph weight " + std::to_string(t) + " is not finite");
                out.weights[t] = static_cast<float>(given[t]);
            }
        }
        for (int child : node.children) {
            if (child < 0 || static_cast<std::size_t>(child) >= count)
                fail(path_, name + ": node index " + std::to_string(child) + " out of range (" + std::to_string(count) + " nodes)");
            AnimationNode& c = animation_.nodes[static_cast<std::size_t>(child)];
            if (c.parent >= 0 || static_cast<std::size_t>(child) == n)
                fail(path_, named("nodes", static_cast<std::size_t>(child), model_.nodes[static_cast<std::size_t>(child)].name) +
                                " has more than one parent (or is its own child); glTF nodes must form trees");
            c.parent = static_cast<int>(n);
        }
    }
    // Parents before children: walk down from the roots. A node never reached is on a cycle.
    std::vector<std::vector<std::size_t>> children(count);
    for (std::size_t n = 0; n < count; ++n)
        if (animation_.nodes[n].parent >= 0) children[static_cast<std::size_t>(animation_.nodes[n].parent)].push_back(n);
    std::vector<std::size_t>& order = animation_.nodeOrder;
    for (std::size_t n = 0; n < count; ++n)
        if (animation_.nodes[n].parent < 0) order.push_back(n);
    for (std::size_t i = 0; i < order.size(); ++i)
        for (std::size_t c : children[order[i]]) order.push_back(c);
    if (order.size() != count) {
        std::vector<bool> reached(count, false);
        for (std::size_t n : order) reached[n] = true;
        std::size_t n = 0;
        while (reached[n]) ++n;
        fail(path_, "node cycle: " + named("nodes", n, model_.nodes[n].name) + " is its own ancestor");
    }
}

void AnimationReader::readSkins() {
    for (std::size_t s = 0; s < model_.skins.size(); ++s) {
        const tinygltf::Skin& skin = model_.skins[s];
        const std::string name = named("skins", s, skin.name);
        Skin out;
        out.name = skin.name;
        if (skin.joints.empty()) fail(path_, name + " has no joints");
        for (int joint : skin.joints) {
            if (joint < 0 || static_cast<std::size_t>(joint) >= model_.nodes.size())
                fail(path_, name + ": joint node index " + std::to_string(joint) + " out of range (" +
                                std::to_string(model_.nodes.size()) + " nodes)");
            out.joints.push_back(static_cast<std::size_t>(joint));
        }
        out.inverseBind.assign(out.joints.size(), glm::mat4(1.0f));
        if (skin.inverseBindMatrices >= 0) {
            const int accessor = accessorIndex(path_, model_, skin.inverseBindMatrices, name + ": inverseBindMatrices");
            const Use use{"inverseBindMatrices", -1, -1, -1, &name};
            if (reader_.count(accessor) != out.joints.size())
                fail(path_, describe(model_, accessor, use) + ": count " + std::to_string(reader_.count(accessor)) +
                                (reader_.count(accessor) < out.joints.size() ? " is short of" : " differs from") + " the skin's " +
                                std::to_string(out.joints.size()) + " joints");
            const std::vector<float> m = reader_.floats(accessor, use, kMatrixFormat, out.joints.size());
            requireFinite(path_, describe(model_, accessor, use), m, 16);
            for (std::size_t j = 0; j < out.joints.size(); ++j)
                for (int c = 0; c < 16; ++c) out.inverseBind[j][c / 4][c % 4] = m[16 * j + static_cast<std::size_t>(c)];
        }
        animation_.skins.push_back(std::move(out));
    }
}

AnimationSampler AnimationReader::readSampler(std::size_t a, std::size_t s, AnimatedProperty property, std::size_t width) {
    const tinygltf::Animation& animation = model_.animations[a];
    const tinygltf::AnimationSampler& sampler = animation.samplers[s];
    const std::string name = named("animations", a, animation.name) + " samplers[" + std::to_string(s) + "]";
    AnimationSampler out;
    out.width = width;
    if (sampler.interpolation == "LINEAR") out.interpolation = Interpolation::Linear;
    else if (sampler.interpolation == "STEP") out.interpolation = Interpolation::Step;
    else if (sampler.interpolation == "CUBICSPLINE") out.interpolation = Interpolation::CubicSpline;
    else fail(path_, name + ": interpolation '" + clip(sampler.interpolation, 40) + "' is not LINEAR, STEP or CUBICSPLINE");

    const std::size_t room = kMaxKeyframeFloats - keyframeFloats_;
    const int input = accessorIndex(path_, model_, sampler.input, name + ": input");
    const Use inputUse{"input", -1, -1, -1, &name};
    out.times = reader_.floats(input, inputUse, kTimeFormat, room);
    if (out.times.empty()) fail(path_, describe(model_, input, inputUse) + ": no keyframes");
    requireFinite(path_, describe(model_, input, inputUse), out.times, 1);
    // glTF asks for strictly increasing times; equal ones are kept (a jump at that time, as
    // viewers play them), times that go back are refused.
    for (std::size_t k = 1; k < out.times.size(); ++k)
        if (out.times[k] < out.times[k - 1])
            fail(path_, describe(model_, input, inputUse) + ": keyframe times decrease at key " + std::to_string(k) + " (" +
                            std::to_string(out.times[k]) + " after " + std::to_string(out.times[k - 1]) + ")");

    const bool cubic = out.interpolation == Interpolation::CubicSpline;
    const int output = accessorIndex(path_, model_, sampler.output, name + ": output");
    const Use outputUse{"output", -1, -1, -1, &name};
    const bool scalar = property == AnimatedProperty::Weights;
    // Elements per key: a vector per key (three for a cubic spline), or a scalar per morph target.
    const std::size_t expected = out.times.size() * (cubic ? 3 : 1) * (scalar ? width : 1);
    if (reader_.count(output) != expected)
        fail(path_, describe(model_, output, outputUse) + ": count " + std::to_string(reader_.count(output)) + " does not match " +
                        std::to_string(out.times.size()) + " keyframes" + (cubic ? " x 3 (CUBICSPLINE)" : "") +
                        (scalar ? " x " + std::to_string(width) + " morph targets" : ""));
    const Format& format = property == AnimatedProperty::Rotation ? kRotationFormat
                           : scalar                               ? kWeightFormat
                                                                  : kVec3Format;
    out.values = reader_.floats(output, outputUse, format, room);
    requireFinite(path_, describe(model_, output, outputUse), out.values, scalar ? 1 : width);
    keyframeFloats_ += out.times.size() + out.values.size();
    if (property == AnimatedProperty::Rotation) {
        // Values are unit quaternions (a cubic spline's tangents are not).
        for (std::size_t k = 0; k < out.times.size(); ++k) {
            float* q = &out.values[(cubic ? 3 * k + 1 : k) * 4];
            const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(length > 0.0f))
                fail(path_, describe(model_, output, outputUse) + ": rotation of keyframe " + std::to_string(k) + " is a zero quaternion");
            for (int c = 0; c < 4; ++c) q[c] /= length;
        }
    }
    return out;
}

void AnimationReader::readClip(std::size_t a) {
    const tinygltf::Animation& animation = model_.animations[a];
    const std::string name = named("animations", a, animation.name);
    AnimationClip out;
    out.name = animation.name;
    std::map<std::pair<int, AnimatedProperty>, std::size_t> read;  // (glTF sampler, property) -> clip sampler
    for (std::size_t c = 0; c < animation.channels.size(); ++c) {
        const tinygltf::AnimationChannel& channel = animation.channels[c];
        const std::string where = name + " channels[" + std::to_string(c) + "]";
        AnimatedProperty property;
        if (!propertyOf(channel.target_path, property) || channel.target_node < 0) {
            // KHR_animation_pointer's "pointer" (materials, cameras, lights) and the like.
            if (skippedChannels_++ == 0) skippedPaths_ = channel.target_node < 0 ? "no target node" : "target path '" + clip(channel.target_path, 40) + "'";
            continue;
        }
        if (static_cast<std::size_t>(channel.target_node) >= model_.nodes.size())
            fail(path_, where + ": target node index " + std::to_string(channel.target_node) + " out of range (" +
                            std::to_string(model_.nodes.size()) + " nodes)");
        if (channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= animation.samplers.size())
            fail(path_, where + ": sampler index " + std::to_string(channel.sampler) + " out of range (" +
                            std::to_string(animation.samplers.size()) + " samplers)");
        const std::size_t node = static_cast<std::size_t>(channel.target_node);
        const std::string nodeName = named("nodes", node, model_.nodes[node].name);
        if (animation_.nodes[node].matrix && property != AnimatedProperty::Weights)
            fail(path_, where + ": " + nodeName + " is placed by a matrix, which glTF does not allow an animation to target");
        std::size_t width = property == AnimatedProperty::Rotation ? 4 : 3;
        if (property == AnimatedProperty::Weights) {
            width = animation_.nodes[node].weights.size();
            if (width == 0) fail(path_, where + ": weights of " + nodeName + ", which has no mesh with morph targets");
        }
        auto [it, added] = read.try_emplace({channel.sampler, property}, out.samplers.size());
        if (added) out.samplers.push_back(readSampler(a, static_cast<std::size_t>(channel.sampler), property, width));
        if (out.samplers[it->second].width != width)
            fail(path_, where + ": samplers[" + std::to_string(channel.sampler) + "] also drives weights of another width");
        out.channels.push_back({it->second, node, property});
    }
    for (const AnimationSampler& s : out.samplers) out.duration = std::max(out.duration, s.times.back());
    animation_.clips.push_back(std::move(out));
}

bool AnimationReader::deforms(const MeshInstance& instance) const {
    const tinygltf::Node& node = model_.nodes[instance.node];
    return node.skin >= 0 || !animation_.nodes[instance.node].weights.empty() || moved_[instance.node];
}

std::vector<std::string> AnimationReader::warnings() const {
    if (skippedChannels_ == 0) return {};
    return {counted(skippedChannels_, "animation channel", "animation channels") + " skipped (" + skippedPaths_ +
            (skippedChannels_ > 1 ? " and others" : "") + "; only node translation, rotation, scale and morph weights are animated)"};
}

}  // namespace ml::gltf
