// Camera maths and the --camera parser.
#include <gtest/gtest.h>

#include "renderer/camera/camera.h"

namespace ml {
namespace {

TEST(Camera, TargetProjectsToTheCentre) {
    Camera c;
    c.eye = {3, 4, 5};
    c.target = {-1, 0, 2};
    const glm::vec4 clip = c.projection(16.0f / 9.0f) * c.view() * glm::vec4(c.target, 1.0f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f);
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-5f);
}

TEST(Camera, NearAndFarMapToTheDepthRange) {
    Camera c;
    c.eye = {0, 0, 0};
    c.target = {0, 0, -1};
    c.nearPlane = 0.5f;
    c.farPlane = 40.0f;
    const glm::mat4 vp = c.projection(1.0f) * c.view();
    const glm::vec4 n = vp * glm::vec4(0, 0, -0.5f, 1), f = vp * glm::vec4(0, 0, -40.0f, 1);
    EXPECT_NEAR(n.z / n.w, 1.0f, 1e-5f);  // reversed depth: 1 at the near plane
    EXPECT_NEAR(f.z / f.w, 0.0f, 1e-5f);
}

TEST(Camera, LookingStraightDownIsNotDegenerate) {
    Camera c;
    c.eye = {0, 10, 0};
    c.target = {0, 0, 0};
    const glm::mat4 v = c.view();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(v[i][j]));
}

TEST(Camera, FitClipPlanesEnclosesTheBounds) {
    Bounds b;
    b.extend({-10, 0, -10});
    b.extend({10, 5, 10});
    Camera c;
    c.eye = {0, 2, 0};  // inside the bounds
    fitClipPlanes(c, b);
    EXPECT_GT(c.farPlane, glm::length(glm::vec3(10, 3, 10)));
    EXPECT_GT(c.nearPlane, 0.0f);
    EXPECT_LT(c.nearPlane, 0.5f);
}

TEST(Camera, ParsesSevenNumbers) {
    const Camera c = parseCamera("1,2,3,4,5,6,45");
    EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.target, glm::vec3(4, 5, 6));
    EXPECT_EQ(c.fovyDegrees, 45.0f);
}

TEST(Camera, RejectsBadText) {
    for (const char* bad : {"1,2,3", "1,2,3,4,5,6,7,8", "a,2,3,4,5,6,45", "1,2,3,1,2,3,45", "1,2,3,4,5,6,0", "1,2,3,4,5,6,nan"})
        EXPECT_THROW(parseCamera(bad), std::invalid_argument) << bad;
}

TEST(Camera, SceneCameraNamesAreCheckedAgainstTheScene) {
    EXPECT_TRUE(namesSceneCamera("gltf:0"));
    EXPECT_FALSE(namesSceneCamera("1,2,3,4,5,6,45"));
    EXPECT_EQ(sceneCameraIndex("gltf:1", 2), 1u);
    const auto message = [](const std::string& text, std::size_t count) {
        try {
            (void)sceneCameraIndex(text, count);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("gltf:5", 2), "--camera gltf:5: the scene has 2 cameras (gltf:0..gltf:1)");
    EXPECT_EQ(message("gltf:0", 0), "--camera gltf:0: the scene has no cameras");
    for (const char* bad : {"gltf:", "gltf:-1", "gltf:x", "gltf:1.5", "gltf:99999999999999999999"})
        EXPECT_NE(message(bad, 3).find("expected gltf:N"), std::string::npos) << bad;
}

TEST(Camera, SceneCameraKeepsItsUpAndItsClipPlanes) {
    SceneCamera file;
    file.pose = CameraPose{glm::vec3(1, 2, 3), glm::vec3(1, 2, 2), 40.0f};
    file.up = {-1, 0, 0};
    file.nearPlane = 0.25f;
    file.farPlane = 50.0f;
    Bounds b;
    b.extend({-1, -1, -1});
    b.extend({1, 1, 1});
    Camera c = cameraFromSceneCamera(file);
    fitClipPlanes(c, b, file);
    EXPECT_EQ(c.eye, file.pose.eye);
    EXPECT_EQ(c.target, file.pose.target);
    EXPECT_EQ(c.up, file.up);
    EXPECT_EQ(c.fovyDegrees, 40.0f);
    EXPECT_EQ(c.nearPlane, 0.25f);
    EXPECT_EQ(c.farPlane, 50.0f);

    // No zfar in the file (infinite): the far plane is fitted to the bounds.
    file.farPlane = 0.0f;
    fitClipPlanes(c, b, file);
    EXPECT_EQ(c.nearPlane, 0.25f);
    EXPECT_GT(c.farPlane, glm::length(glm::vec3(1, 2, 3)));
}

}  // namespace
}  // namespace ml
