// The scene model's own helpers: bounds and the framing view derived from them.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/scene.h"
#include "scenes/scene_library.h"

namespace ml {
namespace {

// The bounds are of what the triangles draw (issue 61): a vertex no index uses is not part of the
// scene, and once widened the framing, the clip planes and the light volume.
TEST(SceneModel, BoundsCoverEveryDrawnVertexAndNoOther) {
    Scene s;
    s.vertices = {{{-1, 2, 3}}, {{100, 100, 100}}, {{4, -5, 6}}, {{0, 0, -7}}};
    s.indices = {0, 2, 3};
    computeBounds(s);
    EXPECT_EQ(s.bounds.min, glm::vec3(-1, -5, -7));
    EXPECT_EQ(s.bounds.max, glm::vec3(4, 2, 6));
    EXPECT_FALSE(s.bounds.empty());
}

TEST(SceneModel, EmptyBoundsAreEmpty) {
    Scene s;
    computeBounds(s);
    EXPECT_TRUE(s.bounds.empty());
}

TEST(SceneModel, FramingViewSeesTheWholeBoundingSphere) {
    Bounds b;
    b.extend({-10, 0, -5});
    b.extend({10, 4, 5});
    const CameraPose pose = framingView(b);
    const float radius = 0.5f * glm::length(b.size());
    const float distance = glm::length(pose.eye - b.center());
    // The sphere's angular radius fits half the vertical field of view.
    EXPECT_LE(std::asin(radius / distance), glm::radians(pose.fovyDegrees) * 0.5f + 1e-4f);
    EXPECT_EQ(pose.target, b.center());
}

TEST(SceneLibrary, UnknownNameIsAOneLineError) {
    std::vector<std::string> warnings;
    try {
        loadScene(SceneRequest{"colosseum"}, warnings);
        FAIL() << "expected SceneError";
    } catch (const SceneError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("colosseum"), std::string::npos);
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
}

}  // namespace
}  // namespace ml
