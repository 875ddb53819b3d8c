// Generated lights in Morton order of their places (renderer/lights/spatial_order.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "renderer/lights/spatial_order.h"

namespace ml {
namespace {

Bounds unitCube() {
    Bounds b;
    b.min = glm::vec3(0.0f);
    b.max = glm::vec3(1.0f);
    return b;
}

Light pointAt(glm::vec3 position, float red) {
    Light l;
    l.position = position;
    l.color = glm::vec3(red, 0.0f, 0.0f);
    return l;
}

std::vector<std::array<float, 4>> sortedFields(const std::vector<Light>& lights) {
    std::vector<std::array<float, 4>> f;
    for (const Light& l : lights) f.push_back({l.position.x, l.position.y, l.position.z, l.color.r});
    std::sort(f.begin(), f.end());
    return f;
}

// The eight octants' centres in Morton order: x is the lowest bit, then y, then z.
TEST(SpatialOrder, OctantsComeInMortonOrder) {
    std::vector<Light> lights;
    for (int i = 7; i >= 0; --i)
        lights.push_back(pointAt({(i & 1) ? 0.75f : 0.25f, (i & 2) ? 0.75f : 0.25f, (i & 4) ? 0.75f : 0.25f}, float(i)));
    sortLightsSpatially(lights, unitCube());
    for (int i = 0; i < 8; ++i) EXPECT_EQ(lights[std::size_t(i)].color.r, float(i)) << "octant " << i;
}

// A permutation: the same lights, each whole; neighbours in space end up near in the buffer,
// and lights in one cell keep the order they came in.
TEST(SpatialOrder, PermutesWholeLightsKeepingTiesInOrder) {
    std::vector<Light> lights;
    for (int i = 0; i < 1000; ++i) {
        const float t = float((i * 7919) % 1000) / 1000.0f;
        lights.push_back(pointAt({t, 1.0f - t, 0.5f * t}, float(i)));
    }
    lights.push_back(pointAt({0.5f, 0.5f, 0.5f}, 2000.0f));
    lights.push_back(pointAt({0.5f, 0.5f, 0.5f}, 1000.0f));  // same cell as the one before
    lights.push_back(pointAt({-5.0f, 9.0f, 0.2f}, 3000.0f));  // outside: clamped to the faces
    const auto before = sortedFields(lights);
    sortLightsSpatially(lights, unitCube());
    EXPECT_EQ(sortedFields(lights), before);
    const auto first = std::find_if(lights.begin(), lights.end(), [](const Light& l) { return l.color.r == 2000.0f; });
    const auto second = std::find_if(lights.begin(), lights.end(), [](const Light& l) { return l.color.r == 1000.0f; });
    EXPECT_LT(first, second) << "ties keep their order";
    float meanStep = 0.0f;
    for (std::size_t i = 1; i < lights.size(); ++i) meanStep += glm::length(lights[i].position - lights[i - 1].position);
    meanStep /= float(lights.size() - 1);
    EXPECT_LT(meanStep, 0.05f) << "neighbours in the buffer are neighbours in space (a random order averages about 0.6)";
}

// Nothing to order: an empty volume or a single light leaves the set as it is.
TEST(SpatialOrder, EmptyVolumeLeavesTheOrder) {
    std::vector<Light> lights = {pointAt({0.9f, 0.9f, 0.9f}, 0.0f), pointAt({0.1f, 0.1f, 0.1f}, 1.0f)};
    sortLightsSpatially(lights, Bounds{});
    EXPECT_EQ(lights[0].color.r, 0.0f);
    sortLightsSpatially(lights, unitCube());
    EXPECT_EQ(lights[0].color.r, 1.0f);
}

}  // namespace
}  // namespace ml
