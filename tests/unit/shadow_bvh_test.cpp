// The shadow rays' BVH (renderer/raytracing/shadow_bvh.h): its layout holds every casting
// triangle once inside boxes that contain it, and the CPU mirror of the GPU's traversal
// (shadow_bvh_traversal.h) gives Embree's own answer (rtcOccluded1, embree_occlusion.h) on cases
// worked out by hand and on 100,000 random rays from surfaces to lights in boxes and the atrium,
// except for rays that pass within a hair of a triangle's edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/hash.h"
#include "renderer/raytracing/embree_occlusion.h"
#include "renderer/raytracing/shadow_alpha.h"
#include "renderer/raytracing/shadow_bvh.h"
#include "renderer/raytracing/shadow_bvh_traversal.h"
#include "renderer/scene/surface_samples.h"
#include "scenes/scene_library.h"

namespace ml {
namespace {

// Every width the layout has (--shadow-bvh-width).
constexpr std::uint32_t kWidths[] = {2u, 4u, 8u};

// --- Scenes made by hand ------------------------------------------------------------------------

std::uint32_t addMaterial(Scene& scene, AlphaMode mode) {
    Material m;
    m.name = "material " + std::to_string(scene.materials.size());
    m.alphaMode = mode;
    scene.materials.push_back(m);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

// The quad corner, corner + u, corner + u + v, corner + v, as two triangles in a range of its own.
void addQuad(Scene& scene, glm::vec3 corner, glm::vec3 u, glm::vec3 v, std::uint32_t material) {
    const auto first = static_cast<std::uint32_t>(scene.vertices.size());
    for (const glm::vec3& p : {corner, corner + u, corner + u + v, corner + v}) scene.vertices.push_back(Vertex{p, {0, 0, 1}, {0, 0}});
    const auto firstIndex = static_cast<std::uint32_t>(scene.indices.size());
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + i);
    scene.draws.push_back(DrawRange{firstIndex, 6, material});
    computeBounds(scene);
}

// A 2 x 2 quad in the plane z = 0, centred on the origin.
Scene quadScene(AlphaMode mode = AlphaMode::Opaque) {
    Scene scene;
    scene.name = "quad";
    addQuad(scene, {-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, addMaterial(scene, mode));
    return scene;
}

// Both answers, and that they agree.
struct Answers {
    bool bvh;
    bool embree;
};
Answers occlusion(const Scene& scene, glm::vec3 origin, glm::vec3 direction, float tMax, const ShadowCoverage& covered = {}) {
    const ShadowBvh bvh = buildShadowBvh(scene);
    const EmbreeOcclusion embree(scene);
    return {occludedByBvh(bvh, origin, direction, tMax, covered), embree.occluded(origin, direction, tMax, covered)};
}

void expectBoth(bool expected, const Answers& answers, const std::string& what = "") {
    EXPECT_EQ(answers.bvh, expected) << what << " (our BVH's traversal)";
    EXPECT_EQ(answers.embree, expected) << what << " (Embree's rtcOccluded1)";
}

// --- The layout's invariants ----------------------------------------------------------------------

glm::vec3 xyz(const glm::vec4& v) { return glm::vec3(v); }
std::uint32_t wBits(const glm::vec4& v) { return glm::floatBitsToUint(v.w); }

bool emptyBox(glm::vec3 lo, glm::vec3 hi) { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }

struct Walk {
    std::vector<int> triangleSeen;   // times each triangle sits in a leaf
    std::vector<int> nodeSeen;       // times each node is referenced (the root: once, by the walk)
    std::uint32_t depth = 0;
    std::uint32_t stackNeed = 0;     // shadow_bvh.h's need(root), worked out again here
    std::size_t leaves = 0;
    std::vector<std::string> faults;
};

// Walks the subtree of `reference`, checking that every corner under it lies in [lo, hi];
// `level` is the level of `reference` as an inner node (the root's: 1). Returns the stack entries
// the traversal needs under it once it is popped (shadow_bvh.h).
std::uint32_t walk(const ShadowBvh& bvh, std::uint32_t reference, glm::vec3 lo, glm::vec3 hi, std::uint32_t level, std::uint32_t parent,
                   Walk& w) {
    if (w.faults.size() > 10) return 0;
    if (shadowReferenceIsLeaf(reference)) {
        const std::uint32_t first = shadowLeafFirst(reference), count = shadowLeafCount(reference);
        ++w.leaves;
        if (count > kShadowBvhMaxLeafSize) w.faults.push_back("a leaf of " + std::to_string(count) + " triangles");
        for (std::uint32_t i = first; i < first + count; ++i) {
            if (i >= bvh.triangles.size()) {
                w.faults.push_back("a leaf past the last triangle");
                return 0;
            }
            ++w.triangleSeen[i];
            const GpuBvhTriangle& t = bvh.triangles[i];
            for (const glm::vec4& c : {t.v0, t.v1, t.v2})
                if (glm::any(glm::lessThan(xyz(c), lo)) || glm::any(glm::greaterThan(xyz(c), hi)))
                    w.faults.push_back("triangle " + std::to_string(i) + " sticks out of its box");
        }
        return 0;
    }
    if (reference >= bvh.nodeCount() || (level > 1 && reference <= parent)) {
        w.faults.push_back("node reference " + std::to_string(reference) + " out of order or past the end");
        return 0;
    }
    ++w.nodeSeen[reference];
    w.depth = std::max(w.depth, level);
    const glm::vec4* n = bvh.node(reference);
    if (bvh.width == 2 && (wBits(n[2]) != 0u || wBits(n[3]) != 0u)) w.faults.push_back("a right box's w is not 0");
    std::uint32_t pushed = 0, need = 0;
    bool emptySeen = false;
    for (std::uint32_t slot = 0; slot < bvh.width; ++slot) {
        const ShadowBvhChild child = shadowNodeChild(n, bvh.width, slot);
        if (!child.present) {
            // A wide node's empty slots follow its children, behind empty boxes.
            emptySeen = true;
            if (!emptyBox(child.lo, child.hi)) w.faults.push_back("an empty slot with a box");
            continue;
        }
        if (emptySeen) w.faults.push_back("a child after an empty slot");
        // The one-leaf binary tree's right child: its leaf again, behind an empty box, not walked twice.
        if (emptyBox(child.lo, child.hi)) {
            const ShadowBvhChild first = shadowNodeChild(n, bvh.width, 0);
            if (!(bvh.width == 2 && bvh.nodeCount() == 1 && slot == 1 && child.reference == first.reference))
                w.faults.push_back("an empty box outside the one-leaf tree");
            ++pushed;
            continue;
        }
        // A child's box lies inside its parent's.
        if (glm::any(glm::lessThan(child.lo, lo)) || glm::any(glm::greaterThan(child.hi, hi)))
            w.faults.push_back("node " + std::to_string(reference) + "'s child box sticks out of its own");
        need = std::max(need, pushed + walk(bvh, child.reference, child.lo, child.hi, level + 1, reference, w));
        ++pushed;
    }
    if (pushed < 2 && bvh.nodeCount() > 1) w.faults.push_back("a node of fewer than two children");
    return std::max(need, pushed);
}

// Every casting triangle of `scene` once, in a box that holds it; the stack bound; the triangles'
// words. Returns the walk for the callers' own checks.
Walk expectLayoutInvariants(const Scene& scene, const ShadowBvh& bvh) {
    std::size_t casting = 0, masked = 0;
    std::vector<std::uint32_t> materialOf(scene.triangleCount(), 0);
    for (const DrawRange& d : scene.draws) {
        const Material& m = scene.materials[d.material];
        for (std::uint32_t t = d.firstIndex / 3; t < (d.firstIndex + d.indexCount) / 3; ++t) materialOf[t] = d.material;
        if (m.blended()) continue;
        casting += d.indexCount / 3;
        if (m.alphaTested()) masked += d.indexCount / 3;
    }
    EXPECT_EQ(bvh.triangles.size(), casting);
    EXPECT_EQ(bvh.maskTriangles, masked);
    Walk w;
    w.triangleSeen.assign(bvh.triangles.size(), 0);
    w.nodeSeen.assign(bvh.nodeCount(), 0);
    if (bvh.nodes.empty()) {
        EXPECT_EQ(casting, 0u);
        return w;
    }
    const float inf = std::numeric_limits<float>::infinity();
    w.stackNeed = walk(bvh, 0u, glm::vec3(-inf), glm::vec3(inf), 1, 0, w);
    for (const std::string& f : w.faults) ADD_FAILURE() << scene.name << ": " << f;
    EXPECT_EQ(std::count(w.triangleSeen.begin(), w.triangleSeen.end(), 1), static_cast<std::ptrdiff_t>(bvh.triangles.size()))
        << "every triangle in exactly one leaf";
    EXPECT_EQ(std::count(w.nodeSeen.begin(), w.nodeSeen.end(), 1), static_cast<std::ptrdiff_t>(bvh.nodeCount()))
        << "every node reached exactly once";
    EXPECT_EQ(w.depth, bvh.depth);
    EXPECT_EQ(w.leaves, bvh.leaves);
    EXPECT_LE(bvh.depth, kShadowBvhMaxDepth);
    EXPECT_EQ(w.stackNeed, bvh.stackNeed);
    EXPECT_LE(bvh.stackNeed, static_cast<std::uint32_t>(ML_SHADOW_STACK)) << "the traversal's stack holds every push";

    // The triangles are the scene's, corners in its order, each once, with their material words.
    std::vector<int> sceneSeen(scene.triangleCount(), 0);
    Bounds bounds;
    for (const GpuBvhTriangle& t : bvh.triangles) {
        const std::uint32_t s = wBits(t.v1);
        if (s >= scene.triangleCount()) {
            ADD_FAILURE() << "scene triangle " << s << " past the end";
            return w;
        }
        ++sceneSeen[s];
        const glm::vec4* corners[3] = {&t.v0, &t.v1, &t.v2};
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(xyz(*corners[k]), scene.vertices[scene.indices[3 * s + k]].position) << "triangle " << s << " corner " << k;
            bounds.extend(xyz(*corners[k]));
        }
        const Material& m = scene.materials[materialOf[s]];
        EXPECT_FALSE(m.blended());
        EXPECT_EQ(wBits(t.v0), m.alphaTested() ? materialOf[s] : kShadowOpaque);
        EXPECT_EQ(wBits(t.v2), 0u);
    }
    EXPECT_EQ(std::count(sceneSeen.begin(), sceneSeen.end(), 1), static_cast<std::ptrdiff_t>(casting));
    EXPECT_EQ(bounds.min, bvh.bounds.min);
    EXPECT_EQ(bounds.max, bvh.bounds.max);
    return w;
}

// --- Hand-made cases ----------------------------------------------------------------------------

TEST(ShadowBvh, ARayThroughAQuadIsBlocked) {
    const Scene scene = quadScene();
    expectBoth(true, occlusion(scene, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 1.0f));
    expectBoth(true, occlusion(scene, {0.3f, 0.2f, 1.0f}, {0.0f, 0.0f, -2.0f}, 1.0f), "from the back: two-sided");
    expectBoth(true, occlusion(scene, {-2.75f, -2.1f, -1.0f}, {6.0f, 4.0f, 2.0f}, 1.0f), "slanted");
    expectBoth(false, occlusion(scene, {1.5f, 0.0f, -1.0f}, {0.0f, 0.0f, 2.0f}, 1.0f), "beside the quad");
}

TEST(ShadowBvh, ARayThatStopsJustShortOfAQuadIsNotBlocked) {
    const Scene scene = quadScene();
    // The quad at t = 0.5 of a ray of length 2 (t counts in units of |direction|).
    expectBoth(false, occlusion(scene, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 0.4999f));
    expectBoth(true, occlusion(scene, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 0.5001f));
    expectBoth(false, occlusion(scene, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 0.999f}, 1.0f), "the light 1 mm before the quad");
    expectBoth(false, occlusion(scene, {0.3f, 0.2f, 0.001f}, {0.0f, 0.0f, 2.0f}, 1.0f), "starting 1 mm past it");
    expectBoth(true, occlusion(scene, {0.3f, 0.2f, -1e-3f}, {0.0f, 0.0f, 2e-3f}, 1.0f), "a 2 mm ray across it");
}

TEST(ShadowBvh, ARayParallelToAFaceIsNotBlocked) {
    const Scene scene = quadScene();
    expectBoth(false, occlusion(scene, {-2.0f, 0.3f, 0.0f}, {4.0f, 0.0f, 0.0f}, 1.0f), "in the quad's plane, across it");
    expectBoth(false, occlusion(scene, {-2.0f, 0.3f, 0.01f}, {4.0f, 0.0f, 0.0f}, 1.0f), "1 cm above it");
    expectBoth(false, occlusion(scene, {-2.0f, -2.0f, 0.0f}, {4.0f, 4.0f, 0.0f}, 1.0f), "in its plane, along the diagonal");
}

TEST(ShadowBvh, AGrazingRayIsBlocked) {
    const Scene scene = quadScene();
    // A thousandth of a radian to the quad's plane, crossing it at x = 0.
    expectBoth(true, occlusion(scene, {-10.0f, 0.1f, -0.01f}, {20.0f, 0.0f, 0.02f}, 1.0f));
    // Down towards it at the same angle, reaching z = 0 only at x = 1.005, 5 mm past its far edge.
    expectBoth(false, occlusion(scene, {-10.0f, 0.1f, 0.011005f}, {20.0f, 0.0f, -0.02f}, 1.0f));
    // From 50 m away at a thousandth of a radian, crossing it at (0, 0.3).
    expectBoth(true, occlusion(scene, {-50.0f, 0.3f, 0.05f}, {100.0f, 0.0f, -0.1f}, 1.0f));
}

TEST(ShadowBvh, ABlendTriangleDoesNotBlock) {
    // Glass alone: no structure at all, nothing blocked.
    const Scene glass = quadScene(AlphaMode::Blend);
    const ShadowBvh bvh = buildShadowBvh(glass);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.triangles.empty());
    expectBoth(false, occlusion(glass, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 1.0f));
    // Glass in front of a wall: the ray through the glass alone passes, the one into the wall stops.
    Scene scene = quadScene(AlphaMode::Blend);
    addQuad(scene, {5, -1, 0}, {2, 0, 0}, {0, 2, 0}, addMaterial(scene, AlphaMode::Opaque));
    EXPECT_EQ(buildShadowBvh(scene).triangles.size(), 2u);
    expectBoth(false, occlusion(scene, {0.3f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 1.0f));
    expectBoth(true, occlusion(scene, {6.0f, 0.2f, -1.0f}, {0.0f, 0.0f, 2.0f}, 1.0f));
}

TEST(ShadowBvh, AMaskTriangleAsksTheHookWhetherItCoversTheHit) {
    Scene scene = quadScene(AlphaMode::Opaque);
    const std::uint32_t leaves = addMaterial(scene, AlphaMode::Mask);
    addQuad(scene, {-1, -1, 1}, {2, 0, 0}, {0, 2, 0}, leaves);  // the MASK quad at z = 1, triangles 2 and 3
    const ShadowBvh bvh = buildShadowBvh(scene);
    const EmbreeOcclusion embree(scene);
    ASSERT_EQ(bvh.maskTriangles, 2u);
    const glm::vec3 origin(0.3f, 0.2f, 2.0f), direction(0.0f, 0.0f, -1.5f);  // down to z = 0.5: the MASK quad only
    for (bool isCovered : {false, true}) {
        for (int oracle = 0; oracle < 2; ++oracle) {
            SCOPED_TRACE(std::string(oracle ? "Embree" : "our BVH") + (isCovered ? ", covered" : ", a hole"));
            int calls = 0;
            const ShadowCoverage hook = [&](std::uint32_t material, std::uint32_t triangle, float u, float v) {
                ++calls;
                EXPECT_EQ(material, leaves);
                EXPECT_TRUE(triangle == 2u || triangle == 3u) << triangle;
                // (u, v) weigh the scene triangle's corners 1 and 2: they give back the hit point.
                const glm::vec3 a = scene.vertices[scene.indices[3 * triangle]].position;
                const glm::vec3 b = scene.vertices[scene.indices[3 * triangle + 1]].position;
                const glm::vec3 c = scene.vertices[scene.indices[3 * triangle + 2]].position;
                const glm::vec3 hit = (1.0f - u - v) * a + u * b + v * c;
                EXPECT_NEAR(hit.x, 0.3f, 1e-5f);
                EXPECT_NEAR(hit.y, 0.2f, 1e-5f);
                EXPECT_NEAR(hit.z, 1.0f, 1e-5f);
                return isCovered;
            };
            const bool blocked = oracle ? embree.occluded(origin, direction, 1.0f, hook) : occludedByBvh(bvh, origin, direction, 1.0f, hook);
            EXPECT_EQ(blocked, isCovered);
            EXPECT_EQ(calls, 1);
        }
    }
    // No hook: MASK blocks as OPAQUE does.
    EXPECT_TRUE(occludedByBvh(bvh, origin, direction, 1.0f));
    EXPECT_TRUE(embree.occluded(origin, direction, 1.0f));
    // Through a hole in the MASK quad on to the opaque one behind it: blocked there; the hook is
    // never asked about the opaque quad.
    const ShadowCoverage holes = [&](std::uint32_t, std::uint32_t, float, float) { return false; };
    EXPECT_TRUE(occludedByBvh(bvh, origin, {0.0f, 0.0f, -4.0f}, 1.0f, holes));
    EXPECT_TRUE(embree.occluded(origin, {0.0f, 0.0f, -4.0f}, 1.0f, holes));
}

// The alpha rule's CPU reading (shadow_alpha.h), through both oracles: a MASK quad whose texture
// is clear on its left half (u < 0.5) blocks rays through its right half only; the texture
// transform, the factor and the second UV set each move the answer as glTF says they should.
TEST(ShadowAlpha, AMaskQuadBlocksWhereItsTextureIsSolid) {
    Scene scene;
    scene.name = "mask quad";
    const std::uint32_t leaves = addMaterial(scene, AlphaMode::Mask);
    addQuad(scene, {-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, leaves);
    const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) scene.vertices[i].uv = uvs[i];
    Image half;
    half.width = 8;
    half.height = 4;  // not square: resampled into the masks' square layer
    half.rgba8.assign(8 * 4 * 4, 255);
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) half.rgba8[(static_cast<std::size_t>(j) * 8 + i) * 4 + 3] = 0;
    scene.images.push_back(half);
    Material& m = scene.materials[leaves];
    m.baseColorTexture.image = 0;
    m.alphaCutoff = 0.5f;

    const auto blocked = [&](float x) {
        ShadowBvh bvh = buildShadowBvh(scene);
        const ShadowAlphaMasks masks = buildShadowAlphaMasks(scene, bvh);
        EXPECT_EQ(masks.layerCount, m.baseColorTexture.present() ? 1 : 0);
        EXPECT_EQ(masks.uvs.size(), 4u);  // two records of two vec4s
        const ShadowCoverage covered = shadowAlphaCoverage(scene, masks);
        const glm::vec3 origin(x, 0.1f, 1.0f), direction(0.0f, 0.0f, -2.0f);
        const bool ours = occludedByBvh(bvh, origin, direction, 1.0f, covered);
        EXPECT_EQ(ours, EmbreeOcclusion(scene).occluded(origin, direction, 1.0f, covered)) << "at x = " << x;
        return ours;
    };
    EXPECT_FALSE(blocked(-0.6f));
    EXPECT_TRUE(blocked(0.6f));
    m.baseColorTexture.transform.offset = {0.5f, 0.0f};  // repeat wrap: the halves swap
    EXPECT_TRUE(blocked(-0.6f));
    EXPECT_FALSE(blocked(0.6f));
    m.baseColorTexture.transform.offset = {0.0f, 0.0f};
    m.baseColorFactor.a = 0.4f;  // below the cut-off everywhere
    EXPECT_FALSE(blocked(0.6f));
    m.baseColorFactor.a = 1.0f;
    scene.uv1.assign(scene.vertices.size(), glm::vec2(0.1f, 0.5f));  // TEXCOORD_1 all in the clear half
    m.baseColorTexture.texCoord = 1;
    EXPECT_FALSE(blocked(0.6f));
    m.baseColorTexture.image = -1;  // no texture: the factor alone, solid
    EXPECT_TRUE(blocked(-0.6f));
}

TEST(ShadowBvh, OneTriangleIsOneNodeWithTheLeafOnTheLeft) {
    Scene scene;
    scene.name = "triangle";
    addMaterial(scene, AlphaMode::Opaque);
    scene.vertices = {Vertex{{0, 0, 0}}, Vertex{{1, 0, 0}}, Vertex{{0, 1, 0}}};
    scene.indices = {0, 1, 2};
    scene.draws = {DrawRange{0, 3, 0}};
    computeBounds(scene);
    for (std::uint32_t width : kWidths) {
        SCOPED_TRACE("width " + std::to_string(width));
        const ShadowBvh bvh = buildShadowBvh(scene, width);
        ASSERT_EQ(bvh.nodeCount(), 1u);
        ASSERT_EQ(bvh.triangles.size(), 1u);
        EXPECT_EQ(bvh.depth, 1u);
        const ShadowBvhChild first = shadowNodeChild(bvh.node(0), width, 0), second = shadowNodeChild(bvh.node(0), width, 1);
        EXPECT_EQ(first.reference, shadowLeafReference(0, 1));
        EXPECT_EQ(first.lo, glm::vec3(0.0f));
        EXPECT_EQ(first.hi, glm::vec3(1.0f, 1.0f, 0.0f));
        // Binary: the right child is the same leaf behind an empty box; wide: an empty slot.
        EXPECT_EQ(second.present, width == 2);
        EXPECT_EQ(second.reference, width == 2 ? first.reference : 0u);
        EXPECT_TRUE(emptyBox(second.lo, second.hi));
        expectLayoutInvariants(scene, bvh);
        EXPECT_TRUE(occludedByBvh(bvh, {0.2f, 0.2f, 1.0f}, {0.0f, 0.0f, -2.0f}, 1.0f));
        EXPECT_FALSE(occludedByBvh(bvh, {0.8f, 0.8f, 1.0f}, {0.0f, 0.0f, -2.0f}, 1.0f));
    }
    expectBoth(true, occlusion(scene, {0.2f, 0.2f, 1.0f}, {0.0f, 0.0f, -2.0f}, 1.0f));
    expectBoth(false, occlusion(scene, {0.8f, 0.8f, 1.0f}, {0.0f, 0.0f, -2.0f}, 1.0f));
}

TEST(ShadowBvh, NothingToCastIsAnEmptyStructure) {
    Scene scene;
    scene.name = "empty";
    const ShadowBvh bvh = buildShadowBvh(scene);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.triangles.empty());
    EXPECT_EQ(bvh.depth, 0u);
    EXPECT_TRUE(bvh.bounds.empty());
    EXPECT_FALSE(occludedByBvh(bvh, {0, 0, 0}, {1, 0, 0}, 1.0f));
    EXPECT_FALSE(EmbreeOcclusion(scene).occluded({0, 0, 0}, {1, 0, 0}, 1.0f));
}

TEST(ShadowBvh, ANonFiniteCornerIsOneLineNamingTheScene) {
    Scene scene = quadScene();
    scene.vertices[2].position.x = std::numeric_limits<float>::quiet_NaN();
    try {
        buildShadowBvh(scene);
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("scene quad: triangle 0 has a corner that is not finite"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(ShadowBvh, TheSlabTestTakesZeroDirectionComponentsWithoutNaN) {
    // Directions with zero components (and a negative zero): finite reciprocals, no NaN.
    const glm::vec3 inverse = shadowRayInverse({0.0f, -0.0f, 1.0f});
    EXPECT_TRUE(std::isfinite(inverse.x) && std::isfinite(inverse.y) && std::isfinite(inverse.z));
    EXPECT_TRUE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, -0.5f}, inverse, 1.0f)) << "through the box";
    // In the plane of a face where the direction is 0: met on the lo face, and on the hi face only
    // at t = 0 (shadow_bvh_traversal.h says why that loses nothing but a free edge in that plane).
    EXPECT_TRUE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {0.0f, 0.0f, -0.5f}, inverse, 1.0f)) << "on the lo faces";
    EXPECT_FALSE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {1.0f, 0.5f, -0.5f}, inverse, 1.0f)) << "on the hi face";
    EXPECT_TRUE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {1.0f, 0.5f, 0.5f}, inverse, 1.0f)) << "starting on the hi face";
    EXPECT_FALSE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {1.5f, 0.5f, -0.5f}, inverse, 1.0f)) << "beside the box, parallel to it";
    EXPECT_FALSE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, -2.0f}, inverse, 1.0f)) << "ends before it";
    EXPECT_FALSE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, 1.5f}, inverse, 1.0f)) << "starts past it";
    EXPECT_TRUE(shadowBoxHit({0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, -1.0f}, inverse, 1.0f)) << "ends on it";
    // A flat box (a triangle in the plane z = 0) that the ray crosses.
    EXPECT_TRUE(shadowBoxHit({0, 0, 0}, {1, 1, 0}, {0.5f, 0.5f, -0.5f}, inverse, 1.0f));
    // The one-leaf tree's empty box (+inf, -inf): met by every ray, see shadow_bvh.h.
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(shadowBoxHit(glm::vec3(inf), glm::vec3(-inf), {0.5f, 0.5f, -0.5f}, shadowRayInverse({1.0f, 2.0f, 3.0f}), 1.0f));
}

TEST(ShadowBvh, RayOriginsMoveOffTheSurfaceAlongTheNormal) {
    // 256 ulps along +y at y = 4 (an ulp of 4 is 2^-21), 1/65536 of the normal near 0.
    const glm::vec3 moved = shadowRayOrigin({0.0f, 4.0f, -4.0f}, {0.0f, 1.0f, 0.0f});
    EXPECT_EQ(moved.x, 0.0f);
    EXPECT_EQ(moved.y, 4.0f + 256.0f * std::ldexp(1.0f, -21));
    EXPECT_EQ(moved.z, -4.0f);
    const glm::vec3 down = shadowRayOrigin({0.0f, -4.0f, 0.01f}, {0.0f, -1.0f, 1.0f});
    EXPECT_EQ(down.y, -4.0f - 256.0f * std::ldexp(1.0f, -21)) << "along -y at a negative coordinate: away from 0";
    EXPECT_EQ(down.z, 0.01f + 1.0f / 65536.0f);
}

// --- The layout on the built-in scenes ---------------------------------------------------------------

Scene builtin(const std::string& name, float detail = 1.0f) {
    std::vector<std::string> warnings;
    return loadScene(SceneRequest{name, detail}, warnings);
}

// A ray that is not finite (a NaN from a helper invocation's extrapolated surface) is not traced:
// NaN operands dropped by min and max would meet every box and walk the whole tree.
TEST(ShadowBvh, ARayThatIsNotFiniteIsNotTraced) {
    const Scene scene = builtin("boxes");
    const ShadowBvh bvh = buildShadowBvh(scene);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (const auto& [origin, direction] : {std::pair{glm::vec3(nan, 0.5f, 0.5f), glm::vec3(0, 1, 0)},
                                            std::pair{glm::vec3(0.5f), glm::vec3(0, nan, 0)},
                                            std::pair{glm::vec3(0.5f), glm::vec3(inf, 1, 0)}}) {
        ShadowTraversalCounts c;
        EXPECT_FALSE(occludedByBvh(bvh, origin, direction, 1.0f, {}, &c));
        EXPECT_EQ(c.nodes, 0u);
    }
}

TEST(ShadowBvh, LayoutHoldsEveryCastingTriangleOnceInsideItsBoxes) {
    for (const auto& [name, detail] : {std::pair<std::string, float>{"boxes", 1.0f}, {"atrium", 0.25f}, {"plane", 1.0f}}) {
        const Scene scene = builtin(name, detail);
        for (std::uint32_t width : kWidths) {
            SCOPED_TRACE(name + ", width " + std::to_string(width));
            const ShadowBvh bvh = buildShadowBvh(scene, width);
            expectLayoutInvariants(scene, bvh);
            std::printf("%s, width %u: %zu of %zu triangles cast (%zu alpha-tested), %zu nodes, %zu leaves, depth %u, stack %u, %zu bytes, "
                        "built in %.3f ms\n",
                        name.c_str(), width, bvh.triangles.size(), scene.triangleCount(), bvh.maskTriangles, bvh.nodeCount(), bvh.leaves,
                        bvh.depth, bvh.stackNeed, bvh.bytes(), 1e3 * bvh.buildSeconds);
        }
    }
}

TEST(ShadowBvh, AWidthTheLayoutDoesNotHaveIsOneLine) {
    try {
        buildShadowBvh(quadScene(), 3);
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "--shadow-bvh-width 3: the shadow BVH has 2, 4 or 8 children a node");
    }
}

TEST(ShadowBvh, TheAtriumsGlassCastsNoShadowAndItsFoliageIsAlphaTested) {
    const Scene scene = builtin("atrium", 0.25f);
    const ShadowBvh bvh = buildShadowBvh(scene);
    std::size_t blended = 0;
    for (const DrawRange& d : scene.draws)
        if (scene.materials[d.material].blended()) blended += d.indexCount / 3;
    EXPECT_GT(blended, 0u) << "the atrium has glass";
    EXPECT_GT(bvh.maskTriangles, 0u) << "the atrium has foliage";
    EXPECT_EQ(bvh.triangles.size() + blended, scene.triangleCount());
}

// --- Random rays against Embree ------------------------------------------------------------------------

// The distance from p to the segment ab, in double.
double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

// Why two answers may differ: where the ray (in double) crosses a casting triangle's plane, it
// passes within `epsilon` of one of the triangle's edges; or the light lies within `epsilon` of a
// casting triangle. (Not the origin: it lies off its own surface by the GPU's offset, which near
// 0 is smaller than any useful epsilon.)
bool nearAnEdge(const ShadowBvh& bvh, glm::vec3 origin, glm::vec3 direction, double epsilon) {
    const glm::dvec3 o(origin), d(direction);
    for (const GpuBvhTriangle& t : bvh.triangles) {
        const glm::dvec3 a(xyz(t.v0)), b(xyz(t.v1)), c(xyz(t.v2));
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double area2 = glm::length(n);
        if (area2 == 0.0) continue;
        const glm::dvec3 unit = n / area2;
        const double h0 = glm::dot(o - a, unit), h1 = glm::dot(o + d - a, unit);  // signed heights of the ends
        const auto edgeDistance = [&](const glm::dvec3& q) {
            return std::min({segmentDistance(q, a, b), segmentDistance(q, b, c), segmentDistance(q, c, a)});
        };
        if (std::fabs(h1) <= epsilon) {
            const glm::dvec3 q = o + d - h1 * unit;  // the light in the plane: inside, or near an edge?
            const bool inside = glm::dot(glm::cross(b - a, q - a), unit) >= 0 && glm::dot(glm::cross(c - b, q - b), unit) >= 0 &&
                                glm::dot(glm::cross(a - c, q - c), unit) >= 0;
            if (inside || edgeDistance(q) < epsilon) return true;
        }
        if ((h0 > 0) == (h1 > 0) || h0 == h1) continue;  // the segment does not cross the plane
        if (edgeDistance(o + (h0 / (h0 - h1)) * d) < epsilon) return true;
    }
    return false;
}

// How near an edge a ray may pass and still get different answers, against the scene's diagonal.
constexpr double kEdgeEpsilon = 1e-6;

struct Agreement {
    std::size_t rays = 0, blocked = 0, disagreements = 0, unexplained = 0;  // unexplained: not near an edge, or past 200
};

struct ShadowRay {
    glm::vec3 origin, direction;
};

// `count` rays from points spread over the scene's surface (by area: renderer/scene/surface_samples.h),
// moved off it toward the light as the GPU moves them, to lights uniform in the scene's bounds,
// or, with `reach` > 0, at most `reach` away in a uniform direction off the surface (the short
// rays of lights whose radius is `reach`).
std::vector<ShadowRay> randomShadowRays(const Scene& scene, std::size_t count, std::uint32_t seed, float reach = 0.0f) {
    const SurfaceSamples samples(scene);
    const glm::vec3 lo = scene.bounds.min - 0.05f * scene.bounds.size(), size = 1.1f * scene.bounds.size();
    std::vector<ShadowRay> rays;
    for (std::uint32_t i = 0; i < count; ++i) {
        const auto r = [&](std::uint32_t k) { return hashToUnitFloat(pcgHash(seed) ^ (8u * i + k)); };
        const SurfaceSamples::Point s = samples.at(r(0), r(1), r(2));
        const glm::vec3 p = s.position(scene);
        const glm::vec3 c0 = scene.vertices[s.corners[0]].position, c1 = scene.vertices[s.corners[1]].position,
                        c2 = scene.vertices[s.corners[2]].position;
        glm::vec3 n = glm::cross(c1 - c0, c2 - c0);
        if (glm::length(n) == 0.0f) continue;
        n = glm::normalize(n);
        glm::vec3 light = lo + size * glm::vec3(r(3), r(4), r(5));
        if (reach > 0.0f) {
            const glm::vec3 d(r(3) - 0.5f, r(4) - 0.5f, r(5) - 0.5f);
            if (glm::length(d) == 0.0f) continue;
            light = p + reach * r(6) * glm::normalize(d);
        }
        if (glm::dot(n, light - p) < 0.0f) n = -n;
        const glm::vec3 origin = shadowRayOrigin(p, n);
        rays.push_back({origin, light - origin});
    }
    return rays;
}

Agreement compareWithEmbree(const Scene& scene, const ShadowBvh& bvh, const EmbreeOcclusion& embree, std::size_t count,
                            const ShadowCoverage& covered, std::uint32_t seed) {
    const double epsilon = kEdgeEpsilon * glm::length(glm::dvec3(scene.bounds.size()));
    Agreement a;
    const std::vector<ShadowRay> rays = randomShadowRays(scene, count, seed);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const auto [origin, direction] = rays[i];
        const bool ours = occludedByBvh(bvh, origin, direction, 1.0f, covered);
        const bool theirs = embree.occluded(origin, direction, 1.0f, covered);
        ++a.rays;
        a.blocked += theirs ? 1 : 0;
        if (ours == theirs) continue;
        ++a.disagreements;
        // Classified one by one against every triangle: past a few hundred the answer is plain.
        if (a.disagreements > 200 || !nearAnEdge(bvh, origin, direction, epsilon)) {
            ++a.unexplained;
            if (a.unexplained <= 5)
                std::printf("  disagreement away from any edge: ray %zu from (%.9g, %.9g, %.9g) along (%.9g, %.9g, %.9g): ours %d, Embree's %d\n", i,
                            origin.x, origin.y, origin.z, direction.x, direction.y, direction.z, ours, theirs);
        }
    }
    return a;
}

void expectAgreementWithEmbree(const std::string& name, float detail, std::uint32_t width) {
    const Scene scene = builtin(name, detail);
    const ShadowBvh bvh = buildShadowBvh(scene, width);
    const EmbreeOcclusion embree(scene);
    ASSERT_EQ(embree.triangles(), bvh.triangles.size());
    constexpr std::size_t kRays = 100000;
    const ShadowCoverage holes = [](std::uint32_t, std::uint32_t, float, float) { return false; };
    for (int pass = 0; pass < (bvh.maskTriangles > 0 ? 2 : 1); ++pass) {
        const char* what = pass == 0 ? "alpha-tested triangles block" : "alpha-tested triangles are holes";
        SCOPED_TRACE(what);
        const Agreement a = compareWithEmbree(scene, bvh, embree, kRays, pass == 0 ? ShadowCoverage{} : holes, 62u + pass);
        std::printf("%s, width %u (%s): %zu rays, %.1f %% blocked; %zu disagree with Embree (%zu away from any edge, epsilon %.2g)\n", name.c_str(),
                    width, what, a.rays, 100.0 * double(a.blocked) / double(a.rays), a.disagreements, a.unexplained,
                    kEdgeEpsilon * glm::length(glm::dvec3(scene.bounds.size())));
        EXPECT_GT(a.rays, kRays * 99 / 100);
        // Both answers occur often: the comparison means something.
        EXPECT_GT(a.blocked, a.rays / 20);
        EXPECT_LT(a.blocked, a.rays - a.rays / 20);
        EXPECT_LT(double(a.disagreements), 1e-4 * double(a.rays));
        EXPECT_EQ(a.unexplained, 0u);
    }
}

class ShadowBvhWidth : public ::testing::TestWithParam<std::uint32_t> {};

TEST_P(ShadowBvhWidth, AgreesWithEmbreeOnRandomRaysInBoxes) { expectAgreementWithEmbree("boxes", 1.0f, GetParam()); }
TEST_P(ShadowBvhWidth, AgreesWithEmbreeOnRandomRaysInTheAtrium) { expectAgreementWithEmbree("atrium", 0.25f, GetParam()); }

// What the node layout buys, in the work the traversal does (the GPU's walk, operation for
// operation): short rays (lights within 2 m, as `overlap:32` makes them) over the atrium, the
// same rays at every width. Wider nodes pop fewer nodes a ray, each testing more boxes; the
// H100 record says what that is worth in time (docs/bench/nvidia-h100/shadow-rays/).
TEST(ShadowBvh, WiderNodesPopFewerNodesARay) {
    const Scene scene = builtin("atrium", 0.25f);
    const std::vector<ShadowRay> rays = randomShadowRays(scene, 20000, 11u, 2.0f);
    double nodesARay[3] = {};
    for (int w = 0; w < 3; ++w) {
        const ShadowBvh bvh = buildShadowBvh(scene, kWidths[w]);
        ShadowTraversalCounts c;
        std::size_t blocked = 0;
        for (const ShadowRay& r : rays) blocked += occludedByBvh(bvh, r.origin, r.direction, 1.0f, {}, &c) ? 1 : 0;
        const double n = double(c.rays);
        nodesARay[w] = double(c.nodes) / n;
        std::printf("atrium, rays up to 2 m, width %u: %.1f nodes, %.1f boxes, %.1f pushes, %.1f triangles a ray (%.1f %% blocked); "
                    "%.0f node bytes read a ray\n",
                    kWidths[w], nodesARay[w], double(c.boxes) / n, double(c.pushes) / n, double(c.triangles) / n, 100.0 * double(blocked) / n,
                    nodesARay[w] * 16.0 * shadowNodeVec4s(kWidths[w]));
    }
    EXPECT_LT(nodesARay[1], 0.7 * nodesARay[0]);
    EXPECT_LT(nodesARay[2], nodesARay[1]);
}

INSTANTIATE_TEST_SUITE_P(ShadowBvh, ShadowBvhWidth, ::testing::ValuesIn(kWidths),
                         [](const ::testing::TestParamInfo<std::uint32_t>& info) { return "Width" + std::to_string(info.param); });

}  // namespace
}  // namespace ml
