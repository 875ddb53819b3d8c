// Tests of the procedural scenes (atrium, plane, boxes): geometry that a renderer can trust,
// determinism, sizes, budgets and the suggested views.
#include "scenes/procedural_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <set>
#include <tuple>

namespace ml {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Checks everything a renderer relies on: finite attributes, unit normals, indices in range,
// draw ranges tiling the index buffer with valid materials, valid textures and images, bounds
// that match the vertices, no degenerate triangles, and winding that agrees with the normals.
void expectValidScene(const Scene& s) {
    ASSERT_FALSE(s.vertices.empty());
    ASSERT_FALSE(s.indices.empty());
    ASSERT_EQ(s.indices.size() % 3, 0u);

    std::size_t badAttr = 0, badNormal = 0;
    for (const Vertex& v : s.vertices) {
        if (!finite(v.position) || !finite(v.normal) || !std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) ++badAttr;
        if (std::abs(glm::length(v.normal) - 1.0f) > 1e-4f) ++badNormal;
    }
    EXPECT_EQ(badAttr, 0u) << "vertices with NaN or infinite attributes";
    EXPECT_EQ(badNormal, 0u) << "normals that are not unit length";

    std::size_t outOfRange = 0;
    for (std::uint32_t i : s.indices)
        if (i >= s.vertices.size()) ++outOfRange;
    ASSERT_EQ(outOfRange, 0u) << "indices past the vertex array";

    // Draw ranges: whole triangles, tiling the index buffer in order, one per material.
    ASSERT_FALSE(s.draws.empty());
    std::uint32_t next = 0;
    std::set<std::uint32_t> drawMaterials;
    for (const DrawRange& d : s.draws) {
        EXPECT_EQ(d.firstIndex, next);
        EXPECT_GT(d.indexCount, 0u);
        EXPECT_EQ(d.indexCount % 3, 0u);
        EXPECT_LT(d.material, s.materials.size());
        drawMaterials.insert(d.material);
        next = d.firstIndex + d.indexCount;
    }
    EXPECT_EQ(next, s.indices.size());
    EXPECT_EQ(drawMaterials.size(), s.draws.size()) << "geometry should be grouped: one draw range per material";

    for (const Material& m : s.materials) {
        EXPECT_TRUE(m.baseColorTexture.image == -1 || (m.baseColorTexture.image >= 0 && m.baseColorTexture.image < int(s.images.size())))
            << m.name;
        for (int c = 0; c < 4; ++c) {
            EXPECT_GE(m.baseColorFactor[c], 0.0f) << m.name;
            EXPECT_LE(m.baseColorFactor[c], 1.0f) << m.name;
        }
        EXPECT_GE(m.metallic, 0.0f) << m.name;
        EXPECT_LE(m.metallic, 1.0f) << m.name;
        EXPECT_GT(m.roughness, 0.0f) << m.name;
        EXPECT_LE(m.roughness, 1.0f) << m.name;
        EXPECT_FALSE(m.name.empty());
    }
    for (const Image& img : s.images) {
        EXPECT_GT(img.width, 0) << img.name;
        EXPECT_GT(img.height, 0) << img.name;
        EXPECT_EQ(img.rgba8.size(), std::size_t(img.width) * std::size_t(img.height) * 4) << img.name;
    }

    Bounds b;
    for (const Vertex& v : s.vertices) b.extend(v.position);
    EXPECT_EQ(s.bounds.min, b.min);
    EXPECT_EQ(s.bounds.max, b.max);

    std::size_t degenerate = 0, agree = 0, total = 0;
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const Vertex& a = s.vertices[s.indices[t]];
        const Vertex& bv = s.vertices[s.indices[t + 1]];
        const Vertex& c = s.vertices[s.indices[t + 2]];
        const glm::vec3 e1 = bv.position - a.position, e2 = c.position - a.position;
        const glm::vec3 g = glm::cross(e1, e2);
        if (glm::length(g) <= 1e-6f * glm::length(e1) * glm::length(e2)) {
            ++degenerate;
            continue;
        }
        ++total;
        if (glm::dot(g, a.normal + bv.normal + c.normal) > 0.0f) ++agree;
    }
    EXPECT_EQ(degenerate, 0u) << "triangles of zero area";
    ASSERT_GT(total, 0u);
    EXPECT_GT(double(agree) / double(total), 0.99) << (total - agree) << " of " << total
                                                   << " triangles wound against their normals";
}

std::size_t imageBytes(const Scene& s) {
    std::size_t n = 0;
    for (const Image& img : s.images) n += img.rgba8.size();
    return n;
}

// --- Atrium -----------------------------------------------------------------------------------

// Built once per detail level for the tests that only read them.
const Scene& atrium(float detail) {
    static const Scene quarter = makeAtrium(0.25f);
    static const Scene full = makeAtrium(1.0f);
    return detail == 1.0f ? full : quarter;
}

TEST(AtriumTest, IsNamedAtrium) { EXPECT_EQ(atrium(0.25f).name, "atrium"); }

TEST(AtriumTest, FullDetailIsWithinTheTriangleBudget) {
    const std::size_t n = atrium(1.0f).triangleCount();
    EXPECT_GE(n, 100000u);
    EXPECT_LE(n, 300000u);
}

TEST(AtriumTest, DetailScalesTheTriangleCountRoughlyLinearly) {
    const std::size_t quarter = atrium(0.25f).triangleCount();
    const std::size_t half = makeAtrium(0.5f).triangleCount();
    const std::size_t full = atrium(1.0f).triangleCount();
    const std::size_t twice = makeAtrium(2.0f).triangleCount();
    EXPECT_LT(quarter, half);
    EXPECT_LT(half, full);
    EXPECT_LT(full, twice);
    EXPECT_LE(quarter, 40000u) << "detail 0.25 is meant as a small scene for tests";
    const double ratio = double(twice) / double(full);
    EXPECT_GT(ratio, 1.6);
    EXPECT_LT(ratio, 2.4);
}

TEST(AtriumTest, DetailBelowTheRangeIsClamped) {
    EXPECT_EQ(makeAtrium(1e-6f).triangleCount(), makeAtrium(0.01f).triangleCount());
}

TEST(AtriumTest, NonPositiveOrNaNDetailThrows) {
    for (float d : {0.0f, -0.0f, -1.0f, -std::numeric_limits<float>::infinity(),
                    std::numeric_limits<float>::quiet_NaN()}) {
        try {
            (void)makeAtrium(d);
            ADD_FAILURE() << "no SceneError for detail " << d;
        } catch (const SceneError& e) {
            EXPECT_STREQ(e.what(), "atrium: detail must be > 0");
        }
    }
}

TEST(AtriumTest, IsDeterministic) {
    const Scene a = makeAtrium(0.25f);
    const Scene& b = atrium(0.25f);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)), 0);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.draws.size(), b.draws.size());
    for (std::size_t i = 0; i < a.draws.size(); ++i) {
        EXPECT_EQ(a.draws[i].firstIndex, b.draws[i].firstIndex);
        EXPECT_EQ(a.draws[i].indexCount, b.draws[i].indexCount);
        EXPECT_EQ(a.draws[i].material, b.draws[i].material);
    }
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i) EXPECT_EQ(a.images[i].rgba8, b.images[i].rgba8);
}

TEST(AtriumTest, QuarterDetailGeometryIsValid) { expectValidScene(atrium(0.25f)); }

TEST(AtriumTest, FullDetailGeometryIsValid) { expectValidScene(atrium(1.0f)); }

TEST(AtriumTest, BoundsMatchTheCourtyardsSize) {
    const Bounds& b = atrium(1.0f).bounds;
    const glm::vec3 size = b.size();
    EXPECT_NEAR(size.x, 36.0f, 2.0f);
    EXPECT_NEAR(size.z, 16.0f, 2.0f);
    EXPECT_NEAR(size.y, 12.0f, 1.0f);
    EXPECT_NEAR(b.min.y, 0.0f, 1e-5f) << "the floor is at y = 0";
    EXPECT_NEAR(b.center().x, 0.0f, 0.5f);
    EXPECT_NEAR(b.center().z, 0.0f, 0.5f);
}

TEST(AtriumTest, FloorFacesUp) {
    const Scene& s = atrium(0.25f);
    std::size_t onFloor = 0, facingDown = 0;
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const glm::vec3 a = s.vertices[s.indices[t]].position, b = s.vertices[s.indices[t + 1]].position,
                        c = s.vertices[s.indices[t + 2]].position;
        if (std::abs(a.y) > 1e-5f || std::abs(b.y) > 1e-5f || std::abs(c.y) > 1e-5f) continue;
        ++onFloor;
        if (glm::cross(b - a, c - a).y <= 0.0f) ++facingDown;
    }
    EXPECT_GT(onFloor, 0u);
    EXPECT_EQ(facingDown, 0u) << "triangles lying on the floor must face up";
}

TEST(AtriumTest, HasSeveralMaterialsWithProceduralTextures) {
    const Scene& s = atrium(0.25f);
    EXPECT_GE(s.materials.size(), 8u);
    EXPECT_GE(s.images.size(), 4u);
    EXPECT_LE(imageBytes(s), 4u * 1024u * 1024u) << "procedural textures should stay small";

    std::set<std::tuple<float, float, float>> colours;
    std::set<float> speculars;
    std::size_t textured = 0;
    for (const Material& m : s.materials) {
        colours.insert({m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b});
        speculars.insert(m.roughness);
        if (m.baseColorTexture.present()) ++textured;
    }
    EXPECT_GE(colours.size(), 6u);
    EXPECT_GE(speculars.size(), 4u);
    EXPECT_GE(textured, 4u);
    // Every texture is used by some material, and every material by some draw.
    std::set<int> usedImages;
    for (const Material& m : s.materials)
        for (const TextureRef* t : {&m.baseColorTexture, &m.normalTexture, &m.metallicRoughnessTexture, &m.occlusionTexture,
                                    &m.emissiveTexture})
            if (t->present()) usedImages.insert(t->image);
    EXPECT_EQ(usedImages.size(), s.images.size());
    EXPECT_EQ(s.draws.size(), s.materials.size());
}

TEST(AtriumTest, SuggestedViewLooksDownTheCourtyardFromInside) {
    const Scene& s = atrium(0.25f);
    ASSERT_TRUE(s.suggestedView.has_value());
    const CameraPose& v = *s.suggestedView;
    EXPECT_GE(v.fovyDegrees, 45.0f);
    EXPECT_LE(v.fovyDegrees, 75.0f);
    // Inside the courtyard (between the end walls and in front of the arcades), above the ground floor arches.
    EXPECT_LT(std::abs(v.eye.x), 17.4f);
    EXPECT_LT(std::abs(v.eye.z), 4.4f);
    EXPECT_GT(v.eye.y, 4.0f);
    EXPECT_LT(v.eye.y, 11.0f);
    const glm::vec3 dir = glm::normalize(v.target - v.eye);
    EXPECT_GT(std::abs(dir.x), 0.95f) << "the view runs along the courtyard's length";
    EXPECT_LT(dir.y, 0.0f) << "and looks slightly down";
    EXPECT_GT(glm::length(v.target - v.eye), 20.0f);
}

// --- Plane ------------------------------------------------------------------------------------

TEST(PlaneTest, IsATwentyMetreSquareFacingUp) {
    const Scene s = makePlane();
    EXPECT_EQ(s.name, "plane");
    expectValidScene(s);
    EXPECT_GE(s.triangleCount(), 2u);
    EXPECT_LE(s.triangleCount(), 512u);
    EXPECT_EQ(s.bounds.min, glm::vec3(-10.0f, 0.0f, -10.0f));
    EXPECT_EQ(s.bounds.max, glm::vec3(10.0f, 0.0f, 10.0f));
    for (const Vertex& v : s.vertices) EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    ASSERT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.materials[0].baseColorTexture.image, -1);
    EXPECT_TRUE(s.images.empty());
    EXPECT_GT(s.materials[0].baseColorFactor.r, 0.5f);
}

TEST(PlaneTest, SuggestedViewLooksDownAtItFromAnAngle) {
    const Scene s = makePlane();
    ASSERT_TRUE(s.suggestedView.has_value());
    const CameraPose& v = *s.suggestedView;
    EXPECT_GT(v.eye.y, 1.0f);
    const glm::vec3 dir = glm::normalize(v.target - v.eye);
    EXPECT_LT(dir.y, -0.2f);
    EXPECT_GT(dir.y, -0.99f) << "at an angle, not straight down";
    EXPECT_LE(std::abs(v.target.x), 10.0f);
    EXPECT_LE(std::abs(v.target.z), 10.0f);
}

TEST(PlaneTest, IsDeterministic) {
    const Scene a = makePlane(), b = makePlane();
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)), 0);
    EXPECT_EQ(a.indices, b.indices);
}

// --- Boxes ------------------------------------------------------------------------------------

TEST(BoxesTest, AFewColouredBoxesOnAPlane) {
    const Scene s = makeBoxes();
    EXPECT_EQ(s.name, "boxes");
    expectValidScene(s);
    // The ground is two triangles; each box five faces (its bottom stands on the ground).
    ASSERT_GE(s.triangleCount(), 2u);
    ASSERT_EQ((s.triangleCount() - 2) % 10, 0u);
    const std::size_t boxes = (s.triangleCount() - 2) / 10;
    EXPECT_GE(boxes, 4u);
    EXPECT_LE(boxes, 6u);
    std::set<std::tuple<float, float, float>> colours;
    for (const Material& m : s.materials) colours.insert({m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b});
    EXPECT_GE(colours.size(), 4u);
    EXPECT_NEAR(s.bounds.min.y, 0.0f, 1e-6f);
    EXPECT_GT(s.bounds.max.y, 1.0f);
    EXPECT_GE(s.bounds.min.x, -10.0f);
    EXPECT_LE(s.bounds.max.x, 10.0f);
    EXPECT_GE(s.bounds.min.z, -10.0f);
    EXPECT_LE(s.bounds.max.z, 10.0f);
    EXPECT_NEAR(s.bounds.size().x, 20.0f, 1e-4f);
    EXPECT_NEAR(s.bounds.size().z, 20.0f, 1e-4f);
}

TEST(BoxesTest, IsFlatShaded) {
    const Scene s = makeBoxes();
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const Vertex& a = s.vertices[s.indices[t]];
        const Vertex& b = s.vertices[s.indices[t + 1]];
        const Vertex& c = s.vertices[s.indices[t + 2]];
        EXPECT_EQ(a.normal, b.normal);
        EXPECT_EQ(a.normal, c.normal);
        const glm::vec3 g = glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
        EXPECT_GT(glm::dot(g, a.normal), 0.9999f);
    }
    // (So no vertex is shared by faces with different normals: each triangle's vertices carry its own.)
}

TEST(BoxesTest, SuggestedViewSeesTheBoxesFromAbove) {
    const Scene s = makeBoxes();
    ASSERT_TRUE(s.suggestedView.has_value());
    const CameraPose& v = *s.suggestedView;
    EXPECT_GT(v.eye.y, s.bounds.max.y);
    EXPECT_LT(glm::normalize(v.target - v.eye).y, 0.0f);
    EXPECT_GT(glm::length(v.eye - s.bounds.center()), 0.5f * glm::length(s.bounds.size()) * 0.5f);
}

// --- All --------------------------------------------------------------------------------------

TEST(ProceduralScenesTest, AllDrawRangesAreFewAndGroupedByMaterial) {
    for (const Scene* s : {&atrium(0.25f), &atrium(1.0f)}) {
        EXPECT_LE(s->draws.size(), s->materials.size());
    }
    const Scene p = makePlane(), b = makeBoxes();
    EXPECT_EQ(p.draws.size(), 1u);
    EXPECT_EQ(b.draws.size(), b.materials.size());
}

}  // namespace
}  // namespace ml
