// glTF 2.0 skinned mesh attributes (3.7.3.3) and morph targets (3.7.2.2).
#include "scenes/gltf_deformation.h"

#include <cmath>

#include "scenes/animation_pose.h"
#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

const Format kJointsFormat{TINYGLTF_TYPE_VEC4, "VEC4 UNSIGNED_BYTE or UNSIGNED_SHORT", [](const tinygltf::Accessor& a, bool) {
                               return !a.normalized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT});
                           }};
const Format kWeightsFormat{TINYGLTF_TYPE_VEC4, "VEC4 FLOAT, or normalized UNSIGNED_BYTE or UNSIGNED_SHORT",
                            [](const tinygltf::Accessor& a, bool) {
                                return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                       (a.normalized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}));
                            }};
// Deltas are floats, or with KHR_mesh_quantization (signed) bytes and shorts.
const Format kDeltaFormat{TINYGLTF_TYPE_VEC3, "VEC3 FLOAT (or BYTE or SHORT with KHR_mesh_quantization)",
                          [](const tinygltf::Accessor& a, bool quantized) {
                              return a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                     (quantized && isOneOf(a.componentType, {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT}));
                          }};

}  // namespace

void DeformationBuilder::add(const MeshInstance& instance, const MeshPlan& plan, const std::vector<std::uint32_t>& groupBases,
                             std::uint32_t firstVertex, std::uint32_t vertexCount) {
    const tinygltf::Node& node = model_.nodes[instance.node];
    DeformedMesh mesh;
    mesh.firstVertex = firstVertex;
    mesh.vertexCount = vertexCount;
    mesh.firstRest = animation_.restPositions.size();
    mesh.node = instance.node;
    mesh.instance = glm::mat4(instance.instance);
    mesh.skin = node.skin;
    mesh.restWeights = animation_.nodes[instance.node].weights;
    mesh.morphTargets = mesh.restWeights.size();
    // Rest positions, normals and tangents are taken at finish; the slots exist from here.
    animation_.restPositions.resize(mesh.firstRest + vertexCount);
    if (mesh.skin >= 0 && animation_.influences.size() < mesh.firstRest) animation_.influences.resize(mesh.firstRest);
    if (mesh.skin >= 0) animation_.influences.resize(mesh.firstRest + vertexCount);
    if (mesh.morphTargets > 0) {
        if (mesh.morphTargets > (kMaxMorphDeltas - animation_.morphDeltas.size()) / std::max<std::uint32_t>(vertexCount, 1))
            fail(path_, named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + ": " +
                            std::to_string(mesh.morphTargets) + " morph targets of " + std::to_string(vertexCount) +
                            " vertices are over the limit (" + std::to_string(kMaxMorphDeltas) + " vertex deltas in all)");
        mesh.firstDelta = animation_.morphDeltas.size();
        animation_.morphDeltas.resize(mesh.firstDelta + mesh.morphTargets * vertexCount);
    }
    for (std::size_t g = 0; g < plan.groups.size(); ++g) {
        const std::size_t local = groupBases[g] - firstVertex;
        const std::size_t end = g + 1 < plan.groups.size() ? groupBases[g + 1] - firstVertex : vertexCount;
        if (mesh.skin >= 0)
            readInfluences(instance, plan.groups[g], mesh.firstRest + local, end - local, animation_.skins[static_cast<std::size_t>(mesh.skin)]);
        if (mesh.morphTargets > 0) readMorphDeltas(instance, plan.groups[g], mesh, local, end - local);
    }
    animation_.meshes.push_back(std::move(mesh));
}

void DeformationBuilder::readInfluences(const MeshInstance& instance, const VertexGroup& group, std::size_t firstRest,
                                        std::size_t count, const Skin& skin) {
    const tinygltf::Primitive& prim = model_.meshes[instance.mesh].primitives[static_cast<std::size_t>(group.firstPrimitive)];
    for (int set = 0; set < 2; ++set) {
        const std::string suffix = "_" + std::to_string(set);
        const auto joints = prim.attributes.find("JOINTS" + suffix), weights = prim.attributes.find("WEIGHTS" + suffix);
        if (joints == prim.attributes.end() && weights == prim.attributes.end()) continue;
        const std::string jointsName = "JOINTS" + suffix, weightsName = "WEIGHTS" + suffix;
        const Use jointsUse{jointsName.c_str(), static_cast<int>(instance.mesh), group.firstPrimitive};
        const Use weightsUse{weightsName.c_str(), static_cast<int>(instance.mesh), group.firstPrimitive};
        const auto where = [&] {
            return named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + " primitive " + std::to_string(group.firstPrimitive);
        };
        if (joints == prim.attributes.end() || weights == prim.attributes.end())
            fail(path_, where() + ": " + (joints == prim.attributes.end() ? weightsName + " without " + jointsName
                                                                           : jointsName + " without " + weightsName));
        for (const auto& [accessor, use] : {std::pair{joints->second, &jointsUse}, std::pair{weights->second, &weightsUse}}) {
            if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size())
                fail(path_, where() + ": " + use->attribute + " accessor index " + std::to_string(accessor) + " out of range (" +
                                std::to_string(model_.accessors.size()) + " accessors)");
            if (reader_.count(accessor) != count)
                fail(path_, describe(model_, accessor, *use) + ": count " + std::to_string(reader_.count(accessor)) +
                                " differs from the POSITION count " + std::to_string(count));
        }
        const std::vector<float> j = reader_.floats(joints->second, jointsUse, kJointsFormat, count);
        const std::vector<float> w = reader_.floats(weights->second, weightsUse, kWeightsFormat, count);
        for (std::size_t i = 0; i < 4 * count; ++i) {
            if (!std::isfinite(w[i]) || w[i] < 0.0f)
                fail(path_, describe(model_, weights->second, weightsUse) + ": weight " + std::to_string(w[i]) + " at element " +
                                std::to_string(i / 4) + " is negative or not finite");
            // A joint with no weight is never read (exporters leave any index there).
            if (w[i] != 0.0f && j[i] >= static_cast<float>(skin.joints.size()))
                fail(path_, describe(model_, joints->second, jointsUse) + ": joint " + std::to_string(static_cast<std::uint32_t>(j[i])) +
                                " at element " + std::to_string(i / 4) + " is past the skin's " + std::to_string(skin.joints.size()) +
                                " joints");
            SkinInfluences& influence = animation_.influences[firstRest + i / 4];
            influence.joints[set][static_cast<int>(i % 4)] = w[i] != 0.0f ? static_cast<std::uint32_t>(j[i]) : 0u;
            influence.weights[set][static_cast<int>(i % 4)] = w[i];
        }
    }
    // Weights that do not sum to 1 (normalized bytes rarely do) are scaled to; all zero leaves
    // the vertex to its node.
    for (std::size_t i = 0; i < count; ++i) {
        SkinInfluences& influence = animation_.influences[firstRest + i];
        const float sum = glm::dot(influence.weights[0], glm::vec4(1.0f)) + glm::dot(influence.weights[1], glm::vec4(1.0f));
        if (sum > 0.0f)
            for (glm::vec4& w : influence.weights) w /= sum;
    }
}

void DeformationBuilder::readMorphDeltas(const MeshInstance& instance, const VertexGroup& group, const DeformedMesh& mesh,
                                         std::size_t local, std::size_t count) {
    const tinygltf::Mesh& gltfMesh = model_.meshes[instance.mesh];
    const tinygltf::Primitive& prim = gltfMesh.primitives[static_cast<std::size_t>(group.firstPrimitive)];
    for (std::size_t t = 0; t < prim.targets.size(); ++t) {
        const std::string name = "targets[" + std::to_string(t) + "] ";
        for (const auto& [attribute, accessor] : prim.targets[t]) {
            const bool position = attribute == "POSITION", normal = attribute == "NORMAL", tangent = attribute == "TANGENT";
            if (!position && !normal && !tangent) {
                if (skippedMorphAttributes_++ == 0) skippedMorphAttribute_ = clip(attribute, 40);
                continue;
            }
            const std::string use = name + attribute;
            const Use deltaUse{use.c_str(), static_cast<int>(instance.mesh), group.firstPrimitive};
            if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size())
                fail(path_, named("meshes", instance.mesh, gltfMesh.name) + " primitive " + std::to_string(group.firstPrimitive) +
                                ": morph " + use + " accessor index " + std::to_string(accessor) + " out of range (" +
                                std::to_string(model_.accessors.size()) + " accessors)");
            if (reader_.count(accessor) != count)
                fail(path_, describe(model_, accessor, deltaUse) + ": count " + std::to_string(reader_.count(accessor)) +
                                " differs from the POSITION count " + std::to_string(count));
            const std::vector<float> d = reader_.floats(accessor, deltaUse, kDeltaFormat, count);
            for (std::size_t i = 0; i < d.size(); ++i)
                if (!std::isfinite(d[i]))
                    fail(path_, describe(model_, accessor, deltaUse) + ": non-finite value (NaN or infinity) at element " +
                                    std::to_string(i / 3));
            for (std::size_t i = 0; i < count; ++i) {
                MorphDelta& delta = animation_.morphDeltas[mesh.firstDelta + t * mesh.vertexCount + local + i];
                const glm::vec3 v(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
                (position ? delta.position : normal ? delta.normal : delta.tangent) = v;
            }
        }
    }
}

void DeformationBuilder::finish(Scene& scene, SceneAnimation&& animation) {
    animation.restNormals.resize(animation.restPositions.size());
    if (!scene.tangents.empty()) animation.restTangents.resize(animation.restPositions.size());
    if (!animation.influences.empty()) animation.influences.resize(animation.restPositions.size());
    for (const DeformedMesh& mesh : animation.meshes) {
        for (std::size_t k = 0; k < mesh.vertexCount; ++k) {
            const Vertex& v = scene.vertices[mesh.firstVertex + k];
            animation.restPositions[mesh.firstRest + k] = v.position;
            animation.restNormals[mesh.firstRest + k] = v.normal;
            if (!scene.tangents.empty()) animation.restTangents[mesh.firstRest + k] = scene.tangents[mesh.firstVertex + k];
        }
    }
    auto shared = std::make_shared<const SceneAnimation>(std::move(animation));
    scene.animation = shared;
    applyPose(scene, poseAt(*shared, nullptr, 0.0));
}

std::vector<std::string> DeformationBuilder::warnings() const {
    if (skippedMorphAttributes_ == 0) return {};
    return {"morph target " + skippedMorphAttribute_ + (skippedMorphAttributes_ > 1 ? " (and " + std::to_string(skippedMorphAttributes_ - 1) + " more attributes)" : "") +
            " skipped (only POSITION, NORMAL and TANGENT deltas are modelled)"};
}

}  // namespace ml::gltf
