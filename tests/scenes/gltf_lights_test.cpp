// glTF lights (KHR_lights_punctual, scenes/gltf_lights.h): placed by nested, rotated and scaled
// node transforms, with the file's colour, intensity, range and cone angles; bad lights refused
// in one line naming them. The files are written as GLB, so each is a self-contained fuzz seed.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenes/gltf_loader.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;

json pointLight(double intensity = 1.0) { return {{"type", "point"}, {"intensity", intensity}}; }
json spotLight(double inner, double outer) {
    return {{"type", "spot"}, {"spot", {{"innerConeAngle", inner}, {"outerConeAngle", outer}}}};
}

void setLights(Gltf& g, const std::vector<json>& lights) {
    g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    g.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json(lights)}}}};
}
json lightOn(int light) { return {{"KHR_lights_punctual", {{"light", light}}}}; }

TEST(GltfLights, LightsAtNestedRotatedScaledNodesLandWhereTheyShould) {
    Gltf g = oneTriangle();
    json spot = spotLight(0.2, 0.6);
    spot["name"] = "Stage";
    spot["color"] = {1.0, 0.5, 0.25};
    spot["intensity"] = 8.0;
    spot["range"] = 12.0;
    json sun = {{"type", "directional"}, {"intensity", 3.0}};
    setLights(g, {pointLight(2.0), spot, sun});
    const double s = std::sqrt(0.5);
    // Parent: translate (1, 2, 3), scale 2. Child: translate (0, 0, 1), turn 90 degrees about +y:
    // the spot sits at (1, 2, 5) and points down -x.
    const int child = g.node({{"extensions", lightOn(1)}, {"translation", {0, 0, 1}}, {"rotation", {0.0, s, 0.0, s}}});
    const int parent = g.node({{"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}, {"children", {child}}});
    // A point light under a non-uniform scale: only its position matters.
    const int point = g.node({{"name", "Lamp"}, {"extensions", lightOn(0)}, {"translation", {-4, 1, 0}}, {"scale", {3, 0.5, 7}}});
    // A sun turned 90 degrees about +x: its -z becomes -y (straight down).
    const int sunNode = g.node({{"extensions", lightOn(2)}, {"rotation", {-s, 0.0, 0.0, s}}});
    g.doc["scenes"][0]["nodes"] = {0, parent, point, sunNode};
    const fs::path file = g.writeGlb(testDir(), "lights");

    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_EQ(scene.lights.size(), 3u);  // in node-walk order
    const SceneLight& stage = scene.lights[0];
    EXPECT_EQ(stage.name, "Stage");
    EXPECT_EQ(stage.type, SceneLight::Type::Spot);
    expectNear(stage.position, {1, 2, 5});
    expectNear(stage.direction, {-1, 0, 0});
    expectNear(stage.color, {1.0f, 0.5f, 0.25f});
    EXPECT_FLOAT_EQ(stage.intensity, 8.0f);
    EXPECT_FLOAT_EQ(stage.range, 12.0f);
    EXPECT_FLOAT_EQ(stage.innerConeAngle, 0.2f);
    EXPECT_FLOAT_EQ(stage.outerConeAngle, 0.6f);

    const SceneLight& lamp = scene.lights[1];
    EXPECT_EQ(lamp.name, "Lamp");  // the node's name where the light has none
    EXPECT_EQ(lamp.type, SceneLight::Type::Point);
    expectNear(lamp.position, {-4, 1, 0});
    expectNear(lamp.color, {1, 1, 1});  // no colour given: white
    EXPECT_EQ(lamp.range, 0.0f);        // none given

    const SceneLight& sunLight = scene.lights[2];
    EXPECT_EQ(sunLight.type, SceneLight::Type::Directional);
    expectNear(sunLight.direction, {0, -1, 0});
    EXPECT_FLOAT_EQ(sunLight.intensity, 3.0f);
}

TEST(GltfLights, ALightOnTwoNodesIsPlacedTwiceAndAnUnplacedLightNotAtAll) {
    Gltf g = oneTriangle();
    setLights(g, {pointLight(), pointLight()});
    g.doc["scenes"][0]["nodes"] = {0, g.node({{"extensions", lightOn(0)}, {"translation", {1, 0, 0}}}),
                                   g.node({{"extensions", lightOn(0)}, {"translation", {2, 0, 0}}})};
    const Scene scene = load(g.writeGlb(testDir(), "instances"));
    ASSERT_EQ(scene.lights.size(), 2u);
    expectNear(scene.lights[0].position, {1, 0, 0});
    expectNear(scene.lights[1].position, {2, 0, 0});
}

TEST(GltfLights, BadLightsAreRefusedNamingThem) {
    struct Case {
        const char* name;
        json light;
        std::vector<const char*> keywords;
    };
    const std::vector<Case> cases = {
        {"type", {{"type", "area"}}, {"lights[0]", "type 'area'"}},
        {"outer_zero", spotLight(0.0, 0.0), {"lights[0]", "outerConeAngle"}},
        {"outer_wide", spotLight(0.1, 1.8), {"lights[0]", "outerConeAngle"}},
        {"inner_above_outer", spotLight(0.7, 0.5), {"lights[0]", "innerConeAngle"}},
        {"intensity_negative", pointLight(-1.0), {"lights[0]", "intensity"}},
        {"color_negative", {{"type", "point"}, {"color", {1.0, -0.5, 1.0}}}, {"lights[0]", "color[1]"}},
        {"color_short", {{"type", "point"}, {"color", {1.0, 1.0}}}, {"lights[0]", "color has 2 numbers"}},
        {"range_negative", {{"type", "point"}, {"range", -2.0}}, {"lights[0]", "range"}},
        {"intensity_huge", pointLight(1e300), {"lights[0]", "intensity"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Gltf g = oneTriangle();
        setLights(g, {c.light});
        g.doc["scenes"][0]["nodes"] = {0, g.node({{"extensions", lightOn(0)}})};
        expectFault(g.writeGlb(testDir(), std::string("light_") + c.name), {c.keywords[0], c.keywords[1]});
    }
    Gltf index = oneTriangle();
    setLights(index, {pointLight()});
    index.doc["scenes"][0]["nodes"] = {0, index.node({{"extensions", lightOn(4)}})};
    expectFault(index.writeGlb(testDir(), "light_index"), {"nodes[1]", "lights[4] out of range (1 lights)"});

    Gltf zeroScale = oneTriangle();
    setLights(zeroScale, {spotLight(0.1, 0.5)});
    zeroScale.doc["scenes"][0]["nodes"] = {0, zeroScale.node({{"extensions", lightOn(0)}, {"scale", {0, 0, 0}}})};
    expectFault(zeroScale.writeGlb(testDir(), "light_zero_scale"), {"lights[0]", "nodes[1]", "direction"});
}

TEST(GltfLights, AFileWithoutLightsHasNone) { EXPECT_TRUE(load(oneTriangle().writeGlb(testDir(), "no_lights")).lights.empty()); }

}  // namespace
}  // namespace ml
