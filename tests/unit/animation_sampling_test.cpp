// Keyframe interpolation against glTF 2.0's Appendix C: STEP, LINEAR (slerp along the shorter
// arc), CUBICSPLINE (tangents scaled by the keyframe interval), before the first and after the
// last key, and the clip's loop.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include "scenes/animation_sampling.h"

namespace ml {
namespace {

AnimationSampler sampler(Interpolation interpolation, std::vector<float> times, std::vector<float> values, std::size_t width) {
    AnimationSampler s;
    s.interpolation = interpolation;
    s.times = std::move(times);
    s.values = std::move(values);
    s.width = width;
    return s;
}

float sample1(const AnimationSampler& s, float t) {
    float out = -1.0f;
    sampleAnimation(s, AnimatedProperty::Weights, t, std::span<float>(&out, 1));
    return out;
}

glm::quat sampleQuat(const AnimationSampler& s, float t) {
    std::array<float, 4> q{};
    sampleAnimation(s, AnimatedProperty::Rotation, t, q);
    return glm::quat(q[3], q[0], q[1], q[2]);
}

TEST(AnimationSampling, StepHoldsEachKeyUntilTheNext) {
    const AnimationSampler s = sampler(Interpolation::Step, {1.0f, 2.0f, 3.0f}, {10.0f, 20.0f, 30.0f}, 1);
    EXPECT_EQ(sample1(s, 0.0f), 10.0f);  // before the first key: the first value
    EXPECT_EQ(sample1(s, 1.0f), 10.0f);
    EXPECT_EQ(sample1(s, 1.99f), 10.0f);
    EXPECT_EQ(sample1(s, 2.0f), 20.0f);
    EXPECT_EQ(sample1(s, 2.5f), 20.0f);
    EXPECT_EQ(sample1(s, 3.0f), 30.0f);
    EXPECT_EQ(sample1(s, 9.0f), 30.0f);  // after the last: the last value
}

TEST(AnimationSampling, LinearInterpolatesAndClampsAtTheEnds) {
    const AnimationSampler s = sampler(Interpolation::Linear, {1.0f, 3.0f}, {10.0f, 20.0f}, 1);
    EXPECT_EQ(sample1(s, -1.0f), 10.0f);
    EXPECT_FLOAT_EQ(sample1(s, 1.5f), 12.5f);
    EXPECT_FLOAT_EQ(sample1(s, 2.0f), 15.0f);
    EXPECT_EQ(sample1(s, 4.0f), 20.0f);
}

TEST(AnimationSampling, LinearRotationIsASlerp) {
    // 0 to 90 degrees about z: at a quarter, 22.5 degrees (a lerp of the quaternions would not be).
    const float h = std::sqrt(0.5f);
    const AnimationSampler s = sampler(Interpolation::Linear, {0.0f, 1.0f}, {0, 0, 0, 1, 0, 0, h, h}, 4);
    const glm::quat q = sampleQuat(s, 0.25f);
    EXPECT_NEAR(glm::degrees(glm::angle(q)), 22.5f, 1e-3f);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
}

TEST(AnimationSampling, SlerpTakesTheShorterArc) {
    // +170 degrees to -170 degrees about z: the short way is 20 degrees through 180, not 340
    // through 0. The second key is stored with a negative w (the same rotation as its negation).
    const glm::quat a = glm::angleAxis(glm::radians(170.0f), glm::vec3(0, 0, 1));
    const glm::quat b = glm::angleAxis(glm::radians(-170.0f), glm::vec3(0, 0, 1));
    const AnimationSampler s = sampler(Interpolation::Linear, {0.0f, 1.0f}, {a.x, a.y, a.z, a.w, b.x, b.y, b.z, b.w}, 4);
    const glm::quat mid = sampleQuat(s, 0.5f);
    const glm::vec3 x = mid * glm::vec3(1, 0, 0);
    EXPECT_NEAR(x.x, -1.0f, 1e-5f);  // turned by 180 degrees
    EXPECT_NEAR(x.y, 0.0f, 1e-5f);
}

TEST(AnimationSampling, CubicSplineScalesTangentsByTheInterval) {
    // v0 = 0, v1 = 1 over an interval of 2 s, out-tangent of key 0 = 1/s, in-tangent of key 1 = 0.
    // Hermite at u = 0.5: h00 v0 + h10 * 2 * b0 + h01 v1 + h11 * 2 * a1
    //   = 0.5 * 0 + 0.125 * 2 * 1 + 0.5 * 1 + (-0.125) * 2 * 0 = 0.75.
    const AnimationSampler s =
        sampler(Interpolation::CubicSpline, {1.0f, 3.0f}, {/*a0*/ 9.0f, /*v0*/ 0.0f, /*b0*/ 1.0f, /*a1*/ 0.0f, /*v1*/ 1.0f, /*b1*/ 9.0f}, 1);
    EXPECT_FLOAT_EQ(sample1(s, 2.0f), 0.75f);
    EXPECT_EQ(sample1(s, 0.0f), 0.0f);  // the value, not a tangent
    EXPECT_EQ(sample1(s, 5.0f), 1.0f);
    // u = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875.
    EXPECT_NEAR(sample1(s, 1.5f), 0.140625f * 2.0f + 0.15625f, 1e-6f);
}

TEST(AnimationSampling, CubicSplineRotationComesOutUnit) {
    const float h = std::sqrt(0.5f);
    const AnimationSampler s = sampler(Interpolation::CubicSpline, {0.0f, 1.0f},
                                       {0, 0, 0, 0, /*v0*/ 0, 0, 0, 1, 0, 0, 1, 0, /*a1*/ 0, 0, 0, 0, /*v1*/ 0, 0, h, h, 0, 0, 0, 0}, 4);
    EXPECT_NEAR(glm::length(sampleQuat(s, 0.3f)), 1.0f, 1e-6f);
}

TEST(AnimationSampling, ClipTimeLoops) {
    AnimationClip clip;
    clip.duration = 2.0f;
    EXPECT_EQ(clipTime(clip, 0.0), 0.0f);
    EXPECT_FLOAT_EQ(clipTime(clip, 1.5), 1.5f);
    EXPECT_FLOAT_EQ(clipTime(clip, 2.0), 0.0f);
    EXPECT_FLOAT_EQ(clipTime(clip, 5.25), 1.25f);
    EXPECT_FLOAT_EQ(clipTime(clip, -0.5), 1.5f);
    clip.duration = 0.0f;
    EXPECT_EQ(clipTime(clip, 3.0), 0.0f);
}

}  // namespace
}  // namespace ml
