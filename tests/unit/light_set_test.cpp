// Light generation, validation and the JSON file round trip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/lights/light_set.h"

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

TEST(LightSet, SpotsAndSunsRoundTripExactly) {
    LightGeneration gen;
    gen.count = 200;
    gen.spotShare = 0.5f;
    std::vector<Light> lights = generateLights(unitBounds(), gen);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.3f, -2.0f, 0.1f};  // not unit: kept as given
    sun.color = {0.1f, 0.2f, 0.3f};
    lights.insert(lights.begin() + 3, sun);
    const auto path = tempFile("spots.json").string();
    saveLightsFile(path, lights);
    const auto loaded = loadLightsFile(path);
    ASSERT_EQ(loaded.size(), lights.size());
    std::size_t spots = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        EXPECT_EQ(loaded[i].type, lights[i].type) << i;
        EXPECT_EQ(loaded[i].color, lights[i].color) << i;
        EXPECT_EQ(loaded[i].direction, lights[i].direction) << i;
        if (lights[i].type == LightType::Directional) continue;
        EXPECT_EQ(loaded[i].position, lights[i].position) << i;
        EXPECT_EQ(loaded[i].radius, lights[i].radius) << i;
        if (lights[i].type != LightType::Spot) continue;
        ++spots;
        EXPECT_EQ(loaded[i].innerConeAngle, lights[i].innerConeAngle) << i;
        EXPECT_EQ(loaded[i].outerConeAngle, lights[i].outerConeAngle) << i;
    }
    EXPECT_GT(spots, 60u);
    EXPECT_LT(spots, 140u);
}

TEST(LightSet, SpotsKeepThePointsOfASetInPlace) {
    LightGeneration gen;
    gen.count = 300;
    const auto points = generateLights(unitBounds(), gen);
    gen.spotShare = 0.5f;
    gen.spotAngleDeg = 35.0f;
    const auto mixed = generateLights(unitBounds(), gen);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(points[i].position, mixed[i].position);
        if (mixed[i].type != LightType::Spot) continue;
        EXPECT_NEAR(glm::length(mixed[i].direction), 1.0f, 1e-5f);
        EXPECT_FLOAT_EQ(mixed[i].outerConeAngle, 35.0f * 3.14159265f / 180.0f);
        EXPECT_FLOAT_EQ(mixed[i].innerConeAngle, kGeneratedSpotInnerShare * mixed[i].outerConeAngle);
    }
}

TEST(LightSet, BadSpotsAndSunsAreRejectedWithTheIndex) {
    const std::string point = R"({"position":[0,0,0],"radius":1,"color":[1,1,1]})";
    const auto spot = [](const std::string& fields) {
        return R"({"type":"spot","position":[0,0,0],"radius":1,"color":[1,1,1],)" + fields + "}";
    };
    const auto file = [&](const std::string& light) { return R"({"lights":[)" + point + "," + light + "]}"; };
    expectRejected(file(spot(R"("direction":[0,-1,0],"outerConeAngle":2.0)")), "light 1: spot outerConeAngle");
    expectRejected(file(spot(R"("direction":[0,-1,0],"outerConeAngle":0)")), "light 1: spot outerConeAngle");
    expectRejected(file(spot(R"("direction":[0,-1,0],"innerConeAngle":0.6,"outerConeAngle":0.5)")), "light 1: spot innerConeAngle");
    expectRejected(file(spot(R"("direction":[0,0,0],"outerConeAngle":0.5)")), "light 1: spot direction is zero");
    expectRejected(file(spot(R"("outerConeAngle":0.5)")), "light 1: \"direction\"");
    expectRejected(file(spot(R"("direction":[0,-1,0])")), "light 1: \"outerConeAngle\"");
    expectRejected(file(R"({"type":"directional","color":[1,1,1],"direction":[0,0,0]})"), "light 1: directional direction is zero");
    expectRejected(file(R"({"type":"area","color":[1,1,1]})"), "light 1: \"type\" 'area'");
    std::vector<Light> lights(2);
    lights[1].type = LightType::Spot;
    lights[1].outerConeAngle = std::nanf("");
    try {
        validateLights(lights, "test");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("light 1: spot outerConeAngle"), std::string::npos) << e.what();
    }
}

TEST(LightSet, AFileLightWithoutRangeStopsWhereItFallsTo1Over255) {
    Scene scene;
    SceneLight white;
    white.intensity = 1.0f;
    SceneLight ranged;
    ranged.range = 7.0f;
    ranged.intensity = 100.0f;
    scene.lights = {white, ranged};
    const auto lights = lightsFromScene(scene);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_NEAR(lights[0].radius, std::sqrt(255.0f), 1e-4f);
    EXPECT_EQ(lights[1].radius, 7.0f);
    EXPECT_EQ(lights[1].color, glm::vec3(100.0f));
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

TEST(LightAnimation, AtTimeZeroEveryLightIsWhereItWasPlaced) {
    // The repro of issue 61: a light at y = 4 over a scene whose light volume spans y -0.42..2.42
    // wrapped to y = 1.17, under the quad it lit, before a single frame had passed.
    const LightAnimation anim{0.5f, -0.4175f, 2.835f};
    Light above;
    above.position = {0.0f, 4.0f, 0.0f};
    const std::vector<Light> lights{above};
    const LightAnimation fitted = fitDrift(anim, driftingLights(lights));
    EXPECT_LE(fitted.wrapMinY, anim.wrapMinY);
    EXPECT_GT(fitted.wrapMinY + fitted.wrapHeight, 4.0f) << "the wrap range holds the light";
    EXPECT_EQ(animateLight(above, 0, 0.0f, fitted).position, above.position);
    for (float y : {-0.4175f, 0.3f, 1.9f, 2.4174f}) {
        Light l;
        l.position = {1.0f, y, 2.0f};
        EXPECT_EQ(animateLight(l, 3, 0.0f, anim).position, l.position) << y;
    }
}

TEST(LightAnimation, PlacedLightsStayWhereTheFilePutsThem) {
    Scene scene;
    SceneLight point;
    point.position = {0.0f, 4.0f, 0.0f};
    point.range = 40.0f;
    SceneLight sun;
    sun.type = SceneLight::Type::Directional;
    scene.lights = {sun, point};
    std::vector<Light> lights = lightsFromScene(scene);
    ASSERT_EQ(lights.size(), 2u);
    EXPECT_FALSE(lights[0].drifts);
    EXPECT_FALSE(lights[1].drifts);
    Light generated;
    generated.position = {0.0f, 1.0f, 0.0f};
    lights.push_back(generated);
    const DriftingLights drifting = driftingLights(lights);
    EXPECT_EQ(drifting.first, 1u) << "the directional light is not among the GPU's lights";
    const LightAnimation anim = fitDrift(LightAnimation{1.0f, 0.0f, 5.0f}, drifting);
    EXPECT_EQ(animateLight(lights[1], 0, 3.0f, anim).position, lights[1].position);
    EXPECT_NE(animateLight(lights[2], 1, 3.0f, anim).position, lights[2].position);
    // A placed light after a generated one breaks the order the GPU's index relies on.
    std::vector<Light> misordered{generated, lights[1]};
    EXPECT_THROW(driftingLights(misordered), std::invalid_argument);
}

TEST(LightAnimation, ALightsFileIsAnExactSet) {
    const std::string path = ::testing::TempDir() + "exact_set.json";
    Light l;
    l.position = {0.5f, 9.0f, -1.0f};
    saveLightsFile(path, {l});
    const std::vector<Light> loaded = loadLightsFile(path);
    ASSERT_EQ(loaded.size(), 1u);
    EXPECT_FALSE(loaded[0].drifts);
    EXPECT_EQ(driftingLights(loaded).first, 1u);
}

}  // namespace
}  // namespace ml
