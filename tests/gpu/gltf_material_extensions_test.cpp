// glTF's material extensions on files the tests write: KHR_materials_unlit, KHR_materials_ior,
// KHR_materials_specular (factors and both maps), KHR_materials_clearcoat (factors, its three maps,
// the emissive under it), KHR_materials_sheen (factors, both maps, under a coat),
// KHR_materials_anisotropy (strength and rotation, its map, under a normal map, every light type),
// KHR_materials_iridescence (a fixed thickness, a metal, one image for both maps, over a higher ior),
// KHR_materials_pbrSpecularGlossiness (held to its conversion by hand) and KHR_materials_variants
// (each variant drawn with its material). Every clustered method (both deferred resolves, the
// visibility buffer, all in the exact G-buffer) is held to naive on each; the frame's pixel is
// held to the CPU mirror (renderer/reference/shading_reference.h) and, for unlit, to the base
// colour itself, whatever the lights.
#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "app/frame_options.h"
#include "glsl/include/bindings.h"
#include "renderer/gbuffer_format.h"
#include "renderer/image/image.h"
#include "renderer/methods/naive_forward.h"
#include "renderer/pass_timer.h"
#include "renderer/reference/shading_reference.h"
#include "renderer/scene/material_features.h"
#include "scenes/material_variants.h"
#include "tests/gpu/gpu_test.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;
using test::GpuTest;

constexpr int kWidth = 160, kHeight = 90;

// A 2x2 texture of one RGBA8 texel, nearest-filtered: the map's value is the texel to the bit.
int addFlatTexture(Gltf& g, std::array<std::uint8_t, 4> texel) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 4; ++i) rgba.insert(rgba.end(), texel.begin(), texel.end());
    const int image = g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(2, 2, rgba))}});
    const int sampler = g.add("samplers", {{"magFilter", 9728}, {"minFilter", 9728}});
    return g.add("textures", {{"source", image}, {"sampler", sampler}});
}

float srgbToLinear(std::uint8_t v) {
    const float c = v / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// A point light for the clusters and a sun for the mirror's comparison (no falloff to place exactly).
std::vector<Light> testLights() {
    Light point{{0.4f, 0.3f, 2.0f}, 8.0f, {2.0f, 2.0f, 2.0f}};
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -0.2f, -1.0f));
    sun.color = glm::vec3(1.5f);
    return {point, sun};
}

// The quad's point under the centre of the frame's middle pixel, as the pixel's ray meets z = 0
// (the camera at (0, 0, 4) looking down -z, 60 degrees vertically; row 0 at the top).
glm::vec3 middlePixelPoint() {
    const float t = std::tan(glm::radians(30.0f)) * 4.0f;
    const float x = ((kWidth / 2 + 0.5f) / kWidth * 2.0f - 1.0f) * t * float(kWidth) / float(kHeight);
    const float y = (1.0f - (kHeight / 2 + 0.5f) / kHeight * 2.0f) * t;
    return {x, y, 0.0f};
}

// The CPU mirror's sample of the quad under the middle pixel: facing the camera (+z), of this
// base colour, metallic and roughness.
SurfaceSample middlePixelSample(glm::vec3 base, float metallic, float roughness) {
    SurfaceSample s;
    s.position = middlePixelPoint();
    s.normal = glm::vec3(0.0f, 0.0f, 1.0f);
    s.baseColor = base;
    s.metallic = metallic;
    s.roughness = roughness;
    return s;
}

// The middle pixel against the CPU mirror's `s`, and the extension visible there: the mirror's
// `without` (s less the extension) is not the same.
void expectMirrorPixelShowingTheExtension(const test::ReferenceFrame& naive, const SurfaceSample& s, const SurfaceSample& without,
                                          const std::vector<Light>& lights, const FrameSettings& settings, const std::string& label) {
    const glm::vec3 mirror = shadeReference(s, kFrontView.eye, lights, settings.ambient, true, settings.lightModel);
    const float* p = naive.hdr.at(kWidth / 2, kHeight / 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], mirror[k], 1e-4f + 1e-4f * mirror[k]) << label << " channel " << k;
    const glm::vec3 plain = shadeReference(without, kFrontView.eye, lights, settings.ambient, true, settings.lightModel);
    EXPECT_GT(glm::length(mirror - plain), 1e-3f) << label << ": the extension changed nothing";
}

// A quad of base colour `base` whose extension is switched off (`extensions(g)`: the material's
// extensions object, maps added to g) compiles none of `features` in and draws, in every method,
// the frame the plain material draws.
void expectSwitchedOffExtensionDrawsThePlainMaterial(glm::vec3 base, const std::function<json(Gltf&)>& extensions,
                                                     std::uint32_t features, const std::string& label) {
    std::vector<float> pixels[2];
    for (int withExtension = 0; withExtension < 2; ++withExtension) {
        Gltf g;
        json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}};
        if (withExtension) material["extensions"] = extensions(g);
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, g.add("materials", material))}, "switched_off");
        EXPECT_EQ(materialFeatures(scene) & features, 0u) << label;
        FrameRenderer renderer(scene, testLights(), test::smallFrame(scene, kFrontView, kWidth, kHeight));
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, label);
        pixels[withExtension] = naive.hdr.pixels;
    }
    EXPECT_EQ(pixels[0], pixels[1]) << label << " changed the frame";
}

class GltfMaterialExtensions : public GpuTest {};

// A lit wall behind an unlit quad: the quad shows its base colour to the float, in every method, with the lights on or off; its features compile in only here.
TEST_F(GltfMaterialExtensions, UnlitShowsItsBaseColourWhateverTheLights) {
    Gltf g;
    const int lit = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}, {"metallicFactor", 0.0}}}});
    const int unlit = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.5, 0.25, 1.0}}}},
                                          {"extensions", {{"KHR_materials_unlit", json::object()}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_unlit"};
    const Scene scene = writeAndLoad(g, {square(g, -0.5f, 3.0f, lit), square(g, 0.0f, 1.0f, unlit)}, "unlit");
    ASSERT_TRUE(scene.materials[1].unlit);
    EXPECT_EQ(materialFeatures(scene) & (ML_FEATURE_UNLIT | ML_FEATURE_SPECULAR), std::uint32_t(ML_FEATURE_UNLIT));

    const glm::vec3 expected(0.9f, 0.5f, 0.25f);
    std::vector<float> unlitPixel[2];
    for (const std::vector<Light>& lights : {testLights(), std::vector<Light>{}}) {
        FrameRenderer renderer(scene, lights, test::smallFrame(scene, kFrontView, kWidth, kHeight));
        const std::string label = lights.empty() ? "unlit, no lights" : "unlit, lights";
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, label);
        const float* p = naive.hdr.at(kWidth / 2, kHeight / 2);
        unlitPixel[lights.empty()].assign(p, p + 3);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], expected[c]) << label << " channel " << c;
        // The lit wall beside it does see the lights.
        if (!lights.empty()) {
            EXPECT_GT(naive.hdr.at(kWidth / 2 - 40, kHeight / 2)[0], 0.1f);
        }
    }
    EXPECT_EQ(unlitPixel[0], unlitPixel[1]) << "the lights changed an unlit pixel";
}

struct SpecularCase {
    const char* name;
    json extensions;
    float metallic;
    glm::vec3 specularF0;  // what the mirror takes: min(((ior - 1) / (ior + 1))^2 x colour, 1)
    float specularWeight;
};

// Quads of KHR_materials_ior and KHR_materials_specular (factors, maps, ior 0, a metal) under a
// sun and a point light: every method holds to naive, and the middle pixel to the CPU mirror.
TEST_F(GltfMaterialExtensions, SpecularAndIorMatchNaiveAndTheCpuMirror) {
    const auto f0 = [](double ior) { return float(std::pow((ior - 1.0) / (ior + 1.0), 2.0)); };
    // The maps' texels: specular weight in A (linear), colour in RGB (sRGB).
    const std::array<std::uint8_t, 4> weightTexel{0, 0, 0, 153}, colourTexel{255, 64, 128, 255};
    const glm::vec3 colourMap(srgbToLinear(255), srgbToLinear(64), srgbToLinear(128));
    std::vector<SpecularCase> cases = {
        {"ior 2.42", {{"KHR_materials_ior", {{"ior", 2.42}}}}, 0.0f, glm::vec3(f0(2.42)), 1.0f},
        {"ior 1.0", {{"KHR_materials_ior", {{"ior", 1.0}}}}, 0.0f, glm::vec3(0.0f), 1.0f},
        {"specular colour and weight",
         {{"KHR_materials_specular", {{"specularFactor", 0.6}, {"specularColorFactor", {1.0, 0.3, 0.2}}}}},
         0.0f, glm::vec3(0.04f) * glm::vec3(1.0f, 0.3f, 0.2f), 0.6f},
        {"ior 0 and a colour past 1",
         {{"KHR_materials_ior", {{"ior", 0.0}}}, {"KHR_materials_specular", {{"specularColorFactor", {2.0, 0.5, 0.1}}}}},
         0.0f, glm::vec3(1.0f, 0.5f, 0.1f), 1.0f},
        {"maps", {{"KHR_materials_specular", {{"specularFactor", 0.8}, {"specularColorFactor", {0.9, 1.0, 1.0}}}}}, 0.0f,
         glm::min(glm::vec3(0.04f) * glm::vec3(0.9f, 1.0f, 1.0f) * colourMap, glm::vec3(1.0f)), 0.8f * 153.0f / 255.0f},
        {"half metal", {{"KHR_materials_ior", {{"ior", 1.8}}}, {"KHR_materials_specular", {{"specularColorFactor", {0.2, 1.0, 0.5}}}}},
         0.5f, glm::vec3(f0(1.8)) * glm::vec3(0.2f, 1.0f, 0.5f), 1.0f},
    };
    const glm::vec3 base(0.6f, 0.45f, 0.3f);
    for (SpecularCase& c : cases) {
        Gltf g;
        if (std::string(c.name) == "maps") {
            c.extensions["KHR_materials_specular"]["specularTexture"] = {{"index", addFlatTexture(g, weightTexel)}};
            c.extensions["KHR_materials_specular"]["specularColorTexture"] = {{"index", addFlatTexture(g, colourTexel)}};
        }
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
                                                                           {"metallicFactor", c.metallic}, {"roughnessFactor", 0.35}}},
                                                 {"extensions", c.extensions}});
        g.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular"};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, material)}, "specular");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_SPECULAR) << c.name;
        const std::vector<Light> lights = testLights();
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);

        SurfaceSample s = middlePixelSample(base, c.metallic, 0.35f);
        s.specularF0 = c.specularF0;
        s.specularWeight = c.specularWeight;
        const glm::vec3 mirror = shadeReference(s, kFrontView.eye, lights, settings.ambient, true, settings.lightModel);
        const float* p = naive.hdr.at(kWidth / 2, kHeight / 2);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], mirror[k], 1e-4f + 1e-4f * mirror[k]) << c.name << " channel " << k;
    }
}

struct ClearcoatCase {
    const char* name;
    float factor, roughness;        // the extension's factors
    std::array<std::uint8_t, 4> coatTexel, roughnessTexel, normalTexel;  // {0,0,0,0}: no such map
    glm::vec3 emissive;
    float clearcoat, clearcoatRoughness;  // what the mirror takes: factor x map
    glm::vec3 clearcoatNormal;
};

// The tangent-space texel's normal on the test's quad (N = +z, T = +x, B = +y), scale 1.
glm::vec3 quadNormalFromTexel(std::array<std::uint8_t, 4> t) {
    return glm::normalize(glm::vec3(t[0], t[1], t[2]) / 255.0f * 2.0f - 1.0f);
}

// Quads under KHR_materials_clearcoat (factors, each map, a tilted coat normal over the plain one,
// an emissive under the coat): every method holds to naive, and the middle pixel to the CPU mirror;
// a clearcoatFactor of 0 compiles nothing in and leaves the frame as it was without the extension.
TEST_F(GltfMaterialExtensions, ClearcoatMatchesNaiveAndTheCpuMirror) {
    const std::array<std::uint8_t, 4> none{0, 0, 0, 0}, tilted{200, 128, 230, 255};
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    const std::vector<ClearcoatCase> cases = {
        {"smooth coat", 1.0f, 0.05f, none, none, none, glm::vec3(0.0f), 1.0f, 0.05f, up},
        {"half coat, rough", 0.5f, 0.6f, none, none, none, glm::vec3(0.0f), 0.5f, 0.6f, up},
        {"maps", 0.9f, 0.8f, {153, 0, 0, 255}, {0, 51, 0, 255}, none, glm::vec3(0.0f), 0.9f * 153.0f / 255.0f,
         0.8f * 51.0f / 255.0f, up},
        {"coat normal map", 1.0f, 0.1f, none, none, tilted, glm::vec3(0.0f), 1.0f, 0.1f, quadNormalFromTexel(tilted)},
        {"emissive under the coat", 1.0f, 0.2f, none, none, none, glm::vec3(0.5f, 0.2f, 0.1f), 1.0f, 0.2f, up},
    };
    const glm::vec3 base(0.7f, 0.1f, 0.1f);
    const std::vector<float> tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
    for (const ClearcoatCase& c : cases) {
        Gltf g;
        json coat = {{"clearcoatFactor", c.factor}, {"clearcoatRoughnessFactor", c.roughness}};
        if (c.coatTexel != none) coat["clearcoatTexture"] = {{"index", addFlatTexture(g, c.coatTexel)}};
        if (c.roughnessTexel != none) coat["clearcoatRoughnessTexture"] = {{"index", addFlatTexture(g, c.roughnessTexel)}};
        if (c.normalTexel != none) coat["clearcoatNormalTexture"] = {{"index", addFlatTexture(g, c.normalTexel)}};
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
                                                                           {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}},
                                                 {"emissiveFactor", {c.emissive.r, c.emissive.g, c.emissive.b}},
                                                 {"extensions", {{"KHR_materials_clearcoat", coat}}}});
        g.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
        const json extra = {{"TANGENT", g.accessor(g.view(tangents.data(), tangents.size() * 4), kFloat, 4, "VEC4")}};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, material, extra)}, "clearcoat");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_CLEARCOAT) << c.name;
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_CLEARCOAT_MAP) != 0, c.coatTexel != none || c.roughnessTexel != none || c.normalTexel != none)
            << c.name;
        const std::vector<Light> lights = testLights();
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);

        SurfaceSample s = middlePixelSample(base, 0.0f, 0.5f);
        s.emissive = c.emissive;
        s.clearcoat = c.clearcoat;
        s.clearcoatRoughness = c.clearcoatRoughness;
        s.clearcoatNormal = c.clearcoatNormal;
        SurfaceSample uncoated = s;
        uncoated.clearcoat = 0.0f;
        expectMirrorPixelShowingTheExtension(naive, s, uncoated, lights, settings, c.name);
    }

    // clearcoatFactor 0 (with a map) is no coat: nothing compiles in, the frame is the plain material's.
    expectSwitchedOffExtensionDrawsThePlainMaterial(
        base,
        [](Gltf& g) {
            return json{{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.0}, {"clearcoatTexture", {{"index", addFlatTexture(g, {255, 0, 0, 255})}}}}}};
        },
        ML_FEATURE_CLEARCOAT | ML_FEATURE_CLEARCOAT_MAP, "clearcoatFactor 0");
}

// A spec-gloss quad (diffuse and specular-glossiness maps, factors) and the same material converted
// by hand to metallic-roughness + KHR_materials_ior 0 + KHR_materials_specular: the same pixels in
// every method, and the middle pixel what the CPU mirror gives for the spec-gloss material itself.
TEST_F(GltfMaterialExtensions, SpecularGlossinessMatchesItsConversionByHand) {
    const glm::vec4 diffuse(0.8f, 0.6f, 0.5f, 1.0f);
    const glm::vec3 specular(0.9f, 0.5f, 0.3f);
    const float glossiness = 0.7f;
    const std::array<std::uint8_t, 4> diffuseTexel{200, 230, 150, 255}, specGlossTexel{180, 255, 90, 191};
    // The roughness the hand conversion stores: 1 - glossinessFactor x A, in a map's G channel.
    const auto roughnessByte = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - glossiness * specGlossTexel[3] / 255.0)));

    const auto file = [&](bool specGloss, bool maps) {
        Gltf g;
        const int diffuseMap = maps ? addFlatTexture(g, diffuseTexel) : -1;
        const int sgMap = maps ? addFlatTexture(g, specGlossTexel) : -1;
        json material;
        if (specGloss) {
            json sg = {{"diffuseFactor", {diffuse.r, diffuse.g, diffuse.b, diffuse.a}},
                       {"specularFactor", {specular.r, specular.g, specular.b}},
                       {"glossinessFactor", glossiness}};
            if (maps) {
                sg["diffuseTexture"] = {{"index", diffuseMap}};
                sg["specularGlossinessTexture"] = {{"index", sgMap}};
            }
            material = {{"extensions", {{"KHR_materials_pbrSpecularGlossiness", sg}}}};
            g.doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
        } else {
            json pbr = {{"baseColorFactor", {diffuse.r, diffuse.g, diffuse.b, diffuse.a}}, {"metallicFactor", 0.0},
                        {"roughnessFactor", maps ? 1.0 : 1.0 - glossiness}};
            json spec = {{"specularFactor", 1.0}, {"specularColorFactor", {specular.r, specular.g, specular.b}}};
            if (maps) {
                pbr["baseColorTexture"] = {{"index", diffuseMap}};
                pbr["metallicRoughnessTexture"] = {{"index", addFlatTexture(g, {0, roughnessByte, 0, 255})}};
                spec["specularColorTexture"] = {{"index", sgMap}};
            }
            material = {{"pbrMetallicRoughness", pbr},
                        {"extensions", {{"KHR_materials_ior", {{"ior", 0.0}}}, {"KHR_materials_specular", spec}}}};
            g.doc["extensionsUsed"] = {"KHR_materials_ior", "KHR_materials_specular"};
        }
        const int m = g.add("materials", material);
        return writeAndLoad(g, {square(g, 0.0f, 2.5f, m)}, specGloss ? "specgloss" : "by-hand");
    };
    for (bool maps : {false, true}) {
        const std::string label = maps ? "spec-gloss maps" : "spec-gloss factors";
        const Scene specGloss = file(true, maps), byHand = file(false, maps);
        const std::vector<Light> lights = testLights();
        const FrameSettings settings = test::smallFrame(specGloss, kFrontView, kWidth, kHeight);
        FrameRenderer converted(specGloss, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(converted, label);
        FrameRenderer reference(byHand, lights, settings);
        const test::ReferenceFrame hand = test::expectClusteredVariantsMatchNaive(reference, label + " by hand");
        writePng((test::testOutputDir() / (test::testNameOf(label) + ".png")).string(), naive.ldr);
        // Within 1/255 of the hand conversion, every pixel.
        ASSERT_EQ(naive.ldr.pixels.size(), hand.ldr.pixels.size());
        int worst = 0;
        for (std::size_t i = 0; i < naive.ldr.pixels.size(); ++i)
            worst = std::max(worst, std::abs(int(naive.ldr.pixels[i]) - int(hand.ldr.pixels[i])));
        EXPECT_LE(worst, 1) << label;

        // And, for the factors, the mirror of the spec-gloss material read as the extension means
        // it. (With a metallic-roughness map the GPU's highlight is ~1e-3 off the mirror on
        // llvmpipe whichever file feeds it, so the maps are held to the conversion by hand only.)
        if (maps) continue;
        SurfaceSample s = middlePixelSample(glm::vec3(diffuse), 0.0f, 1.0f - glossiness);
        s.specularF0 = specular;
        s.specularWeight = 1.0f;
        const glm::vec3 mirror = shadeReference(s, kFrontView.eye, lights, settings.ambient, true, settings.lightModel);
        const float* p = naive.hdr.at(kWidth / 2, kHeight / 2);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p[k], mirror[k], 1e-4f + 1e-4f * mirror[k]) << label << " channel " << k;
    }
}

// A two-variant file: a quad mapped to green ("Leaf") and blue ("Sea") in front of a red wall
// without mappings. Each variant draws the quad in its colour in every method, to the float what a
// file drawing that material directly gives, and leaves the wall as it was.
TEST_F(GltfMaterialExtensions, EachVariantDrawsItsMaterial) {
    const glm::vec4 colours[] = {{0.8f, 0.1f, 0.1f, 1.0f}, {0.1f, 0.8f, 0.1f, 1.0f}, {0.1f, 0.1f, 0.8f, 1.0f}};
    // mapped < 0: the quad has no mappings and draws material `quadMaterial` (the direct reference).
    const auto file = [&](bool mapped, int quadMaterial) {
        Gltf g;
        for (const glm::vec4& c : colours) colourMaterial(g, c, "OPAQUE");
        json quad = square(g, 0.0f, 1.0f, quadMaterial);
        if (mapped) {
            g.doc["extensionsUsed"] = {"KHR_materials_variants"};
            g.doc["extensions"]["KHR_materials_variants"]["variants"] = json::array({{{"name", "Leaf"}}, {{"name", "Sea"}}});
            quad["extensions"]["KHR_materials_variants"]["mappings"] =
                json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}});
        }
        return writeAndLoad(g, {square(g, -0.5f, 3.0f, 0), quad}, mapped ? "variants" : "direct");
    };
    const std::vector<Light> lights = testLights();
    const Scene loaded = file(true, 0);
    ASSERT_EQ(loaded.materialVariants.names.size(), 2u);
    std::vector<float> wall;
    for (int chosen = 0; chosen < 3; ++chosen) {  // 0: default, 1: Leaf, 2: Sea
        const std::string label = chosen == 0 ? "variant default" : "variant " + loaded.materialVariants.names[chosen - 1];
        Scene scene = loaded;
        applyMaterialVariant(scene, chosen == 0 ? std::nullopt : std::optional<std::size_t>(chosen - 1));
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, label);
        writePng((test::testOutputDir() / (test::testNameOf(label) + ".png")).string(), naive.ldr);

        const float* quad = naive.hdr.at(kWidth / 2, kHeight / 2);
        const int brightest = int(std::max_element(quad, quad + 3) - quad);
        EXPECT_EQ(brightest, chosen) << label << ": the quad is not in its material's colour";
        const float* w = naive.hdr.at(kWidth / 2 - 60, kHeight / 2);
        if (chosen == 0) wall.assign(w, w + 3);
        EXPECT_EQ(std::vector<float>(w, w + 3), wall) << label << ": the wall changed";

        const Scene direct = file(false, chosen);
        FrameRenderer directRenderer(direct, lights, test::smallFrame(direct, kFrontView, kWidth, kHeight));
        const test::ReferenceFrame expected = test::renderReference(directRenderer, 0);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(quad[k], expected.hdr.at(kWidth / 2, kHeight / 2)[k]) << label << " channel " << k;
    }
}

struct SheenCase {
    const char* name;
    glm::vec3 colorFactor;
    float roughnessFactor;
    std::array<std::uint8_t, 4> colorTexel, roughnessTexel;  // {0,0,0,0}: no such map
    float clearcoat;                                         // 0: no coat over the sheen
    glm::vec3 sheenColor;                                    // what the mirror takes: factor x map
    float sheenRoughness;
};

// Quads under KHR_materials_sheen (the colour alone, rough, both maps, under a clear coat): every
// method holds to naive, and the middle pixel to the CPU mirror; a sheenColorFactor of 0 compiles
// nothing in and leaves the frame as it was without the extension.
TEST_F(GltfMaterialExtensions, SheenMatchesNaiveAndTheCpuMirror) {
    const std::array<std::uint8_t, 4> none{0, 0, 0, 0}, colorTexel{200, 150, 90, 255}, roughnessTexel{0, 0, 0, 153};
    const glm::vec3 mapped = glm::vec3(1.0f, 0.8f, 0.6f) *
                             glm::vec3(srgbToLinear(colorTexel[0]), srgbToLinear(colorTexel[1]), srgbToLinear(colorTexel[2]));
    const std::vector<SheenCase> cases = {
        {"colour factor only", glm::vec3(0.8f, 0.6f, 0.9f), 0.0f, none, none, 0.0f, glm::vec3(0.8f, 0.6f, 0.9f), 0.0f},
        {"rough", glm::vec3(0.9f), 0.8f, none, none, 0.0f, glm::vec3(0.9f), 0.8f},
        {"both maps", glm::vec3(1.0f, 0.8f, 0.6f), 0.9f, colorTexel, roughnessTexel, 0.0f, mapped, 0.9f * 153.0f / 255.0f},
        {"under a clear coat", glm::vec3(0.7f), 0.5f, none, none, 1.0f, glm::vec3(0.7f), 0.5f},
    };
    const glm::vec3 base(0.2f, 0.3f, 0.6f);
    for (const SheenCase& c : cases) {
        Gltf g;
        json sheen = {{"sheenColorFactor", {c.colorFactor.r, c.colorFactor.g, c.colorFactor.b}}, {"sheenRoughnessFactor", c.roughnessFactor}};
        if (c.colorTexel != none) sheen["sheenColorTexture"] = {{"index", addFlatTexture(g, c.colorTexel)}};
        if (c.roughnessTexel != none) sheen["sheenRoughnessTexture"] = {{"index", addFlatTexture(g, c.roughnessTexel)}};
        json extensions = {{"KHR_materials_sheen", sheen}};
        if (c.clearcoat > 0.0f) extensions["KHR_materials_clearcoat"] = {{"clearcoatFactor", c.clearcoat}, {"clearcoatRoughnessFactor", 0.2}};
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
                                                                           {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}},
                                                 {"extensions", extensions}});
        g.doc["extensionsUsed"] = {"KHR_materials_sheen", "KHR_materials_clearcoat"};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, material)}, "sheen");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_SHEEN) << c.name;
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_SHEEN_MAP) != 0, c.colorTexel != none || c.roughnessTexel != none) << c.name;
        // A light low over the quad too, where the sheen's albedo (its (1 - N.L)^3 term) and lobe show.
        std::vector<Light> lights = testLights();
        lights.push_back(Light{{2.5f, 0.4f, 0.3f}, 8.0f, {4.0f, 3.0f, 2.0f}});
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);

        SurfaceSample s = middlePixelSample(base, 0.0f, 0.5f);
        s.clearcoat = c.clearcoat;
        s.clearcoatRoughness = 0.2f;
        s.clearcoatNormal = s.normal;
        s.sheenColor = c.sheenColor;
        s.sheenRoughness = c.sheenRoughness;
        SurfaceSample plain = s;
        plain.sheenColor = glm::vec3(0.0f);
        expectMirrorPixelShowingTheExtension(naive, s, plain, lights, settings, c.name);
    }

    // sheenColorFactor 0 (with a map and a roughness) is no sheen: nothing compiles in, the frame is
    // the plain material's.
    expectSwitchedOffExtensionDrawsThePlainMaterial(
        base,
        [](Gltf& g) {
            return json{{"KHR_materials_sheen", {{"sheenRoughnessFactor", 0.5},
                                                 {"sheenColorTexture", {{"index", addFlatTexture(g, {255, 255, 255, 255})}}}}}};
        },
        ML_FEATURE_SHEEN | ML_FEATURE_SHEEN_MAP, "sheenColorFactor 0");
}

struct AnisotropyCase {
    const char* name;
    float strength, rotation;                 // the extension's factors
    std::array<std::uint8_t, 4> anisotropyTexel, normalTexel;  // {0,0,0,0}: no such map
};

// Quads under KHR_materials_anisotropy (strength 0.6 turned by a rotation, its map's direction and
// strength, full strength under a normal map so that the normal the lobe turns about is not the one
// B_a is made from) lit by a point, a spot and a sun, the file without TANGENT (the loader makes
// them): every method, the exact G-buffer's seventh target among them, holds to naive, and the
// middle pixel to the CPU mirror. A strength of 0 compiles nothing in and leaves the frame as it
// was without the extension; a map whose blue is 0 leaves the lobe isotropic to the bit.
TEST_F(GltfMaterialExtensions, AnisotropyMatchesNaiveAndTheCpuMirror) {
    const std::array<std::uint8_t, 4> none{0, 0, 0, 0};
    const std::vector<AnisotropyCase> cases = {
        {"strength 0.6 turned 0.7", 0.6f, 0.7f, none, none},
        {"map", 0.8f, -0.4f, {230, 60, 170, 255}, none},
        {"full strength under a normal map", 1.0f, 1.9f, none, {150, 110, 240, 255}},
    };
    const glm::vec3 base(0.7f, 0.55f, 0.4f);
    std::vector<Light> lights = testLights();
    Light spot{{-0.8f, 0.6f, 1.5f}, 9.0f, {3.0f, 2.5f, 2.0f}};
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(glm::vec3(0.6f, -0.5f, -1.5f));
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.9f;
    lights.push_back(spot);
    lights.push_back(Light{{2.2f, -0.6f, 0.5f}, 8.0f, {3.0f, 3.0f, 4.0f}});  // low over the quad: the stretched lobe
    for (const AnisotropyCase& c : cases) {
        Gltf g;
        json anisotropy = {{"anisotropyStrength", c.strength}, {"anisotropyRotation", c.rotation}};
        if (c.anisotropyTexel != none) anisotropy["anisotropyTexture"] = {{"index", addFlatTexture(g, c.anisotropyTexel)}};
        json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.3}}},
                         {"extensions", {{"KHR_materials_anisotropy", anisotropy}}}};
        if (c.normalTexel != none) material["normalTexture"] = {{"index", addFlatTexture(g, c.normalTexel)}};
        g.doc["extensionsUsed"] = {"KHR_materials_anisotropy"};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, g.add("materials", material))}, "anisotropy");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_ANISOTROPY) << c.name;
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_ANISOTROPY_MAP) != 0, c.anisotropyTexel != none) << c.name;
        ASSERT_FALSE(scene.tangents.empty()) << c.name;
        // The square's generated frame: T along +x (u), B = w N x T along -y (v runs down the image).
        const glm::vec4 tangent = scene.tangents[0];
        EXPECT_NEAR(glm::distance(glm::vec3(tangent), glm::vec3(1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f) << c.name;
        EXPECT_EQ(tangent.w, -1.0f) << c.name;
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);
        writePng((test::testOutputDir() / (test::testNameOf(c.name) + ".png")).string(), naive.ldr);

        SurfaceSample s;
        s.position = middlePixelPoint();
        const glm::vec3 ng(0.0f, 0.0f, 1.0f);
        s.normal = ng;
        if (c.normalTexel != none) {  // the map's texel in that frame
            const glm::vec3 k = glm::vec3(c.normalTexel[0], c.normalTexel[1], c.normalTexel[2]) / 255.0f * 2.0f - 1.0f;
            s.normal = glm::normalize(glm::vec3(tangent) * k.x + glm::cross(ng, glm::vec3(tangent)) * tangent.w * k.y + ng * k.z);
        }
        s.baseColor = base;
        s.metallic = 0.5f;
        s.roughness = 0.3f;
        glm::vec2 direction(1.0f, 0.0f);
        s.anisotropyStrength = c.strength;
        if (c.anisotropyTexel != none) {
            direction = glm::vec2(c.anisotropyTexel[0], c.anisotropyTexel[1]) / 255.0f * 2.0f - 1.0f;
            s.anisotropyStrength *= c.anisotropyTexel[2] / 255.0f;
        }
        ASSERT_TRUE(anisotropyDirections(ng, tangent, direction, c.rotation, s.anisotropyT, s.anisotropyB));
        SurfaceSample plain = s;
        plain.anisotropyStrength = 0.0f;
        expectMirrorPixelShowingTheExtension(naive, s, plain, lights, settings, c.name);
    }

    // anisotropyStrength 0 (with a rotation and a map) is the isotropic lobe: nothing compiles in,
    // the frame is the plain material's.
    expectSwitchedOffExtensionDrawsThePlainMaterial(
        base,
        [](Gltf& g) {
            return json{{"KHR_materials_anisotropy", {{"anisotropyRotation", 0.5},
                                                      {"anisotropyTexture", {{"index", addFlatTexture(g, {255, 128, 255, 255})}}}}}};
        },
        ML_FEATURE_ANISOTROPY | ML_FEATURE_ANISOTROPY_MAP, "anisotropyStrength 0");

    // A map whose blue is 0 makes the strength 0 at every pixel with the lobe compiled in: each
    // method draws the plain material's frame to the bit (naive first, then each clustered variant).
    std::vector<std::vector<float>> frames[2];
    for (int withExtension = 0; withExtension < 2; ++withExtension) {
        Gltf g;
        json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.3}}}};
        if (withExtension)
            material["extensions"] = {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyRotation", 0.5},
                                                                    {"anisotropyTexture", {{"index", addFlatTexture(g, {255, 128, 0, 255})}}}}}};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, g.add("materials", material))}, "zero_strength_map");
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_ANISOTROPY) != 0, withExtension == 1);
        FrameRenderer renderer(scene, lights, test::smallFrame(scene, kFrontView, kWidth, kHeight));
        frames[withExtension].push_back(test::renderReference(renderer, 0).hdr.pixels);
        for (const test::ClusteredVariant& v : test::kClusteredVariants) {
            MethodSettings m;
            m.kind = v.kind;
            m.resolve = v.resolve;
            renderer.setMethod(m);
            renderer.render(0);
            frames[withExtension].push_back(test::readReference(renderer).hdr.pixels);
        }
    }
    for (std::size_t i = 0; i < frames[0].size(); ++i)
        EXPECT_EQ(frames[0][i], frames[1][i]) << (i == 0 ? "naive" : test::kClusteredVariants[i - 1].name)
                                              << ": a strength of 0 changed the frame";
}

// A scene whose anisotropic material has no tangent stream (the loader always makes one; a scene
// built otherwise may not): prepareFrame says in one line that it is lit isotropic, nothing of the
// lobe compiles in, and every method draws the plain material's frame to the bit.
TEST_F(GltfMaterialExtensions, AnisotropyWithoutTangentsIsLitIsotropicWithAWarning) {
    std::vector<float> frames[2];
    for (int withExtension = 0; withExtension < 2; ++withExtension) {
        Gltf g;
        json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.7, 0.55, 0.4, 1.0}}, {"metallicFactor", 0.5}, {"roughnessFactor", 0.3}}}};
        if (withExtension) material["extensions"] = {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyRotation", 0.7}}}};
        Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, g.add("materials", material))}, "no_tangents");
        ASSERT_EQ(scene.tangents.empty(), withExtension == 0);
        scene.tangents.clear();
        EXPECT_EQ(materialFeatures(scene) & (ML_FEATURE_ANISOTROPY | ML_FEATURE_NORMAL_MAP), 0u);
        app::FrameOptions o;
        o.scene = "no_tangents.glb";
        o.size = std::to_string(kWidth) + "x" + std::to_string(kHeight);
        const app::PreparedFrame prepared = app::prepareFrame(o, &scene);
        const auto warned = std::count_if(prepared.warnings.begin(), prepared.warnings.end(), [](const std::string& w) {
            return w.find("KHR_materials_anisotropy") != std::string::npos && w.find("isotropic") != std::string::npos;
        });
        EXPECT_EQ(warned, withExtension) << "one line where the lobe cannot be stretched";
        FrameRenderer renderer(scene, testLights(), test::smallFrame(scene, kFrontView, kWidth, kHeight));
        frames[withExtension] = test::expectClusteredVariantsMatchNaive(renderer, "no tangents").hdr.pixels;
    }
    EXPECT_EQ(frames[0], frames[1]) << "without tangents the lobe is not the plain material's";
}

struct IridescenceCase {
    const char* name;
    float factor, ior, thicknessMinimum, thicknessMaximum;
    std::array<std::uint8_t, 4> texel;  // {0,0,0,0}: no maps; else the strength map (R), and the thickness map (G)
    bool thicknessMap;                  // ...from the same image
    std::array<std::uint8_t, 4> baseTexel;  // {0,0,0,0}: no base colour map
    float metallic, baseIor;            // baseIor 0: no KHR_materials_ior
    float iridescence, thickness;       // what the mirror takes: factor x R, mix(minimum, maximum, G)
};

// Quads under KHR_materials_iridescence (a fixed thickness, a metal, both maps from one image, over
// a base of ior 2): every method holds to naive with a point, a spot and a directional light, and
// the middle pixel to the CPU mirror; an iridescenceFactor of 0 compiles nothing in and leaves the
// frame as it was without the extension.
TEST_F(GltfMaterialExtensions, IridescenceMatchesNaiveAndTheCpuMirror) {
    const std::array<std::uint8_t, 4> none{0, 0, 0, 0}, texel{200, 128, 0, 255}, baseTexel{255, 0, 255, 255};
    const std::vector<IridescenceCase> cases = {
        {"factor 1, thickness 400", 1.0f, 1.3f, 100.0f, 400.0f, none, false, none, 0.0f, 0.0f, 1.0f, 400.0f},
        {"metal, film ior 1.8", 1.0f, 1.8f, 100.0f, 300.0f, none, false, none, 1.0f, 0.0f, 1.0f, 300.0f},
        {"both maps, one image", 0.8f, 1.33f, 200.0f, 600.0f, texel, true, none, 0.0f, 0.0f, 0.8f * 200.0f / 255.0f,
         200.0f + (600.0f - 200.0f) * (128.0f / 255.0f)},
        {"over ior 2", 1.0f, 1.33f, 100.0f, 250.0f, none, false, none, 0.0f, 2.0f, 1.0f, 250.0f},
        // The strength map alone (its unit's other slot empty) beside a base colour map (unit 0,
        // which the extended record's slots must leave alone; 0 and 255, which every sRGB decode
        // gives exactly, so that the white a lost binding falls back to shows): the thickness is
        // the maximum.
        {"strength map, base colour map", 1.0f, 1.5f, 100.0f, 350.0f, texel, false, baseTexel, 0.0f, 0.0f, 200.0f / 255.0f, 350.0f},
    };
    const glm::vec3 base(0.2f, 0.3f, 0.6f);
    for (const IridescenceCase& c : cases) {
        Gltf g;
        json film = {{"iridescenceFactor", c.factor}, {"iridescenceIor", c.ior}, {"iridescenceThicknessMinimum", c.thicknessMinimum},
                     {"iridescenceThicknessMaximum", c.thicknessMaximum}};
        if (c.texel != none) {
            const int texture = addFlatTexture(g, c.texel);
            film["iridescenceTexture"] = {{"index", texture}};
            if (c.thicknessMap) film["iridescenceThicknessTexture"] = {{"index", texture}};
        }
        json extensions = {{"KHR_materials_iridescence", film}};
        if (c.baseIor > 0.0f) extensions["KHR_materials_ior"] = {{"ior", c.baseIor}};
        json pbr = {{"baseColorFactor", {base.r, base.g, base.b, 1.0}}, {"metallicFactor", c.metallic}, {"roughnessFactor", 0.3}};
        if (c.baseTexel != none) pbr["baseColorTexture"] = {{"index", addFlatTexture(g, c.baseTexel)}};
        const int material = g.add("materials", {{"pbrMetallicRoughness", pbr}, {"extensions", extensions}});
        g.doc["extensionsUsed"] = {"KHR_materials_iridescence", "KHR_materials_ior"};
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, material)}, "iridescence");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_IRIDESCENCE) << c.name;
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_IRIDESCENCE_MAP) != 0, c.texel != none) << c.name;
        // A spot over the quad too: every light type goes through the film.
        std::vector<Light> lights = testLights();
        Light spot{{-0.5f, -0.3f, 1.5f}, 8.0f, {3.0f, 2.5f, 2.0f}};
        spot.type = LightType::Spot;
        spot.direction = glm::vec3(0.2f, 0.1f, -1.0f);
        spot.innerConeAngle = 0.3f;
        spot.outerConeAngle = 0.9f;
        lights.push_back(spot);
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);

        const glm::vec3 mappedBase =
            c.baseTexel == none ? base
                                : base * glm::vec3(srgbToLinear(c.baseTexel[0]), srgbToLinear(c.baseTexel[1]), srgbToLinear(c.baseTexel[2]));
        SurfaceSample s = middlePixelSample(mappedBase, c.metallic, 0.3f);
        if (c.baseIor > 0.0f) s.specularF0 = glm::vec3(dielectricF0(c.baseIor));
        s.iridescence = c.iridescence;
        s.iridescenceThickness = c.thickness;
        s.iridescenceIor = c.ior;
        SurfaceSample plain = s;
        plain.iridescence = 0.0f;
        expectMirrorPixelShowingTheExtension(naive, s, plain, lights, settings, c.name);
    }

    // iridescenceFactor 0 (with maps, a thickness and an ior) is no film: nothing compiles in, the
    // frame is the plain material's to the bit.
    expectSwitchedOffExtensionDrawsThePlainMaterial(
        base,
        [](Gltf& g) {
            const int texture = addFlatTexture(g, {255, 255, 255, 255});
            return json{{"KHR_materials_iridescence", {{"iridescenceIor", 1.8},
                                                       {"iridescenceThicknessMaximum", 500.0},
                                                       {"iridescenceTexture", {{"index", texture}}},
                                                       {"iridescenceThicknessTexture", {{"index", texture}}}}}};
        },
        ML_FEATURE_IRIDESCENCE | ML_FEATURE_IRIDESCENCE_MAP, "iridescenceFactor 0");
}

struct TransmissionCase {
    const char* name;
    float factor, roughness, ior;         // ior 0: no KHR_materials_ior (1.5)
    std::array<std::uint8_t, 4> texel;    // {0,0,0,0}: no maps; else the transmission map (R) and, with a volume, the thickness map (G)
    float thickness, distance;            // thickness 0: no KHR_materials_volume
    glm::vec3 attenuation;
    float transmission, mappedThickness;  // what the mirror takes: factor x R, thickness x G
    bool mirrored;                        // the middle pixel held to the CPU mirror (not where the volume refracts it)
};

// The wall's point under the middle pixel, `z` behind the quad's plane (the pixel's ray continued).
glm::vec3 middlePixelPointAt(float z) {
    const glm::vec3 eye = kFrontView.eye;
    return eye + (middlePixelPoint() - eye) * ((eye.z - z) / eye.z);
}

// Quads under KHR_materials_transmission (thin-walled at ior 1 and 1.5, rough and smooth, its map)
// and KHR_materials_volume (tinted over a thickness and its map; refracting) in front of a lit wall,
// lit from the front by a point light and a sun and from behind by a point light between quad and
// wall: every method holds to naive, and the middle pixel to the CPU mirror, with the wall's own
// mirrored radiance as what the quad sees behind it. A transmissionFactor of 0 compiles nothing in
// and leaves the frame as it was without the extension; --msaa refuses a transmissive scene.
TEST_F(GltfMaterialExtensions, TransmissionMatchesNaiveAndTheCpuMirror) {
    const std::array<std::uint8_t, 4> none{0, 0, 0, 0}, texel{128, 200, 0, 255};
    const glm::vec3 noTint(1.0f);
    const std::vector<TransmissionCase> cases = {
        {"thin, ior 1, rough", 1.0f, 0.4f, 1.0f, none, 0.0f, 0.0f, noTint, 1.0f, 0.0f, true},
        {"thin, ior 1.5, smooth", 1.0f, 0.0f, 0.0f, none, 0.0f, 0.0f, noTint, 1.0f, 0.0f, true},
        {"half by its map", 1.0f, 0.3f, 1.0f, texel, 0.0f, 0.0f, noTint, 128.0f / 255.0f, 0.0f, true},
        {"tinted volume, ior 1", 0.9f, 0.2f, 1.0f, none, 0.3f, 0.6f, {0.4f, 0.7f, 0.9f}, 0.9f, 0.3f, true},
        {"volume's thickness map", 1.0f, 0.2f, 1.0f, texel, 0.5f, 0.4f, {0.3f, 0.6f, 0.9f}, 128.0f / 255.0f, 0.5f * 200.0f / 255.0f, true},
        {"refracting volume, ior 1.5", 1.0f, 0.0f, 1.5f, none, 0.3f, 1.0f, {0.5f, 0.8f, 0.9f}, 1.0f, 0.3f, false},
    };
    const glm::vec3 base(0.9f, 0.7f, 0.5f), wallBase(0.8f, 0.3f, 0.2f);
    constexpr float kWallZ = -0.5f, kWallRoughness = 0.6f;
    std::vector<Light> lights = testLights();
    lights.push_back(Light{{0.2f, -0.1f, -0.25f}, 4.0f, {3.0f, 2.0f, 1.0f}});  // behind the quad, before the wall
    for (const TransmissionCase& c : cases) {
        Gltf g;
        json transmission = {{"transmissionFactor", c.factor}};
        json volume = {{"thicknessFactor", c.thickness}, {"attenuationDistance", c.distance},
                       {"attenuationColor", {c.attenuation.r, c.attenuation.g, c.attenuation.b}}};
        if (c.texel != none) {
            const int texture = addFlatTexture(g, c.texel);
            transmission["transmissionTexture"] = {{"index", texture}};
            volume["thicknessTexture"] = {{"index", texture}};
        }
        json extensions = {{"KHR_materials_transmission", transmission}};
        if (c.thickness > 0.0f) extensions["KHR_materials_volume"] = volume;
        if (c.ior > 0.0f) extensions["KHR_materials_ior"] = {{"ior", c.ior}};
        const int quad = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
                                                                       {"metallicFactor", 0.0},
                                                                       {"roughnessFactor", c.roughness}}},
                                             {"extensions", extensions}});
        const int wall = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {wallBase.r, wallBase.g, wallBase.b, 1.0}},
                                                                       {"metallicFactor", 0.0},
                                                                       {"roughnessFactor", kWallRoughness}}}});
        g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior"};
        const Scene scene = writeAndLoad(g, {square(g, kWallZ, 3.0f, wall), square(g, 0.0f, 1.0f, quad)}, "transmission");
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_TRANSMISSION) << c.name;
        ASSERT_TRUE(materialFeatures(scene) & ML_FEATURE_BLEND) << c.name << ": drawn as glass";
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_TRANSMISSION_MAP) != 0, c.texel != none) << c.name;
        const FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
        FrameRenderer renderer(scene, lights, settings);
        const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, c.name);
        if (!c.mirrored) continue;

        SurfaceSample wallPoint = middlePixelSample(wallBase, 0.0f, kWallRoughness);
        wallPoint.position = middlePixelPointAt(kWallZ);
        SurfaceSample s = middlePixelSample(base, 0.0f, c.roughness);
        if (c.ior > 0.0f) s.specularF0 = glm::vec3(dielectricF0(c.ior));
        s.transmission = c.transmission;
        s.thickness = c.mappedThickness;
        s.attenuationDistance = c.thickness > 0.0f ? c.distance : 0.0f;
        s.attenuationColor = c.attenuation;
        s.behind = shadeReference(wallPoint, kFrontView.eye, lights, settings.ambient, true, settings.lightModel);
        SurfaceSample opaque = s;
        opaque.transmission = 0.0f;
        expectMirrorPixelShowingTheExtension(naive, s, opaque, lights, settings, c.name);
    }

    // transmissionFactor 0 (with a map and a volume) is opaque: nothing compiles in, not even the
    // transparent pass, and the frame is the plain material's to the bit.
    expectSwitchedOffExtensionDrawsThePlainMaterial(
        base,
        [](Gltf& g) {
            const int texture = addFlatTexture(g, {255, 255, 255, 255});
            return json{{"KHR_materials_transmission", {{"transmissionTexture", {{"index", texture}}}}},
                        {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 1.0}}}};
        },
        ML_FEATURE_TRANSMISSION | ML_FEATURE_TRANSMISSION_MAP | ML_FEATURE_BLEND, "transmissionFactor 0");

    // The forward pass (--msaa) does not model transmission: refused in one line that says why.
    Gltf g;
    const int quad = g.add("materials", {{"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission"};
    const Scene scene = writeAndLoad(g, {square(g, 0.0f, 1.0f, quad)}, "transmission_msaa");
    FrameSettings settings = test::smallFrame(scene, kFrontView, kWidth, kHeight);
    settings.method.msaa = 4;
    try {
        FrameRenderer renderer(scene, testLights(), settings);
        ADD_FAILURE() << "--msaa 4 drew a transmissive scene";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("KHR_materials_transmission"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--msaa 4"), std::string::npos) << e.what();
    }
}

// Naive draws a frame past one draw's pixel-lights in scissored bands; a transmissive surface sees
// the opaque frame beyond its own band (a refracting, rough volume: the ray leaves the volume
// elsewhere and the mip chain blurs across rows), so every band's opaque frame comes first and the
// banded frame is one draw's to the bit (drawing each band's glass after its own opaque band drew
// seams at the bands' edges, up to 209/255 on AttenuationTest at 1280x720).
TEST_F(GltfMaterialExtensions, TransmissionSeesTheWholeOpaqueFrameWhenNaiveDrawsInBands) {
    Gltf g;
    const int quad = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.6, 1.0}}, {"roughnessFactor", 0.6}, {"metallicFactor", 0.0}}},
                                         {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                                         {"KHR_materials_volume", {{"thicknessFactor", 0.8}}},
                                                         {"KHR_materials_ior", {{"ior", 1.8}}}}}});
    const int wall = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.3, 0.2, 1.0}}, {"metallicFactor", 0.0}}}});
    g.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior"};
    const Scene scene = writeAndLoad(g, {square(g, -0.5f, 3.0f, wall), square(g, 0.0f, 1.2f, quad)}, "transmission_bands");
    std::vector<Light> lights = testLights();
    lights.push_back(Light{{-0.6f, 0.5f, -0.3f}, 3.0f, {4.0f, 1.0f, 0.5f}});  // a spot of colour on the wall, behind the quad
    const FrameSettings s = test::smallFrame(scene, kFrontView, kWidth, kHeight);
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    PassTimer timer;
    const FrameContext ctx = renderer.frameContext(timer);
    const auto draw = [&](double pixelLightsPerDraw) {
        NaiveForward naive(renderer.scene().materialFeatures(), s.method.clustering, {}, pixelLightsPerDraw);
        naive.render(ctx);
        return renderer.readHdr().pixels;
    };
    const std::vector<float> once = draw(kNaivePixelLightsPerDraw);
    const std::vector<float> banded = draw(double(kWidth) * kHeight * double(lights.size()) / 4.5);  // five bands
    ASSERT_EQ(banded.size(), once.size());
    EXPECT_TRUE(banded == once) << "the banded frame differs from one draw's";
}

// Every extension's lobe in one scene (a tile each: clear coat, sheen, anisotropy, iridescence,
// specular, and a plain one): the exact G-buffer holds all eight targets at once, each tile flagged
// in its own sign bit, and every method draws naive's frame.
TEST_F(GltfMaterialExtensions, EveryLobeInOneSceneMatchesNaive) {
    Gltf g;
    const auto material = [&](const json& extensions) {
        json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.4, 0.3, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.4}}}};
        if (!extensions.empty()) m["extensions"] = extensions;
        return g.add("materials", m);
    };
    const std::vector<int> materials = {
        material({{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}, {"clearcoatRoughnessFactor", 0.1}}}}),
        material({{"KHR_materials_sheen", {{"sheenColorFactor", {0.9, 0.2, 0.2}}, {"sheenRoughnessFactor", 0.5}}}}),
        material({{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.7}, {"anisotropyRotation", 0.5}}}}),
        material({{"KHR_materials_iridescence", {{"iridescenceFactor", 1.0}, {"iridescenceThicknessMaximum", 400.0}}}}),
        material({{"KHR_materials_ior", {{"ior", 2.0}}}}),
        material(json::object()),
    };
    g.doc["extensionsUsed"] = {"KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_anisotropy",
                               "KHR_materials_iridescence", "KHR_materials_ior"};
    // A 3 x 2 grid of tiles facing the camera, 1.2 across.
    std::vector<json> tiles;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const float x = -1.4f + 1.4f * float(i % 3), y = i < 3 ? 0.7f : -0.7f, h = 0.6f;
        const json attributes = {{"POSITION", g.vec3({{x - h, y - h, 0}, {x + h, y - h, 0}, {x + h, y + h, 0}, {x - h, y + h, 0}})},
                                 {"NORMAL", g.vec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}})},
                                 {"TEXCOORD_0", g.vec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}})}};
        tiles.push_back(primitive(attributes, g.indices({0, 1, 2, 0, 2, 3}), materials[i]));
    }
    const Scene scene = writeAndLoad(g, tiles, "every_lobe");
    const std::uint32_t lobes = ML_FEATURE_CLEARCOAT | ML_FEATURE_SHEEN | ML_FEATURE_ANISOTROPY | ML_FEATURE_IRIDESCENCE | ML_FEATURE_SPECULAR;
    ASSERT_EQ(materialFeatures(scene) & lobes, lobes);
    EXPECT_EQ(gbufferExactTargets(materialFeatures(scene)), 8);
    FrameRenderer renderer(scene, testLights(), test::smallFrame(scene, kFrontView, kWidth, kHeight));
    const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, "every lobe");
    // Each tile is lit and differs from the plain one (the lobes are there, not dropped alike).
    const auto tilePixel = [&](std::size_t i) {
        const glm::vec3 centre(-1.4f + 1.4f * float(i % 3), i < 3 ? 0.7f : -0.7f, 0.0f);
        const float t = std::tan(glm::radians(30.0f)) * 4.0f;
        const int px = int((centre.x / (t * float(kWidth) / float(kHeight)) + 1.0f) * 0.5f * kWidth);
        const int py = int((1.0f - centre.y / t) * 0.5f * kHeight);
        const float* p = naive.hdr.at(px, py);
        return glm::vec3(p[0], p[1], p[2]);
    };
    const glm::vec3 plain = tilePixel(5);
    EXPECT_GT(plain.r, 0.0f);
    for (std::size_t i = 0; i + 1 < materials.size(); ++i) EXPECT_GT(glm::length(tilePixel(i) - plain), 1e-3f) << "tile " << i;
}

}  // namespace
}  // namespace ml
