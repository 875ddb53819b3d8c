// The view's fly and orbit camera: frame-rate independence, mode switches, reset.
#include <gtest/gtest.h>

#include <glm/gtc/epsilon.hpp>

#include "renderer/camera/camera_controller.h"

namespace ml {
namespace {

Camera startCamera() {
    Camera c;
    c.eye = {0.0f, 2.0f, 10.0f};
    c.target = {0.0f, 2.0f, 0.0f};
    c.fovyDegrees = 50.0f;
    return c;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(ViewCameraController, UntouchedItIsExactlyTheStartCamera) {
    CameraController c(startCamera(), 20.0f);
    c.update(CameraInput{}, 0.016f);
    EXPECT_EQ(c.camera().eye, startCamera().eye);
    EXPECT_EQ(c.camera().target, startCamera().target);
}

TEST(ViewCameraController, FlyingOneSecondGoesTheSameDistanceAtAnyFrameRate) {
    CameraInput forward;
    forward.move = {0.0f, 0.0f, 1.0f};
    CameraController slow(startCamera(), 20.0f), fast(startCamera(), 20.0f);
    for (int i = 0; i < 10; ++i) slow.update(forward, 1.0f / 10.0f);
    for (int i = 0; i < 240; ++i) fast.update(forward, 1.0f / 240.0f);
    expectNear(slow.camera().eye, fast.camera().eye);
    // And that distance is the fly speed: straight ahead, down -z.
    expectNear(slow.camera().eye, startCamera().eye + glm::vec3(0, 0, -slow.flySpeed()));
}

TEST(ViewCameraController, ShiftIsFasterAndDiagonalsAreNot) {
    CameraController straight(startCamera(), 20.0f), diagonal(startCamera(), 20.0f), shifted(startCamera(), 20.0f);
    CameraInput in;
    in.move = {0, 0, 1};
    straight.update(in, 1.0f);
    in.fast = true;
    shifted.update(in, 1.0f);
    CameraInput diag;
    diag.move = {1, 0, 1};
    diagonal.update(diag, 1.0f);
    const float d = glm::length(straight.camera().eye - startCamera().eye);
    EXPECT_NEAR(glm::length(diagonal.camera().eye - startCamera().eye), d, 1e-4f);
    EXPECT_NEAR(glm::length(shifted.camera().eye - startCamera().eye), d * CameraController::kFastFactor, 1e-3f);
}

TEST(ViewCameraController, QAndEMoveStraightDownAndUp) {
    CameraController c(startCamera(), 20.0f);
    CameraInput up;
    up.move = {0, 1, 0};
    c.update(up, 0.5f);
    expectNear(c.camera().eye, startCamera().eye + glm::vec3(0, 0.5f * c.flySpeed(), 0));
}

TEST(ViewCameraController, ScrollChangesFlySpeed) {
    CameraController c(startCamera(), 20.0f);
    const float before = c.flySpeed();
    CameraInput in;
    in.scroll = 2.0f;
    c.update(in, 0.016f);
    EXPECT_NEAR(c.flySpeed(), before * CameraController::kScrollFactor * CameraController::kScrollFactor, 1e-4f);
}

TEST(ViewCameraController, OrbitKeepsTheTargetAndTheDistance) {
    CameraController c(startCamera(), 20.0f);
    c.setMode(CameraMode::Orbit);
    CameraInput drag;
    drag.drag = {150.0f, -40.0f};
    c.update(drag, 0.016f);
    expectNear(c.camera().target, startCamera().target);
    EXPECT_NEAR(glm::length(c.camera().eye - startCamera().target), 10.0f, 1e-3f);
    EXPECT_GT(glm::length(c.camera().eye - startCamera().eye), 1.0f) << "the eye should have moved round";
}

TEST(ViewCameraController, OrbitScrollZoomsIn) {
    CameraController c(startCamera(), 20.0f);
    c.setMode(CameraMode::Orbit);
    CameraInput in;
    in.scroll = 1.0f;
    c.update(in, 0.016f);
    EXPECT_NEAR(glm::length(c.camera().eye - startCamera().target), 10.0f / CameraController::kScrollFactor, 1e-3f);
}

TEST(ViewCameraController, PitchStopsShortOfStraightUp) {
    CameraController c(startCamera(), 20.0f);
    CameraInput look;
    look.drag = {0.0f, -100000.0f};  // far past vertical
    c.update(look, 0.016f);
    EXPECT_LT(glm::normalize(c.camera().target - c.camera().eye).y, 0.9999f);
    EXPECT_GT(glm::normalize(c.camera().target - c.camera().eye).y, 0.99f);
}

TEST(ViewCameraController, ResetReturnsToTheStart) {
    CameraController c(startCamera(), 20.0f);
    CameraInput in;
    in.move = {1, 0, 1};
    in.drag = {30, 10};
    in.scroll = 3;
    c.update(in, 1.0f);
    c.reset();
    EXPECT_EQ(c.camera().eye, startCamera().eye);
    EXPECT_EQ(c.camera().target, startCamera().target);
    EXPECT_NEAR(c.flySpeed(), 0.2f * 20.0f, 1e-5f);
}

TEST(ViewCameraController, SwitchingToOrbitDoesNotMoveTheView) {
    CameraController c(startCamera(), 20.0f);
    CameraInput look;
    look.drag = {80.0f, 20.0f};
    c.update(look, 0.016f);
    const Camera before = c.camera();
    c.setMode(CameraMode::Orbit);
    CameraInput zoomNothing;
    zoomNothing.scroll = 0.0f;
    zoomNothing.drag = {1e-3f, 0.0f};  // a touch: the camera is rebuilt around the new pivot
    c.update(zoomNothing, 0.016f);
    expectNear(c.camera().eye, before.eye, 1e-2f);
    expectNear(c.camera().target, before.target, 1e-2f);
}

}  // namespace
}  // namespace ml
