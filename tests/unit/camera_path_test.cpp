// The JSON camera path of `view --camera-path`: interpolation, holds, and errors that name the culprit.
#include <gtest/gtest.h>

#include "renderer/camera/camera_path.h"

namespace ml {
namespace {

CameraPath twoKeys() {
    return CameraPath::fromJson(nlohmann::json::parse(R"({"keyframes": [
        {"frame": 10, "eye": [0, 2, 8], "target": [0, 0, 0], "fovy": 40},
        {"frame": 20, "eye": [4, 2, 8], "target": [2, 0, 0], "fovy": 60}]})"),
                                "test.json");
}

TEST(ViewCameraPath, InterpolatesLinearlyBetweenKeyframes) {
    const Camera c = twoKeys().at(15);
    EXPECT_EQ(c.eye, glm::vec3(2, 2, 8));
    EXPECT_EQ(c.target, glm::vec3(1, 0, 0));
    EXPECT_FLOAT_EQ(c.fovyDegrees, 50.0f);
}

TEST(ViewCameraPath, HoldsBeforeTheFirstAndAfterTheLast) {
    EXPECT_EQ(twoKeys().at(0).eye, glm::vec3(0, 2, 8));
    EXPECT_EQ(twoKeys().at(10).eye, glm::vec3(0, 2, 8));
    EXPECT_EQ(twoKeys().at(20).eye, glm::vec3(4, 2, 8));
    EXPECT_EQ(twoKeys().at(1000).eye, glm::vec3(4, 2, 8));
}

TEST(ViewCameraPath, FovyDefaultsToThePreviousKeyframes) {
    const CameraPath p = CameraPath::fromJson(nlohmann::json::parse(R"({"keyframes": [
        {"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 0], "fovy": 35},
        {"frame": 5, "eye": [1, 0, 5], "target": [0, 0, 0]}]})"),
                                              "p.json");
    EXPECT_FLOAT_EQ(p.keyframes()[1].fovyDegrees, 35.0f);
    const CameraPath single = CameraPath::fromJson(
        nlohmann::json::parse(R"({"keyframes": [{"frame": 3, "eye": [0, 0, 5], "target": [0, 0, 0]}]})"), "s.json");
    EXPECT_FLOAT_EQ(single.at(7).fovyDegrees, 60.0f);
}

void expectError(const char* json, const std::string& expected) {
    try {
        CameraPath::fromJson(nlohmann::json::parse(json), "bad.json");
        FAIL() << "no error for " << json;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
    }
}

TEST(ViewCameraPath, ErrorsNameTheFileAndKeyframe) {
    expectError(R"({"keyframes": []})", "at least one keyframe");
    expectError(R"({"frames": []})", "at least one keyframe");
    expectError(R"({"keyframes": [{"frame": 0, "eye": [0, 0, 5]}]})", "keyframe 0: missing \"target\"");
    expectError(R"({"keyframes": [{"frame": -1, "eye": [0, 0, 5], "target": [0, 0, 0]}]})", "whole number");
    expectError(R"({"keyframes": [{"frame": 0, "eye": [0, 0], "target": [0, 0, 0]}]})", "\"eye\": expected an array of 3");
    expectError(R"({"keyframes": [{"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 5]}]})", "same point");
    expectError(R"({"keyframes": [{"frame": 0, "eye": [0, 0, 5], "target": [0, 0, 0], "fovy": 180}]})", "fovy");
    expectError(R"({"keyframes": [{"frame": 4, "eye": [0, 0, 5], "target": [0, 0, 0]},
                                  {"frame": 4, "eye": [0, 1, 5], "target": [0, 0, 0]}]})",
                "keyframe 1: frames must increase");
}

TEST(ViewCameraPath, LoadReportsAMissingFile) {
    EXPECT_THROW(CameraPath::load("/nonexistent/path.json"), std::invalid_argument);
}

}  // namespace
}  // namespace ml
