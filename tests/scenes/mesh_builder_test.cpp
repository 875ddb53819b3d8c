// Tests of MeshBuilder: closed primitives are wound outward (positive signed volume of the right
// size), normals point out, grouping by material and texture scaling.
#include "scenes/mesh_builder.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace ml {
namespace {

Scene build(const MeshBuilder& mb) {
    Scene s;
    mb.writeTo(s);
    return s;
}

// Divergence theorem: positive for a closed mesh wound counter-clockwise seen from outside.
double signedVolume(const Scene& s) {
    double v = 0.0;
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const glm::dvec3 a = s.vertices[s.indices[t]].position, b = s.vertices[s.indices[t + 1]].position,
                         c = s.vertices[s.indices[t + 2]].position;
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

// Each triangle's geometric normal agrees with its vertex normals.
std::size_t windingDisagreements(const Scene& s) {
    std::size_t bad = 0;
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const Vertex& a = s.vertices[s.indices[t]];
        const Vertex& b = s.vertices[s.indices[t + 1]];
        const Vertex& c = s.vertices[s.indices[t + 2]];
        const glm::vec3 g = glm::cross(b.position - a.position, c.position - a.position);
        if (glm::dot(g, a.normal + b.normal + c.normal) <= 0.0f) ++bad;
    }
    return bad;
}

TEST(MeshBuilderTest, SphereIsClosedAndFacesOut) {
    MeshBuilder mb(1);
    const glm::vec3 c{1.0f, 2.0f, -3.0f};
    mb.addSphere(0, c, 0.5f, 64, 32);
    const Scene s = build(mb);
    const double exact = 4.0 / 3.0 * glm::pi<double>() * 0.125;
    EXPECT_NEAR(signedVolume(s), exact, 0.02 * exact);
    EXPECT_EQ(windingDisagreements(s), 0u);
    for (const Vertex& v : s.vertices) {
        EXPECT_NEAR(glm::length(v.position - c), 0.5f, 1e-5f);
        EXPECT_GT(glm::dot(v.normal, v.position - c), 0.0f);
    }
}

TEST(MeshBuilderTest, BoxIsClosedFlatAndFacesOut) {
    MeshBuilder mb(1);
    mb.addBox(0, glm::vec3(-1.0f, 0.0f, 2.0f), glm::vec3(1.0f, 0.5f, 5.0f));
    const Scene s = build(mb);
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_EQ(s.vertices.size(), 24u);
    EXPECT_NEAR(signedVolume(s), 2.0 * 0.5 * 3.0, 1e-5);
    EXPECT_EQ(windingDisagreements(s), 0u);
    const glm::vec3 centre{0.0f, 0.25f, 3.5f};
    for (const Vertex& v : s.vertices) EXPECT_GT(glm::dot(v.normal, v.position - centre), 0.0f);
}

TEST(MeshBuilderTest, BoxFaceMaskLeavesFacesOut) {
    MeshBuilder mb(1);
    mb.addBox(0, glm::vec3(0.0f), glm::vec3(1.0f), 0x3fu & ~0x4u);  // no bottom
    const Scene s = build(mb);
    EXPECT_EQ(s.triangleCount(), 10u);
    for (const Vertex& v : s.vertices) EXPECT_NE(v.normal, glm::vec3(0.0f, -1.0f, 0.0f));
}

TEST(MeshBuilderTest, RotatedBoxKeepsItsVolume) {
    MeshBuilder mb(1);
    Frame f = frameAlong(glm::vec3(3.0f, 1.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.5f));
    mb.addBox(0, f, glm::vec3(0.5f, 1.0f, 0.25f));
    const Scene s = build(mb);
    EXPECT_NEAR(signedVolume(s), 1.0, 1e-4);
    EXPECT_EQ(windingDisagreements(s), 0u);
}

TEST(MeshBuilderTest, CappedCylinderIsClosedAlongAnyAxis) {
    for (const glm::vec3 axis : {glm::vec3(0, 1, 0), glm::vec3(0, -1, 0), glm::vec3(1, 0, 0), glm::vec3(0.3f, 0.2f, -1)}) {
        MeshBuilder mb(1);
        mb.addCylinder(0, frameAlong(glm::vec3(0.5f, -1.0f, 2.0f), axis), 0.4f, 0.4f, 2.0f, 96);
        const Scene s = build(mb);
        const double exact = glm::pi<double>() * 0.16 * 2.0;
        EXPECT_NEAR(signedVolume(s), exact, 0.01 * exact);
        EXPECT_EQ(windingDisagreements(s), 0u);
    }
}

TEST(MeshBuilderTest, LatheProfileNormalsPointAwayFromTheSolid) {
    // A column-like profile: up the outside, a bead, inward over the top to the axis.
    ProfileBuilder pb({1.0f, 0.0f});
    pb.lineTo(1.0f, 2.0f, 3);
    pb.arcTo({1.0f, 2.2f}, 0.5f * glm::pi<float>(), true, 6);
    pb.lineTo(0.0f, 2.4f);
    ASSERT_EQ(pb.runs().size(), 3u);
    for (const ProfilePoint& p : pb.runs()[0]) EXPECT_EQ(p.normal, glm::vec2(1.0f, 0.0f));
    for (const ProfilePoint& p : pb.runs()[2]) EXPECT_GT(p.normal.y, 0.99f);
    EXPECT_NEAR(pb.cursor().x, 0.0f, 1e-6f);

    MeshBuilder mb(1);
    Frame f;
    mb.addLathe(0, f, pb.runs(), 48);
    const Scene s = build(mb);
    EXPECT_EQ(windingDisagreements(s), 0u);
    for (const Vertex& v : s.vertices) {
        const glm::vec2 radial{v.position.x, v.position.z};
        if (glm::length(radial) > 0.5f && v.position.y < 2.0f) {
            EXPECT_GT(glm::dot(glm::vec2(v.normal.x, v.normal.z), radial), 0.0f);
        }
    }
}

TEST(MeshBuilderTest, FlatQuadFacesItsNormalWhicheverWayTheCornersRun) {
    for (bool reversed : {false, true}) {
        MeshBuilder mb(1);
        glm::vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        if (reversed) std::swap(p[1], p[3]);
        mb.addFlatQuad(0, p[0], p[1], p[2], p[3], glm::vec3(0.0f, 0.0f, -1.0f));
        const Scene s = build(mb);
        ASSERT_EQ(s.triangleCount(), 2u);
        EXPECT_EQ(windingDisagreements(s), 0u);
    }
}

TEST(MeshBuilderTest, GridDropsDegenerateTrianglesAtACollapsedEdge) {
    MeshBuilder mb(1);
    // A cone: the t = 1 row collapses to the apex.
    mb.addGrid(0, 8, 2, [](float s, float t) {
        const float a = glm::two_pi<float>() * s;
        SurfacePoint p;
        p.position = glm::vec3((1.0f - t) * std::cos(a), t, (1.0f - t) * std::sin(a));
        p.normal = glm::vec3(std::cos(a), 1.0f, std::sin(a));
        return p;
    });
    const Scene s = build(mb);
    EXPECT_EQ(s.triangleCount(), 8u * 2u + 8u);
    EXPECT_EQ(windingDisagreements(s), 0u);
}

TEST(MeshBuilderTest, WritesOneDrawRangePerMaterialInMaterialOrder) {
    MeshBuilder mb(3);
    mb.addBox(2, glm::vec3(0.0f), glm::vec3(1.0f));
    mb.addBox(0, glm::vec3(2.0f), glm::vec3(3.0f));
    mb.addBox(2, glm::vec3(4.0f), glm::vec3(5.0f));
    EXPECT_EQ(mb.triangleCount(), 36u);
    Scene s;
    s.vertices.resize(5);  // writeTo appends: indices must account for what is already there
    mb.writeTo(s);
    ASSERT_EQ(s.draws.size(), 2u);
    EXPECT_EQ(s.draws[0].material, 0u);
    EXPECT_EQ(s.draws[0].firstIndex, 0u);
    EXPECT_EQ(s.draws[0].indexCount, 36u);
    EXPECT_EQ(s.draws[1].material, 2u);
    EXPECT_EQ(s.draws[1].firstIndex, 36u);
    EXPECT_EQ(s.draws[1].indexCount, 72u);
    for (std::uint32_t i : s.indices) {
        EXPECT_GE(i, 5u);
        EXPECT_LT(i, s.vertices.size());
    }
    // Material 0's box is the one at 2..3.
    for (std::uint32_t k = 0; k < 36; ++k) EXPECT_GE(s.vertices[s.indices[k]].position.x, 2.0f);
}

TEST(MeshBuilderTest, TextureCoordinatesScaleByMaterial) {
    MeshBuilder mb(2);
    mb.setUvScale(1, 0.25f);
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    mb.addFlatQuad(0, {0, 0, 0}, {4, 0, 0}, {4, 0, -4}, {0, 0, -4}, up);
    mb.addFlatQuad(1, {0, 0, 0}, {4, 0, 0}, {4, 0, -4}, {0, 0, -4}, up);
    const Scene s = build(mb);
    float max0 = 0.0f, max1 = 0.0f;
    for (std::uint32_t k = 0; k < 6; ++k) max0 = std::max(max0, s.vertices[s.indices[k]].uv.x);
    for (std::uint32_t k = 6; k < 12; ++k) max1 = std::max(max1, s.vertices[s.indices[k]].uv.x);
    EXPECT_FLOAT_EQ(max0, 4.0f);
    EXPECT_FLOAT_EQ(max1, 1.0f);
}

TEST(MeshBuilderTest, RejectsAnUnknownMaterial) {
    MeshBuilder mb(1);
    EXPECT_THROW(mb.addBox(1, glm::vec3(0.0f), glm::vec3(1.0f)), std::out_of_range);
}

}  // namespace
}  // namespace ml
