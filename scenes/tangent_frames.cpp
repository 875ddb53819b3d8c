#include "scenes/tangent_frames.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace ml {
namespace {

// Any unit vector orthogonal to n (n a unit vector): cross with the axis least aligned with it.
glm::vec3 anyOrthogonal(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(n, axis));
}

// The bits of a vertex's position, normal and UV: vertices equal in all three are one vertex to
// MikkTSpace, whatever the file's duplicates, and so here.
using VertexKey = std::array<std::uint32_t, 8>;

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& key) const {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint32_t word : key) h = (h ^ word) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

VertexKey keyOf(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
    const float values[8] = {position.x, position.y, position.z, normal.x, normal.y, normal.z, uv.x, uv.y};
    VertexKey key;
    std::memcpy(key.data(), values, sizeof(values));
    for (std::uint32_t& word : key)
        if (word == 0x80000000u) word = 0u;  // -0 and +0 are the same value
    return key;
}

bool finiteNonZero(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length);
}

}  // namespace

void generateTangents(Scene& scene, const IndexRanges& indexRanges, int texCoordSet) {
    const std::size_t vertexCount = scene.vertices.size();
    if (scene.tangents.size() != vertexCount) scene.tangents.resize(vertexCount, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    const auto uvOf = [&](std::uint32_t v) {
        return texCoordSet == 1 && scene.uv1.size() == vertexCount ? scene.uv1[v] : scene.vertices[v].uv;
    };

    // Each vertex sums into the first vertex equal to it, so that a file's duplicate vertices (which a
    // re-export may merge) get the frame the merged vertex would: the frame is the surface's, not
    // the layout's.
    std::vector<std::uint32_t> sumOf(vertexCount);
    std::vector<bool> used(vertexCount, false);
    {
        std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> first;
        for (const auto& [begin, count] : indexRanges)
            for (std::size_t k = begin; k < begin + count; ++k) {
                const std::uint32_t v = scene.indices[k];
                if (used[v]) continue;
                used[v] = true;
                sumOf[v] = first.try_emplace(keyOf(scene.vertices[v].position, scene.vertices[v].normal, uvOf(v)), v).first->second;
            }
    }
    std::vector<glm::dvec3> tangentSums(vertexCount, glm::dvec3(0.0)), bitangentSums(vertexCount, glm::dvec3(0.0));
    for (const auto& [first, count] : indexRanges) {
        for (std::size_t t = first; t + 3 <= first + count; t += 3) {
            const std::uint32_t v[3] = {scene.indices[t], scene.indices[t + 1], scene.indices[t + 2]};
            const glm::dvec3 p0(scene.vertices[v[0]].position), p1(scene.vertices[v[1]].position),
                p2(scene.vertices[v[2]].position);
            const glm::dvec2 uv0(uvOf(v[0])), uv1(uvOf(v[1])), uv2(uvOf(v[2]));
            const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
            const glm::dvec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
            const double uvArea = d1.x * d2.y - d2.x * d1.y;
            if (uvArea == 0.0 || !std::isfinite(uvArea)) continue;  // degenerate UVs: no direction
            // dP/du and dP/dv of the triangle's affine map from UV to position.
            const glm::dvec3 dPdu = (e1 * d2.y - e2 * d1.y) / uvArea;
            const glm::dvec3 dPdv = (e2 * d1.x - e1 * d2.x) / uvArea;
            if (!finiteNonZero(dPdu) || !finiteNonZero(dPdv)) continue;
            const double area = 0.5 * glm::length(glm::cross(e1, e2));
            const glm::dvec3 tangent = glm::normalize(dPdu) * area, bitangent = glm::normalize(dPdv) * area;
            for (std::uint32_t i : v) {
                tangentSums[sumOf[i]] += tangent;
                bitangentSums[sumOf[i]] += bitangent;
            }
        }
    }

    for (std::size_t i = 0; i < vertexCount; ++i) {
        if (!used[i]) continue;
        const glm::dvec3 n(scene.vertices[i].normal), tangentSum = tangentSums[sumOf[i]], bitangentSum = bitangentSums[sumOf[i]];
        const glm::dvec3 t = tangentSum - n * glm::dot(n, tangentSum);
        if (!finiteNonZero(t) || glm::length(t) < 1e-12 * (1.0 + glm::length(tangentSum))) {
            scene.tangents[i] = glm::vec4(anyOrthogonal(glm::vec3(n)), 1.0f);
            continue;
        }
        const glm::dvec3 unit = glm::normalize(t);
        const double w = glm::dot(glm::cross(n, unit), bitangentSum) < 0.0 ? -1.0 : 1.0;
        scene.tangents[i] = glm::vec4(glm::vec3(unit), static_cast<float>(w));
    }
}

}  // namespace ml
