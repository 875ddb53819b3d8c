#include "scenes/gltf_geometry.h"

#include <array>
#include <cmath>
#include <tuple>

#include "scenes/gltf_common.h"
#include "scenes/gltf_variants.h"
#include "scenes/tangent_frames.h"

namespace ml::gltf {
namespace {

glm::vec3 safeNormalize(const glm::vec3& v) {
    const float length = glm::length(v);
    if (!(length > 0.0f) || !std::isfinite(length)) return glm::vec3(0.0f, 1.0f, 0.0f);
    return v / length;
}

}  // namespace

MeshPlan planMesh(const std::string& path, const tinygltf::Model& model, std::size_t meshIndex, std::size_t variantCount,
                  Skipped& skipped) {
    const tinygltf::Mesh& mesh = model.meshes[meshIndex];
    MeshPlan plan;
    std::map<std::tuple<int, int, int, int, int, int>, std::size_t> groupOf;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        // Built only for a message: a mesh may have a million primitives.
        const auto where = [&] { return named("meshes", meshIndex, mesh.name) + " primitive " + std::to_string(p); };
        if (!isOneOf(prim.mode, {TINYGLTF_MODE_TRIANGLES, TINYGLTF_MODE_TRIANGLE_STRIP, TINYGLTF_MODE_TRIANGLE_FAN})) {
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
        if (prim.indices >= 0 && static_cast<std::size_t>(prim.indices) >= model.accessors.size())
            fail(path, where() + ": indices accessor index " + std::to_string(prim.indices) + " out of range (" +
                           std::to_string(model.accessors.size()) + " accessors)");
        if (prim.material >= 0 && static_cast<std::size_t>(prim.material) >= model.materials.size())
            fail(path, where() + ": material index " + std::to_string(prim.material) + " out of range (" +
                           std::to_string(model.materials.size()) + " materials)");

        PrimitivePlan planned{static_cast<int>(p), 0, prim.indices, prim.material, prim.mode, false, false, 0, {}};
        if (prim.extensions.count("KHR_materials_variants") != 0)
            planned.variantMaterials = primitiveVariantMaterials(path, model, prim, variantCount, where());
        const int texcoord1 = attribute("TEXCOORD_1");
        // The streams follow every material the primitive may be drawn with, its variants' too,
        // so that choosing a variant needs no reload. Tangents come from the first normal map's UV set.
        bool normalSetChosen = false;
        const auto needsOf = [&](int materialIndex) {
            if (materialIndex < 0) return;
            const std::size_t m = static_cast<std::size_t>(materialIndex);
            const tinygltf::Material& material = model.materials[m];
            checkTexCoords(path, model, m);
            const bool readsTexcoord1 = usesTexCoord1(material);
            planned.readsTexcoord1 = planned.readsTexcoord1 || readsTexcoord1;
            if (needsTangents(material) && !normalSetChosen) {
                planned.normalMapped = true;
                planned.normalTexCoord = tangentTexCoord(material);
                normalSetChosen = true;
            }
            if (readsTexcoord1 && texcoord1 < 0) {
                for (const MaterialTexture& texture : texturesOf(material))
                    if (texture.texCoord == 1.0)
                        fail(path, named("materials", m, material.name) + ": " + texture.slot + " reads TEXCOORD_1, which " +
                                       where() + " does not have");
            }
        };
        needsOf(prim.material);
        for (int variantMaterial : planned.variantMaterials) needsOf(variantMaterial);
        const int normal = attribute("NORMAL"), texcoord = attribute("TEXCOORD_0"), color = attribute("COLOR_0"),
                  tangent = attribute("TANGENT");
        const auto key = std::make_tuple(position, normal, texcoord, texcoord1, color, tangent);
        auto [it, added] = groupOf.try_emplace(key, plan.groups.size());
        if (added) plan.groups.push_back({position, normal, texcoord, texcoord1, color, tangent, static_cast<int>(p)});
        VertexGroup& group = plan.groups[it->second];
        group.readsTexcoord1 = group.readsTexcoord1 || planned.readsTexcoord1;
        group.needsTangents = group.needsTangents || planned.normalMapped;
        planned.group = it->second;
        plan.primitives.push_back(planned);
    }
    return plan;
}

std::vector<std::uint32_t> SceneBuilder::addInstance(const MeshInstance& instance, const MeshPlan& plan) {
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

    // KHR_materials_volume's thickness is in the mesh's units: the node's scale, rotation aside
    // (the mean of the columns' lengths, as the Sample Viewer's modelScale, averaged).
    const double meshScale = (glm::length(linear[0]) + glm::length(linear[1]) + glm::length(linear[2])) / 3.0;

    std::vector<Block> blocks;
    blocks.reserve(plan.groups.size());
    for (const VertexGroup& group : plan.groups) blocks.push_back(appendVertices(instance, group, normalMatrix, mirrored));

    std::vector<Ranges> normalRanges(plan.groups.size());
    std::vector<std::array<Ranges, 2>> tangentRanges(plan.groups.size());  // by UV set
    for (const PrimitivePlan& prim : plan.primitives) {
        const Block& block = blocks[prim.group];
        const std::size_t first = scene_.indices.size();
        appendTriangles(instance, prim, block, mirrored);
        const std::size_t count = scene_.indices.size() - first;
        if (count == 0) {
            ++skipped_.emptyPrimitives;
            continue;
        }
        runs_.push_back({static_cast<std::uint32_t>(first), static_cast<std::uint32_t>(count), materialSetOf(prim, meshScale)});
        colorsDrawn_ = colorsDrawn_ || plan.groups[prim.group].color >= 0;
        uv1Drawn_ = uv1Drawn_ || prim.readsTexcoord1;
        tangentsDrawn_ = tangentsDrawn_ || prim.normalMapped;
        if (block.generateNormals) normalRanges[prim.group].emplace_back(first, count);
        if (block.generateTangents && prim.normalMapped) tangentRanges[prim.group][prim.normalTexCoord].emplace_back(first, count);
    }
    for (std::size_t g = 0; g < blocks.size(); ++g) {
        // Tangents are made orthogonal to the normals, so those come first.
        if (blocks[g].generateNormals) generateNormals(blocks[g], normalRanges[g]);
        for (int set = 0; set < 2; ++set)
            if (!tangentRanges[g][set].empty()) generateTangents(scene_, tangentRanges[g][set], set);
    }
    std::vector<std::uint32_t> bases;
    for (const Block& block : blocks) bases.push_back(block.base);
    return bases;
}

// Reads a vertex attribute whose NaN or infinite components are a shading fault, not a geometry
// one: they become `replacement`, counted once per primitive group in `repairs`.
std::vector<float> SceneBuilder::readRepaired(const VertexGroup& group, const MeshInstance& instance, int accessor,
                                              const char* attribute, const Format& format, std::size_t count,
                                              float replacement, std::size_t& repairs) const {
    const Use use{attribute, static_cast<int>(instance.mesh), group.firstPrimitive};
    if (reader_.count(accessor) != count)
        fail(path_, describe(model_, accessor, use) + ": count " + std::to_string(reader_.count(accessor)) +
                        " differs from the POSITION count " + std::to_string(count));
    std::vector<float> values = reader_.floats(accessor, use, format, count);
    bool repaired = false;
    for (float& f : values) {
        if (!std::isfinite(f)) {
            f = replacement;
            repaired = true;
        }
    }
    if (repaired) ++repairs;
    return values;
}

template <class T>
void SceneBuilder::appendToStream(std::vector<T>& stream, const std::vector<T>& values, std::size_t base,
                                  std::size_t count, const T& defaultValue) {
    if (values.empty() && stream.empty()) return;
    if (stream.empty()) stream.assign(base, defaultValue);
    if (values.empty()) stream.insert(stream.end(), count, defaultValue);
    else stream.insert(stream.end(), values.begin(), values.end());
}

SceneBuilder::Block SceneBuilder::appendVertices(const MeshInstance& instance, const VertexGroup& group,
                                                 const glm::dmat3& normalMatrix, bool mirrored) {
    const Use positionUse{"POSITION", static_cast<int>(instance.mesh), group.firstPrimitive};
    const std::size_t room = kMaxVertices - scene_.vertices.size();
    const std::vector<float> positions = reader_.floats(group.position, positionUse, kPositionFormat, room);
    const std::size_t count = positions.size() / 3;
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!std::isfinite(positions[i]))
            fail(path_, describe(model_, group.position, positionUse) + ": non-finite position (NaN or infinity) at element " +
                            std::to_string(i / 3));

    Block block;
    block.base = static_cast<std::uint32_t>(scene_.vertices.size());
    block.count = static_cast<std::uint32_t>(count);

    // Broken normals (and tangents) are a shading fault, not a geometry one: generate them instead.
    std::size_t brokenNormals = 0, brokenTangents = 0;
    std::vector<float> normals;
    if (group.normal >= 0) normals = readRepaired(group, instance, group.normal, "NORMAL", kNormalFormat, count, NAN, brokenNormals);
    if (brokenNormals > 0) {
        ++skipped_.regeneratedNormals;
        normals.clear();
    }
    block.generateNormals = normals.empty();

    std::vector<float> uvs, uvs1, colors, fileTangents;
    if (group.texcoord >= 0)
        uvs = readRepaired(group, instance, group.texcoord, "TEXCOORD_0", kTexcoordFormat, count, 0.0f, skipped_.repairedTexcoords);
    if (group.texcoord1 >= 0 && group.readsTexcoord1)
        uvs1 = readRepaired(group, instance, group.texcoord1, "TEXCOORD_1", kTexcoordFormat, count, 0.0f, skipped_.repairedTexcoords);
    if (group.color >= 0)
        colors = readRepaired(group, instance, group.color, "COLOR_0", kColorFormat, count, 1.0f, skipped_.repairedColours);
    if (group.tangent >= 0 && group.needsTangents)
        fileTangents = readRepaired(group, instance, group.tangent, "TANGENT", kTangentFormat, count, NAN, brokenTangents);
    if (brokenTangents > 0) {
        ++skipped_.regeneratedTangents;
        fileTangents.clear();
    }
    block.generateTangents = group.needsTangents && fileTangents.empty();

    const glm::dmat4& m = instance.world;
    const glm::dmat3 linear(m);
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

    std::vector<glm::vec2> uv1Stream;
    for (std::size_t i = 0; i < uvs1.size() / 2; ++i) uv1Stream.emplace_back(uvs1[2 * i], uvs1[2 * i + 1]);
    std::vector<glm::vec4> colorStream;
    const std::size_t colorComponents = count > 0 ? colors.size() / count : 0;  // 3 or 4
    for (std::size_t i = 0; i < count && !colors.empty(); ++i) {
        const float* c = &colors[i * colorComponents];
        colorStream.emplace_back(c[0], c[1], c[2], colorComponents == 4 ? c[3] : 1.0f);
    }
    // A tangent is a direction in the surface: it transforms by the linear part itself (not the
    // inverse transpose, as normals do). Under a mirror the bitangent cross(n, t) turns around
    // while the texture's v direction does not, so w changes sign.
    std::vector<glm::vec4> tangentStream;
    for (std::size_t i = 0; i < fileTangents.size() / 4; ++i) {
        const float* t = &fileTangents[4 * i];
        const glm::vec3 direction = glm::vec3(linear * glm::dvec3(t[0], t[1], t[2]));
        const float length = glm::length(direction);
        // A singular transform (a zero scale) leaves no direction; any unit vector will do there.
        const glm::vec3 unit = length > 0.0f && std::isfinite(length) ? direction / length : glm::vec3(1.0f, 0.0f, 0.0f);
        const float w = (t[3] < 0.0f ? -1.0f : 1.0f) * (mirrored ? -1.0f : 1.0f);
        tangentStream.emplace_back(unit, w);
    }
    if (block.generateTangents) tangentStream.assign(count, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));  // generated later
    appendToStream(scene_.uv1, uv1Stream, block.base, count, glm::vec2(0.0f));
    appendToStream(scene_.colors, colorStream, block.base, count, glm::vec4(1.0f));
    appendToStream(scene_.tangents, tangentStream, block.base, count, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    return block;
}

namespace {

// glTF's triangle modes as a triangle list, winding kept (glTF 2.0, "3.7.2.1 Overview" of meshes):
// strip triangle i is (i, i+1+i%2, i+2-i%2), fan triangle i is (i+1, i+2, 0). Fewer than three
// vertices make no triangle.
std::vector<std::uint32_t> asTriangleList(int mode, std::vector<std::uint32_t> vertices) {
    if (vertices.size() < 3) return {};
    if (mode == TINYGLTF_MODE_TRIANGLES) return vertices;
    std::vector<std::uint32_t> triangles;
    triangles.reserve(3 * (vertices.size() - 2));
    for (std::size_t i = 0; i + 2 < vertices.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            const std::size_t odd = i % 2;
            triangles.insert(triangles.end(), {vertices[i], vertices[i + 1 + odd], vertices[i + 2 - odd]});
        } else {
            triangles.insert(triangles.end(), {vertices[i + 1], vertices[i + 2], vertices[0]});
        }
    }
    return triangles;
}

}  // namespace

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
    if (prim.mode == TINYGLTF_MODE_TRIANGLES && local.size() % 3 != 0) {
        const std::string what = prim.indices >= 0 ? describe(model_, prim.indices, use) : where();
        fail(path_, what + ": " + std::to_string(local.size()) + (prim.indices >= 0 ? " indices" : " vertices") +
                        " do not make whole triangles (not a multiple of 3)");
    }
    // A strip or fan of n vertices makes 3 (n - 2) indices, up to three times what it reads.
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && local.size() > 2 && 3 * (local.size() - 2) > room)
        fail(path_, where() + ": too many triangles to draw (index limit)");
    local = asTriangleList(prim.mode, std::move(local));
    for (std::size_t t = 0; t < local.size(); t += 3) {
        scene_.indices.push_back(block.base + local[t]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 2 : 1)]);
        scene_.indices.push_back(block.base + local[t + (mirrored ? 1 : 2)]);
    }
}

// Per-vertex normals from the triangles that use the vertices, each face weighted by its area
// (the cross product of two edges is twice the area). Positions are already in world space and
// winding already corrected, so the result needs no transform.
void SceneBuilder::generateNormals(const Block& block, const Ranges& ranges) {
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

std::uint32_t SceneBuilder::materialSetOf(const PrimitivePlan& prim, double meshScale) {
    std::vector<std::uint32_t> set{materials_.materialFor(prim.material, meshScale)};
    for (int variantMaterial : prim.variantMaterials) set.push_back(materials_.materialFor(variantMaterial, meshScale));
    const auto [it, added] = materialSetIndex_.try_emplace(set, static_cast<std::uint32_t>(materialSets_.size()));
    if (added) materialSets_.push_back(std::move(set));
    return it->second;
}

void SceneBuilder::finish() {
    // Ranges in the order of their material sets (the default material first): for a file
    // without variants, one range per material in material order.
    std::vector<std::uint32_t> rank(materialSets_.size());
    std::uint32_t next = 0;
    for (const auto& entry : materialSetIndex_) rank[entry.second] = next++;
    std::vector<std::uint32_t> setOfRank(materialSets_.size());
    for (std::uint32_t s = 0; s < rank.size(); ++s) setOfRank[rank[s]] = s;

    std::vector<std::size_t> offsets(materialSets_.size() + 1, 0);
    for (const DrawRange& run : runs_) offsets[rank[run.material] + 1] += run.indexCount;
    for (std::size_t m = 1; m < offsets.size(); ++m) offsets[m] += offsets[m - 1];

    std::vector<std::uint32_t> grouped(scene_.indices.size());
    std::vector<std::size_t> cursor(offsets.begin(), offsets.end() - 1);
    for (const DrawRange& run : runs_) {
        std::size_t& at = cursor[rank[run.material]];
        std::copy_n(scene_.indices.begin() + run.firstIndex, run.indexCount, grouped.begin() + at);
        at += run.indexCount;
    }
    scene_.indices.swap(grouped);
    // A stream only a skipped or empty primitive asked for is not part of the scene.
    if (!colorsDrawn_) scene_.colors.clear();
    if (!uv1Drawn_) scene_.uv1.clear();
    if (!tangentsDrawn_) scene_.tangents.clear();
    scene_.draws.clear();
    MaterialVariants& variants = scene_.materialVariants;
    variants.defaults.clear();
    variants.materials.assign(variants.names.size(), {});
    for (std::size_t r = 0; r + 1 < offsets.size(); ++r) {
        if (offsets[r + 1] == offsets[r]) continue;
        const std::vector<std::uint32_t>& set = materialSets_[setOfRank[r]];
        scene_.draws.push_back({static_cast<std::uint32_t>(offsets[r]), static_cast<std::uint32_t>(offsets[r + 1] - offsets[r]), set[0]});
        if (variants.empty()) continue;
        variants.defaults.push_back(set[0]);
        // A primitive without mappings takes its default under every variant.
        for (std::size_t v = 0; v < variants.names.size(); ++v) variants.materials[v].push_back(set.size() > 1 ? set[1 + v] : set[0]);
    }
}

}  // namespace ml::gltf
