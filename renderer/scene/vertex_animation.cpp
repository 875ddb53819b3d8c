#include "renderer/scene/vertex_animation.h"

#include <algorithm>
#include <stdexcept>

#include "glsl/include/bindings.h"

namespace ml {
namespace {

// glsl/animate_vertices.comp's DeformVertex and DeformMesh (std430).
struct alignas(16) GpuDeformVertex {
    glm::vec4 position;
    glm::vec4 normal;
    glm::vec4 tangent;
    glm::uvec4 info;  // scene vertex, deformed mesh, index within the mesh
    glm::uvec4 joints[2];
    glm::vec4 weights[2];
};
static_assert(sizeof(GpuDeformVertex) == 128, "mirrors DeformVertex in glsl/animate_vertices.comp");

struct alignas(16) GpuDeformMesh {
    glm::uvec4 pose;   // matrix, first joint matrix (or ML_DEFORM_NO_SKIN), first morph weight, morph targets
    glm::uvec4 morph;  // first morph delta, vertex count
};
static_assert(sizeof(GpuDeformMesh) == 32, "mirrors DeformMesh in glsl/animate_vertices.comp");

// The pose buffer: every mesh's matrix, then every skin's joint matrices, then the morph
// weights, four to a vec4.
struct PoseLayout {
    std::vector<std::uint32_t> jointBase;  // per skin, in vec4s
    std::uint32_t weightBase = 0;          // in floats
    std::vector<std::uint32_t> meshWeights;  // per mesh, in floats from weightBase
    std::size_t vec4s = 0;
};

PoseLayout poseLayout(const SceneAnimation& a) {
    PoseLayout layout;
    std::size_t next = 4 * a.meshes.size();
    for (const Skin& skin : a.skins) {
        layout.jointBase.push_back(static_cast<std::uint32_t>(next));
        next += 4 * skin.joints.size();
    }
    layout.weightBase = static_cast<std::uint32_t>(4 * next);
    std::size_t weights = 0;
    for (const DeformedMesh& mesh : a.meshes) {
        layout.meshWeights.push_back(static_cast<std::uint32_t>(weights));
        weights += mesh.morphTargets;
    }
    layout.vec4s = next + (weights + 3) / 4;
    return layout;
}

}  // namespace

VertexAnimationPass::VertexAnimationPass(const Scene& scene, std::size_t clip, bool tangents)
    : animation_(scene.animation),
      clip_(&animation_->clips.at(clip)),
      program_(gl::Program::compute("animate_vertices.comp", shaders::Defines{{"ML_DEFORM_TANGENTS", tangents ? "1" : "0"}})) {
    const SceneAnimation& a = *animation_;
    const PoseLayout layout = poseLayout(a);
    std::vector<GpuDeformVertex> vertices;
    std::vector<GpuDeformMesh> meshes;
    for (std::size_t m = 0; m < a.meshes.size(); ++m) {
        const DeformedMesh& mesh = a.meshes[m];
        GpuDeformMesh g{};
        g.pose = glm::uvec4(4 * m, mesh.skin >= 0 ? layout.jointBase[static_cast<std::size_t>(mesh.skin)] : ML_DEFORM_NO_SKIN,
                            layout.weightBase + layout.meshWeights[m], mesh.morphTargets);
        g.morph = glm::uvec4(mesh.firstDelta, mesh.vertexCount, 0, 0);
        meshes.push_back(g);
        for (std::uint32_t k = 0; k < mesh.vertexCount; ++k) {
            const std::size_t rest = mesh.firstRest + k;
            GpuDeformVertex v{};
            v.position = glm::vec4(a.restPositions[rest], 1.0f);
            v.normal = glm::vec4(a.restNormals[rest], 0.0f);
            v.tangent = a.restTangents.empty() ? glm::vec4(1.0f, 0.0f, 0.0f, 1.0f) : a.restTangents[rest];
            v.info = glm::uvec4(mesh.firstVertex + k, m, k, 0);
            if (mesh.skin >= 0) {
                const SkinInfluences& influence = a.influences[rest];
                for (int set = 0; set < 2; ++set) {
                    v.joints[set] = influence.joints[set];
                    v.weights[set] = influence.weights[set];
                }
            }
            vertices.push_back(v);
        }
    }
    std::vector<glm::vec4> deltas;
    deltas.reserve(3 * a.morphDeltas.size() + 3);
    for (const MorphDelta& d : a.morphDeltas) {
        deltas.emplace_back(d.position, 0.0f);
        deltas.emplace_back(d.normal, 0.0f);
        deltas.emplace_back(d.tangent, 0.0f);
    }
    if (deltas.empty()) deltas.resize(3);  // GL buffers cannot be empty
    vertexCount_ = vertices.size();
    vertices_ = gl::Buffer::fromSpan<GpuDeformVertex>("animation.vertices", vertices, 0);
    meshes_ = gl::Buffer::fromSpan<GpuDeformMesh>("animation.meshes", meshes, 0);
    deltas_ = gl::Buffer::fromSpan<glm::vec4>("animation.morph-deltas", deltas, 0);
    poseData_.assign(std::max<std::size_t>(layout.vec4s, 1), glm::vec4(0.0f));
    poseBuffer_ = gl::Buffer("animation.pose", poseData_.size() * sizeof(glm::vec4));
}

glm::vec3 VertexAnimationPass::posedPosition(std::uint32_t vertex, const glm::vec3& loaded) const {
    // Deformed meshes lie in the scene's vertex order (the loader appends them as it goes).
    const std::vector<DeformedMesh>& meshes = animation_->meshes;
    const auto after = std::upper_bound(meshes.begin(), meshes.end(), vertex,
                                        [](std::uint32_t v, const DeformedMesh& m) { return v < m.firstVertex; });
    if (after == meshes.begin() || pose_.meshMatrices.empty()) return loaded;
    const DeformedMesh& mesh = *(after - 1);
    if (vertex >= mesh.firstVertex + mesh.vertexCount) return loaded;
    return deformVertex(*animation_, pose_, static_cast<std::size_t>(after - 1 - meshes.begin()), vertex - mesh.firstVertex).position;
}

std::size_t VertexAnimationPass::bytes() const { return vertices_.size() + meshes_.size() + deltas_.size() + poseBuffer_.size(); }

void VertexAnimationPass::run(const SceneGpu& scene, double seconds) {
    const SceneAnimation& a = *animation_;
    pose_ = poseAt(a, clip_, seconds);
    const PoseLayout layout = poseLayout(a);
    for (std::size_t m = 0; m < a.meshes.size(); ++m)
        for (int c = 0; c < 4; ++c) poseData_[4 * m + static_cast<std::size_t>(c)] = pose_.meshMatrices[m][c];
    for (std::size_t s = 0; s < a.skins.size(); ++s)
        for (std::size_t j = 0; j < pose_.jointMatrices[s].size(); ++j)
            for (int c = 0; c < 4; ++c) poseData_[layout.jointBase[s] + 4 * j + static_cast<std::size_t>(c)] = pose_.jointMatrices[s][j][c];
    float* weights = &poseData_[0].x;
    for (std::size_t m = 0; m < a.meshes.size(); ++m)
        for (std::size_t t = 0; t < pose_.morphWeights[m].size(); ++t) weights[layout.weightBase + layout.meshWeights[m] + t] = pose_.morphWeights[m][t];
    poseBuffer_.upload(poseData_.data(), poseData_.size() * sizeof(glm::vec4));

    program_.use();
    program_.set("u_vertexCount", static_cast<unsigned>(vertexCount_));
    vertices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_DEFORM_VERTICES);
    meshes_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_DEFORM_MESHES);
    deltas_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MORPH_DELTAS);
    poseBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ANIMATION_POSE);
    scene.bindVertexStreamsForWriting();
    glDispatchCompute(gl::groupsFor(vertexCount_, ML_DEFORM_WORKGROUP), 1, 1);
    // Raster passes fetch positions as vertex attributes; the rest read them as storage.
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace ml
