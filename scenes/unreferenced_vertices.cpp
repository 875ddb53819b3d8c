#include "scenes/unreferenced_vertices.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "scenes/scene_animation.h"

namespace ml {
namespace {

constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

// Keeps the elements of a per-vertex stream whose vertex is kept; an empty stream stays empty.
template <class T>
void compactStream(std::vector<T>& stream, const std::vector<std::uint32_t>& renumbered) {
    if (stream.empty()) return;
    std::size_t next = 0;
    for (std::size_t i = 0; i < stream.size(); ++i)
        if (renumbered[i] != kUnused) stream[next++] = stream[i];
    stream.resize(next);
}

SceneAnimation compactAnimation(const SceneAnimation& old, const std::vector<std::uint32_t>& renumbered) {
    SceneAnimation a = old;
    a.meshes.clear();
    a.restPositions.clear();
    a.restNormals.clear();
    a.restTangents.clear();
    a.influences.clear();
    a.morphDeltas.clear();
    for (const DeformedMesh& mesh : old.meshes) {
        std::vector<std::uint32_t> kept;  // the mesh's own vertex numbers that stay
        for (std::uint32_t k = 0; k < mesh.vertexCount; ++k)
            if (renumbered[mesh.firstVertex + k] != kUnused) kept.push_back(k);
        if (kept.empty()) continue;
        DeformedMesh m = mesh;
        // The kept vertices of a contiguous range stay contiguous: renumbering keeps the order.
        m.firstVertex = renumbered[mesh.firstVertex + kept.front()];
        m.vertexCount = static_cast<std::uint32_t>(kept.size());
        m.firstRest = a.restPositions.size();
        for (std::uint32_t k : kept) {
            const std::size_t rest = mesh.firstRest + k;
            a.restPositions.push_back(old.restPositions[rest]);
            if (!old.restNormals.empty()) a.restNormals.push_back(old.restNormals[rest]);
            if (!old.restTangents.empty()) a.restTangents.push_back(old.restTangents[rest]);
            if (!old.influences.empty()) a.influences.push_back(old.influences[rest]);
        }
        m.firstDelta = a.morphDeltas.size();
        for (std::size_t t = 0; t < mesh.morphTargets; ++t)
            for (std::uint32_t k : kept) a.morphDeltas.push_back(old.morphDeltas[mesh.firstDelta + t * mesh.vertexCount + k]);
        a.meshes.push_back(std::move(m));
    }
    return a;
}

}  // namespace

void dropUnreferencedVertices(Scene& scene) {
    std::vector<std::uint32_t> renumbered(scene.vertices.size(), kUnused);
    for (std::uint32_t i : scene.indices) renumbered[i] = 0;
    std::uint32_t next = 0;
    for (std::uint32_t& n : renumbered)
        if (n != kUnused) n = next++;
    if (next == scene.vertices.size()) return;

    compactStream(scene.vertices, renumbered);
    compactStream(scene.tangents, renumbered);
    compactStream(scene.uv1, renumbered);
    compactStream(scene.colors, renumbered);
    for (std::uint32_t& i : scene.indices) i = renumbered[i];
    if (scene.animation) scene.animation = std::make_shared<const SceneAnimation>(compactAnimation(*scene.animation, renumbered));
}

}  // namespace ml
