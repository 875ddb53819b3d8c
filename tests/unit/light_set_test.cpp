// Light generation, validation and the JSON file round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "renderer/light_set.h"

namespace ml {
namespace {

std::filesystem::path tempFile(const std::string& name) {
    const char* env = std::getenv("ML_TEST_TMP");
    std::filesystem::path dir = env ? env : std::filesystem::temp_directory_path();
    dir /= "light_set_test";
    std::filesystem::create_directories(dir);
    return dir / name;
}

Bounds unitBounds() {
    Bounds b;
    b.extend({-2, 0, -3});
    b.extend({2, 5, 3});
    return b;
}

TEST(LightSet, GenerationIsDeterministicAndInsideTheBounds) {
    LightGeneration gen;
    gen.count = 5000;
    gen.seed = 42;
    const auto a = generateLights(unitBounds(), gen);
    const auto b = generateLights(unitBounds(), gen);
    ASSERT_EQ(a.size(), 5000u);
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].position, b[i].position);
        EXPECT_EQ(a[i].color, b[i].color);
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(a[i].position, unitBounds().min)));
        EXPECT_TRUE(glm::all(glm::lessThanEqual(a[i].position, unitBounds().max)));
    }
    gen.seed = 43;
    EXPECT_NE(generateLights(unitBounds(), gen)[0].position, a[0].position);
}

TEST(LightSet, FileRoundTripIsExact) {
    LightGeneration gen;
    gen.count = 100;
    gen.radius = 1.37f;
    const auto lights = generateLights(unitBounds(), gen);
    const auto path = tempFile("roundtrip.json").string();
    saveLightsFile(path, lights);
    const auto loaded = loadLightsFile(path);
    ASSERT_EQ(loaded.size(), lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        EXPECT_EQ(loaded[i].position, lights[i].position);
        EXPECT_EQ(loaded[i].radius, lights[i].radius);
        EXPECT_EQ(loaded[i].color, lights[i].color);
    }
}

void expectRejected(const std::string& json, const std::string& expectedFragment) {
    const auto path = tempFile("bad.json").string();
    std::ofstream(path) << json;
    try {
        loadLightsFile(path);
        ADD_FAILURE() << "accepted: " << json;
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(expectedFragment), std::string::npos) << what;
        EXPECT_NE(what.find("bad.json"), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(LightSet, BadFilesAreRejectedWithTheIndex) {
    expectRejected("{", "not valid JSON");
    expectRejected("[1,2]", "\"lights\" array");
    expectRejected(R"({"lights":[{"position":[0,0,0],"radius":1,"color":[1,1,1]},{"position":[0,0],"radius":1,"color":[1,1,1]}]})",
                   "light 1");
    expectRejected(R"({"lights":[{"position":[0,0,0],"radius":-1,"color":[1,1,1]}]})", "radius is negative");
    expectRejected(R"({"lights":[{"position":[0,0,0],"radius":"big","color":[1,1,1]}]})", "radius");
    expectRejected(R"({"lights":[{"position":[0,0,0],"radius":1,"color":[1,-1,1]}]})", "color is negative");
    expectRejected(R"({"lights":[{"position":[0,1e999,0],"radius":1,"color":[1,1,1]}]})", "number overflow");
}

TEST(LightSet, ValidationNamesTheFirstBadLight) {
    std::vector<Light> lights(3);
    lights[2].position.y = std::nanf("");
    try {
        validateLights(lights, "test");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("light 2: position is not finite"), std::string::npos) << e.what();
    }
}

TEST(LightAnimation, WrapsWithinTheVerticalExtent) {
    const LightAnimation anim{1.0f, 0.0f, 5.0f};
    Light l;
    l.position = {0.0f, 4.9f, 0.0f};
    for (float t : {0.0f, 0.1f, 1.0f, 10.0f, 1000.0f}) {
        const Light a = animateLight(l, 7, t, anim);
        EXPECT_GE(a.position.y, 0.0f);
        EXPECT_LT(a.position.y, 5.0f + 1e-4f);
        EXPECT_EQ(a.position.x, l.position.x);
    }
    EXPECT_EQ(animateLight(l, 7, 3.0f, LightAnimation{0.0f, 0.0f, 5.0f}).position, l.position);
}

}  // namespace
}  // namespace ml
