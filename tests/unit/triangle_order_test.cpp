// --triangle-order (renderer/scene/triangle_order.h): reordering keeps every draw range's triangles,
// each with its winding, and only reorders them within the range.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include <meshoptimizer.h>

#include "renderer/scene/triangle_order.h"
#include "scenes/scene_library.h"

namespace ml {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// The range's triangles, each rotated to start at its smallest index (the winding kept), sorted.
std::vector<Triangle> canonicalTriangles(const std::vector<std::uint32_t>& indices, const DrawRange& d) {
    std::vector<Triangle> out;
    for (std::uint32_t i = d.firstIndex; i < d.firstIndex + d.indexCount; i += 3) {
        Triangle t{indices[i], indices[i + 1], indices[i + 2]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

Scene atrium() {
    std::vector<std::string> warnings;
    return loadScene(SceneRequest{"atrium", 0.25f}, warnings);
}

TEST(TriangleOrder, EveryOrderKeepsEachRangesTrianglesAndWinding) {
    const Scene scene = atrium();
    for (TriangleOrder order : {TriangleOrder::AsLoaded, TriangleOrder::VertexCache, TriangleOrder::Overdraw}) {
        SCOPED_TRACE(triangleOrderName(order));
        const std::vector<std::uint32_t> indices = orderTriangles(scene, order);
        ASSERT_EQ(indices.size(), scene.indices.size());
        for (const DrawRange& d : scene.draws)
            EXPECT_EQ(canonicalTriangles(indices, d), canonicalTriangles(scene.indices, d)) << "range at " << d.firstIndex;
    }
    EXPECT_EQ(orderTriangles(scene, TriangleOrder::AsLoaded), scene.indices);
}

TEST(TriangleOrder, VertexCacheOrderTransformsFewerVertices) {
    // The full-detail atrium's largest range, its columns and arches: 1.04 vertex shader runs a
    // triangle as built, 0.70 reordered (on a 32-entry FIFO cache model).
    std::vector<std::string> warnings;
    const Scene scene = loadScene(SceneRequest{"atrium", 1.0f}, warnings);
    const DrawRange largest = *std::max_element(scene.draws.begin(), scene.draws.end(),
                                                [](const DrawRange& a, const DrawRange& b) { return a.indexCount < b.indexCount; });
    const auto acmr = [&](const std::vector<std::uint32_t>& indices) {
        return meshopt_analyzeVertexCache(indices.data() + largest.firstIndex, largest.indexCount, scene.vertices.size(), 32, 0, 0).acmr;
    };
    EXPECT_LT(acmr(orderTriangles(scene, TriangleOrder::VertexCache)), 0.8f * acmr(scene.indices));
}

TEST(TriangleOrder, NamesRoundTripAndBadOnesAreRefused) {
    for (TriangleOrder order : {TriangleOrder::AsLoaded, TriangleOrder::VertexCache, TriangleOrder::Overdraw})
        EXPECT_EQ(parseTriangleOrder(triangleOrderName(order)), order);
    EXPECT_THROW(parseTriangleOrder("front-to-back"), std::invalid_argument);
}

}  // namespace
}  // namespace ml
