// The turntable of `render --camera orbit:...`: it returns to its start, keeps its distance and
// elevation, and looks at the centre.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/camera/camera_orbit.h"

namespace ml {
namespace {

CameraOrbit sampleOrbit() {
    CameraOrbit o;
    o.centre = glm::vec3(1.0f, 2.0f, -3.0f);
    o.distance = 10.0f;
    o.elevationDegrees = 30.0f;
    o.azimuthDegrees = 40.0f;
    o.frames = 90;
    return o;
}

TEST(CameraOrbit, ReturnsToItsStartBitForBit) {
    const CameraOrbit o = sampleOrbit();
    for (std::uint32_t start : {0u, 7u, 89u}) {
        EXPECT_EQ(o.at(start).eye, o.at(start + o.frames).eye) << start;
        EXPECT_EQ(o.at(start).eye, o.at(start + 5 * o.frames).eye) << start;
    }
    EXPECT_NE(o.at(0).eye, o.at(1).eye);
    // Halfway round, the eye is opposite its start across the axis through the centre.
    const glm::vec3 a = o.at(0).eye - o.centre, b = o.at(45).eye - o.centre;
    EXPECT_NEAR(a.x, -b.x, 1e-4f);
    EXPECT_NEAR(a.z, -b.z, 1e-4f);
    EXPECT_NEAR(a.y, b.y, 1e-4f);
}

TEST(CameraOrbit, KeepsDistanceAndElevationAndLooksAtTheCentre) {
    const CameraOrbit o = sampleOrbit();
    for (std::uint32_t f = 0; f < o.frames; f += 11) {
        const Camera c = o.at(f);
        EXPECT_EQ(c.target, o.centre);
        EXPECT_NEAR(glm::length(c.eye - o.centre), 10.0f, 1e-4f);
        EXPECT_NEAR(c.eye.y - o.centre.y, 10.0f * std::sin(glm::radians(30.0f)), 1e-4f);
        EXPECT_FLOAT_EQ(c.fovyDegrees, o.fovyDegrees);
    }
}

TEST(CameraOrbit, StartsAtItsAzimuth) {
    CameraOrbit o = sampleOrbit();
    o.azimuthDegrees = 90.0f;  // from +z towards +x: on the +x side
    o.elevationDegrees = 0.0f;
    const glm::vec3 d = o.at(0).eye - o.centre;
    EXPECT_NEAR(d.x, 10.0f, 1e-4f);
    EXPECT_NEAR(d.z, 0.0f, 1e-4f);
}

TEST(CameraOrbit, DistanceFramesTheBounds) {
    Bounds b;
    b.extend(glm::vec3(-3.0f, -4.0f, 0.0f));
    b.extend(glm::vec3(3.0f, 4.0f, 0.0f));  // a bounding sphere of radius 5
    EXPECT_NEAR(orbitDistanceToFrame(b, 60.0f), 10.0f, 1e-4f);
}

}  // namespace
}  // namespace ml
