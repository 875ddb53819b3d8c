#include "scenes/gltf_geometry.h"

#include <cmath>
#include <tuple>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

glm::vec3 safeNormalize(const glm::vec3& v) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return glm::vec3(0.0f, 1.0f, 0.0f);
    return v / length;
}

}  // namespace

MeshPlan planMesh(const std::string& path, const tinygltf::Model& model, std::size_t meshIndex, Skipped& skipped) {
    const tinygltf::Mesh& mesh = model.meshes[meshIndex];
    MeshPlan plan;
    std::map<std::tuple<int, int, int>, std::size_t> groupOf;
    bool morphed = false;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        // Built only for a message: a mesh may have a million primitives.
        const auto where = [&] { return named("meshes", meshIndex, mesh.name) + " primitive " + std::to_string(p); };
        morphed = morphed || !prim.targets.empty();
        if (prim.mode != TINYGLTF_MODE_TRIANGLES) {
            ++skipped.primitiveModes[prim.mode];
            continue;
        }
        const auto attribute = [&](const char* name) {
            const auto it = prim.attributes.find(name);
            if (it == prim.attributes.end()) return -1;
            if (it->second < 0 || static_cast<std::size_t>(it->second) >= model.accessors.size())
                fail(path, where() + ": " + name + " accessor index " + std::to_string(it->second) + " out of range (" +
                               std::to_string(model.accessors.size()) + " accessors)");
            return it->second;
        };
        const int position = attribute("POSITION");
        if (position < 0) {
            ++skipped.withoutPosition;
            continue;
        }
        const int normal = attribute("NORMAL");
        const int texcoord = attribute("TEXCOORD_0");
        if (prim.attributes.count("COLOR_0") != 0) ++skipped.vertexColours;
        if (prim.indices >= 0 && static_cast<std::size_t>(prim.indices) >= model.accessors.size())
            fail(path, where() + ": indices accessor index " + std::to_string(prim.indices) + " out of range (" +
                           std::to_string(model.accessors.size()) + " accessors)");
        if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model.materials.size())
            fail(path, where() + ": material index " + std::to_string(prim.material) + " out of range (" +
                           std::to_string(model.materials.size()) + " materials)");

        const auto key = std::make_tuple(position, normal, texcoord);
        auto [it, added] = groupOf.try_emplace(key, plan.groups.size());
        if (added) plan.groups.push_back({position, normal, texcoord, static_cast<int>(p)});
        plan.primitives.push_back({static_cast<int>(p), it->second, prim.indices, prim.material});
    }
    if (morphed) ++skipped.morphedMeshes;
    return plan;
}

void SceneBuilder::addInstance(const MeshInstance& instance, const MeshPlan& plan) {
    // Normals transform by the inverse transpose of the linear part. Its columns are the cross
    // products of the matrix's columns over the determinant; dropping the division keeps the
    // directions and still works for singular transforms (a zero scale), keeping only the sign.
    const glm::dmat3 linear(instance.world);
    const double det = glm::determinant(linear);
    glm::dmat3 normalMatrix(glm::cross(linear[1], linear[2]), glm::cross(linear[2], linear[0]),
                            glm::cross(linear[0], linear[1]));
    // A mirroring transform flips triangle winding; glTF says to flip it back so that front faces
    // stay front faces (counter-clockwise).
    const bool mirrored = det < 0.0;
    if (mirrored) normalMatrix = -normalMatrix;

    std::vector<Block> blocks;
    blocks.reserve(plan.groups.size());
    for (const VertexGroup& group : plan.groups) blocks.push_back(appendVertices(instance, group, normalMatrix));

    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> generated(plan.groups.size());
    for (const PrimitivePlan& prim : plan.primitives) {
        const Block& block = blocks[prim.group];
        const std::size_t first = scene_.indices.size();
        appendTriangles(instance, prim, block, mirrored);
        const std::size_t count = scene_.indices.size() - first;
        if (count == 0) {
            ++skipped_.emptyPrimitives;
            continue;
        }
        runs_.push_back({static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count), materials_.materialFor(prim.material)});
        if (block.generateNormals) generated[prim.group].emplace_back(first, count);
    }
    for (std::size_t g = 0; g < blocks.size(); ++g)
        if (blocks[g].generateNormals) generateNormals(blocks[g], generated[g]);
}

SceneBuilder::Block SceneBuilder::appendVertices(const MeshInstance& instance, const VertexGroup& group,
                                                 const glm::dmat3& normalMatrix) {
    const Use positionUse{"POSITION", static_cast<int>(instance.mesh), group.firstPrimitive};
    const std::size_t room = kMaxVertices - scene_.vertices.size();
    const std::vector<float> positions = reader_.floats(group.position, positionUse, kPositionFormat, room);
    const std::size_t count = positions.size() / 3;
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!std::isfinite(positions[i]))
            fail(path_, describe(model_, group.position, positionUse) + ": non-finite position (NaN or infinity) at element " +
                            std::to_string(i / 3));

    const auto sameCount = [&](int accessor, const Use& use) {
        if (reader_.count(accessor) != count)
            fail(path_, describe(model_, accessor, use) + ": count " + std::to_string(reader_.count(accessor)) +
                            " differs from the POSITION count " + std::to_string(count));
    };
    Block block;
    block.base = static_cast<std::uint32_t>(scene_.vertices.size());
    block.count = static_cast<std::uint32_t>(count);

    std::vector<float> normals;
    if (group.normal >= 0) {
        const Use use{"NORMAL", static_cast<int>(instance.mesh), group.firstPrimitive};
        sameCount(group.normal, use);
        normals = reader_.floats(group.normal, use, kNormalFormat, count);
        // Broken normals are a shading fault, not a geometry one: generate them instead.
        if (!std::all_of(normals.begin(), normals.end(), [](float f) { return std::isfinite(f); })) {
            ++skipped_.regeneratedNormals;
            normals.clear();
        }
    }
    block.generateNormals = normals.empty();

    std::vector<float> uvs;
    if (group.texcoord >= 0) {
        const Use use{"TEXCOORD_0", static_cast<int>(instance.mesh), group.firstPrimitive};
        sameCount(group.texcoord, use);
        uvs = reader_.floats(group.texcoord, use, kTexcoordFormat, count);
        bool repaired = false;
        for (float& f : uvs) {
            if (!std::isfinite(f)) {
                f = 0.0f;
                repaired = true;
            }
        }
        if (repaired) ++skipped_.repairedTexcoords;
    }

    const glm::dmat4& m = instance.world;
    scene_.vertices.reserve(scene_.vertices.size() + count);
    for (std::size_t i = 0; i < count; ++i) {
        Vertex v;
        const glm::dvec4 p = m * glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0);
        v.position = glm::vec3(p);
        if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z))
            fail(path_, named("nodes", instance.node, model_.nodes[instance.node].name) +
                            ": the node transform makes a position of " +
                            named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + " non-finite");
        if (!normals.empty())
            v.normal = safeNormalize(glm::vec3(normalMatrix * glm::dvec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2])));
        if (!uvs.empty()) v.uv = glm::vec2(uvs[2 * i], uvs[2 * i + 1]);
        scene_.vertices.push_back(v);
    }
    return block;
}

void SceneBuilder::appendTriangles(const MeshInstance& instance, const PrimitivePlan& prim, const Block& block,
                                   bool mirrored) {
    const Use use{"indices", static_cast<int>(instance.mesh), prim.primitive};
    const auto where = [&] {
        return named("meshes", instance.mesh, model_.meshes[instance.mesh].name) + " primitive " +
               std::to_string(prim.primitive);
    };
    const std::size_t room = kMaxIndices - scene_.indices.size();
    std::vector<std::uint32_t> local;
    if (prim.indices >= 0) {
        local = reader_.indices(prim.indices, use, room);
        for (std::size_t i = 0; i < local.size(); ++i)
            if (local[i] >= block.count)
                fail(path_, describe(model_, prim.indices, use) + ": index " + std::to_string(local[i]) + " at element " +
                                std::to_string(i) + " is out of range (vertex count " + std::to_string(block.count) + ")");
    } else {
        if (block.count > room) fail(path_, where() + ": too many vertices to draw (index limit)");
        local.resize(block.count);
        for (std::uint32_t i = 0; i < block.count; ++i) local[i] = i;
    }
    if (local.size() % 3 != 0) {
        const std::string what = prim.indices >= 0 ? describe(model_, prim.indices, use) : where();
        fail(path_, what + ": " + std::to_string(local.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
                        " do not make whole triangles (not a multiple of 3)");
    }
    for (std::size_t t = 0; t < local.size(); t += 3) {
        scene_.indices.push_back(block.base + local[t]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 2 : 1)]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 1 : 2)]);
    }
}

// Per-vertex normals from the triangles that use the vertices, each face weighted by its area
// (the cross product of two edges is twice the area). Positions are already in world space and
// winding already corrected, so the result needs no transform.
void SceneBuilder::generateNormals(const Block& block, const std::vector<std::pair<std::size_t, std::size_t>>& ranges) {
    std::vector<glm::dvec3> sums(block.count, glm::dvec3(0.0));
    for (const auto& [first, count] : ranges) {
        for (std::size_t t = first; t < first + count; t += 3) {
            const std::uint32_t a = scene_.indices[t], b = scene_.indices[t + 1], c = scene_.indices[t + 2];
            const glm::dvec3 pa(scene_.vertices[a].position), pb(scene_.vertices[b].position), pc(scene_.vertices[c].position);
            const glm::dvec3 face = glm::cross(pb - pa, pc - pa);
            sums[a - block.base] += face;
            sums[b - block.base] += face;
            sums[c - block.base] += face;
        }
    }
    for (std::uint32_t i = 0; i < block.count; ++i) scene_.vertices[block.base + i].normal = safeNormalize(glm::vec3(sums[i]));
}

void SceneBuilder::finish() {
    std::vector<std::size_t> offsets(scene_.materials.size() + 1, 0);
    for (const DrawRange& run : runs_) offsets[run.material + 1] += run.indexCount;
    for (std::size_t m = 1; m < offsets.size(); ++m) offsets[m] += offsets[m - 1];

    std::vector<std::uint32_t> grouped(scene_.indices.size());
    std::vector<std::size_t> cursor(offsets.begin(), offsets.end() - 1);
    for (const DrawRange& run : runs_) {
        std::copy_n(scene_.indices.begin() + run.firstIndex, run.indexCount, grouped.begin() + cursor[run.material]);
        cursor[run.material] += run.indexCount;
    }
    scene_.indices.swap(grouped);
    scene_.draws.clear();
    for (std::size_t m = 0; m + 1 < offsets.size(); ++m)
        if (offsets[m + 1] > offsets[m])
            scene_.draws.push_back({static_cast<std::uint32_t>(offsets[m]),
                                    static_cast<std::uint32_t>(offsets[m + 1] - offsets[m]), static_cast<std::uint32_t>(m)});
}

}  // namespace ml::gltf
