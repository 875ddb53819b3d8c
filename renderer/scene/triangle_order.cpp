#include "renderer/scene/triangle_order.h"

#include <stdexcept>

#include <meshoptimizer.h>

namespace ml {

TriangleOrder parseTriangleOrder(const std::string& text) {
    if (text == "as-loaded") return TriangleOrder::AsLoaded;
    if (text == "vertex-cache") return TriangleOrder::VertexCache;
    if (text == "overdraw") return TriangleOrder::Overdraw;
    throw std::invalid_argument("--triangle-order '" + text + "': expected as-loaded, vertex-cache or overdraw");
}

const char* triangleOrderName(TriangleOrder order) {
    switch (order) {
    case TriangleOrder::AsLoaded: return "as-loaded";
    case TriangleOrder::VertexCache: return "vertex-cache";
    case TriangleOrder::Overdraw: return "overdraw";
    }
    return "?";
}

std::vector<std::uint32_t> orderTriangles(const Scene& scene, TriangleOrder order) {
    std::vector<std::uint32_t> indices = scene.indices;
    if (order == TriangleOrder::AsLoaded || scene.vertices.empty()) return indices;
    std::vector<std::uint32_t> scratch;
    for (const DrawRange& d : scene.draws) {
        if (d.indexCount < 3 || std::size_t(d.firstIndex) + d.indexCount > indices.size()) continue;
        std::uint32_t* range = indices.data() + d.firstIndex;
        scratch.assign(range, range + d.indexCount);
        meshopt_optimizeVertexCache(range, scratch.data(), d.indexCount, scene.vertices.size());
        if (order == TriangleOrder::Overdraw) {
            scratch.assign(range, range + d.indexCount);
            meshopt_optimizeOverdraw(range, scratch.data(), d.indexCount, &scene.vertices[0].position.x, scene.vertices.size(),
                                     sizeof(Vertex), 1.05f);
        }
    }
    return indices;
}

}  // namespace ml
