// glTF material features on files the tests write, one small file per feature: alpha-tested
// cut-outs, normal maps (tangents given and generated), emissive, metallic-roughness and
// occlusion maps, texture transforms, TEXCOORD_1, COLOR_0 and samplers. Each is checked for what
// it should show, and every clustered method (both deferred resolves, the visibility buffer, both
// G-buffer layouts that store the material) is held to naive on it.
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "glsl/include/bindings.h"
#include "renderer/scene/material_features.h"
#include "tests/gpu/gpu_test.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;
using test::GpuTest;

constexpr int kWidth = 160, kHeight = 90;

// An RGBA8 image as an embedded PNG, and a texture of it with a sampler.
int addTexture(Gltf& g, int width, int height, const std::vector<std::uint8_t>& rgba, const json& sampler = json::object()) {
    const int image = g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(width, height, rgba))}});
    json texture = {{"source", image}};
    if (!sampler.empty()) texture["sampler"] = g.add("samplers", sampler);
    return g.add("textures", texture);
}

// An image from a function of the texel (x, y) giving RGBA bytes.
std::vector<std::uint8_t> pixels(int width, int height, const std::function<std::array<std::uint8_t, 4>(int, int)>& texel) {
    std::vector<std::uint8_t> out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const auto t = texel(x, y);
            out.insert(out.end(), t.begin(), t.end());
        }
    return out;
}

const json kNearest = {{"magFilter", 9728}, {"minFilter", 9728}};

// Renders naive, then holds every clustered method (and, for deferred, the standard G-buffer)
// to it within the accuracy contract. Returns naive's frame.
test::ReferenceFrame expectEveryMethodMatchesNaive(const Scene& scene, const std::vector<Light>& lights,
                                                   const std::string& label, const CameraPose& pose = kFrontView) {
    FrameRenderer renderer(scene, lights, test::smallFrame(scene, pose, kWidth, kHeight));
    const test::ReferenceFrame naive = test::expectClusteredVariantsMatchNaive(renderer, label);
    MethodSettings standard;
    standard.kind = MethodKind::Deferred;
    standard.gbuffer = GBufferFormat::Standard;
    renderer.setMethod(standard);
    renderer.render(0);
    test::expectWithinContract(renderer, naive, label + " deferred/standard", label + "_standard");
    return naive;
}

const std::vector<Light> kOneLight{{{0.3f, 0.2f, 3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}};

float luminance(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

class GltfMaterials : public GpuTest {};

// A red quad cut out by a checker of alpha 0 / 1 in front of a green wall: the wall shows through
// the cut-outs, the same pixels in every method; drawn OPAQUE the same quad hides the wall.
TEST_F(GltfMaterials, MaskedQuadShowsTheWallThroughItsCutOuts) {
    const auto countWallPixels = [&](const char* alphaMode, bool checkMethods) {
        Gltf g;
        const int checker = addTexture(g, 4, 4, pixels(4, 4, [](int x, int y) {
                                           return std::array<std::uint8_t, 4>{255, 255, 255, std::uint8_t((x + y) % 2 ? 0 : 255)};
                                       }),
                                       kNearest);
        const int wall = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.8, 0.1, 1.0}}, {"metallicFactor", 0.0}}}});
        json cut = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1.0}}, {"metallicFactor", 0.0},
                                              {"baseColorTexture", {{"index", checker}}}}},
                    {"alphaMode", alphaMode}};
        const int quad = g.add("materials", cut);
        const Scene scene = writeAndLoad(g, {square(g, 0.0f, 2.5f, wall), square(g, 1.0f, 1.0f, quad)}, std::string("masked_") + alphaMode);
        EXPECT_EQ((materialFeatures(scene) & ML_FEATURE_ALPHA_TEST) != 0, std::string(alphaMode) == "MASK");
        const test::ReferenceFrame naive = checkMethods ? expectEveryMethodMatchesNaive(scene, kOneLight, std::string("mask ") + alphaMode)
                                                        : test::ReferenceFrame{};
        FrameRenderer renderer(scene, kOneLight, test::smallFrame(scene, kFrontView, kWidth, kHeight));
        renderer.render(0);
        const FloatImage hdr = renderer.readHdr();
        // The quad's middle half on screen: the near quad (1 unit closer) spans about 59 % of the height.
        int wallPixels = 0, total = 0;
        for (int y = kHeight / 2 - 18; y < kHeight / 2 + 18; ++y)
            for (int x = kWidth / 2 - 18; x < kWidth / 2 + 18; ++x, ++total)
                if (hdr.at(x, y)[1] > hdr.at(x, y)[0]) ++wallPixels;
        return double(wallPixels) / double(total);
    };
    const double masked = countWallPixels("MASK", true);
    EXPECT_GT(masked, 0.4);  // half the checker's cells are cut
    EXPECT_LT(masked, 0.6);
    EXPECT_EQ(countWallPixels("OPAQUE", false), 0.0);
}

// A normal map whose left half tilts the normal towards +x and right half towards -x, lit from
// the +x side: the left half is brighter. Tangents given in the file and generated agree.
TEST_F(GltfMaterials, NormalMapTiltsTheLitPatternAndGeneratedTangentsAgree) {
    const auto build = [&](bool withTangents, const char* name) {
        Gltf g;
        // 0.6, 0, 0.8 encoded as (n + 1) / 2: the left half tilted towards +u (= +x here).
        const int map = addTexture(g, 8, 8, pixels(8, 8, [](int x, int) {
                                       const std::uint8_t r = x < 4 ? 204 : 51;
                                       return std::array<std::uint8_t, 4>{r, 128, 230, 255};
                                   }),
                                   kNearest);
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}},
                                                 {"normalTexture", {{"index", map}}}});
        json extra = json::object();
        if (withTangents) {
            // T along +u = +x; v runs down the image (-y), so B = cross(N, T) * w = +y * w needs w = -1.
            const std::vector<float> t = {1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1};
            extra["TANGENT"] = g.accessor(g.view(t.data(), t.size() * 4), kFloat, 4, "VEC4");
        }
        return writeAndLoad(g, {square(g, 0.0f, 2.0f, material, extra)}, name);
    };
    const Scene given = build(true, "normal_given");
    const Scene generated = build(false, "normal_generated");
    ASSERT_EQ(generated.tangents.size(), generated.vertices.size());
    for (const glm::vec4& t : generated.tangents) {
        EXPECT_NEAR(t.x, 1.0f, 1e-5f);
        EXPECT_EQ(t.w, -1.0f);
    }
    const std::vector<Light> fromRight{{{6.0f, 0.0f, 1.0f}, 20.0f, {4.0f, 4.0f, 4.0f}}};
    const test::ReferenceFrame a = expectEveryMethodMatchesNaive(given, fromRight, "normal map, given tangents");
    FrameRenderer renderer(generated, fromRight, test::smallFrame(generated, kFrontView, kWidth, kHeight));
    renderer.render(0);
    test::expectWithinContract(renderer, a, "normal map, generated against given tangents", "normal_generated");
    // Left of centre (tilted towards the light) against right of centre (tilted away), on the
    // same row at the same distance from the light's foot... nearly: the left is farther away.
    const float left = luminance(a.hdr.at(kWidth / 2 - 12, kHeight / 2));
    const float right = luminance(a.hdr.at(kWidth / 2 + 12, kHeight / 2));
    EXPECT_GT(left, 1.5f * right) << left << " " << right;
}

// An emissive quad and no lights: it glows (emissiveFactor x KHR_materials_emissive_strength x
// texture), the same in every method; the wall beside it stays at the ambient term only.
TEST_F(GltfMaterials, EmissiveQuadGlowsWithoutLights) {
    Gltf g;
    const int half = addTexture(g, 2, 1, {255, 255, 255, 255, 128, 128, 128, 255}, kNearest);  // left white, right 0.216 linear
    json glow = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.2, 0.2, 1.0}}, {"metallicFactor", 0.0}}},
                 {"emissiveFactor", {1.0, 0.5, 0.25}},
                 {"emissiveTexture", {{"index", half}}},
                 {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}};
    g.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const int material = g.add("materials", glow);
    const Scene scene = writeAndLoad(g, {square(g, 0.0f, 1.5f, material)}, "emissive");
    EXPECT_NE(materialFeatures(scene) & ML_FEATURE_EMISSIVE_MAP, 0u);
    const test::ReferenceFrame naive = expectEveryMethodMatchesNaive(scene, {}, "emissive");
    const float ambient = test::smallFrame(scene, kFrontView, kWidth, kHeight).ambient * (0.2f + 0.04f);
    const float* left = naive.hdr.at(kWidth / 2 - 10, kHeight / 2);
    const float* right = naive.hdr.at(kWidth / 2 + 10, kHeight / 2);
    EXPECT_NEAR(left[0], 2.0f + ambient, 1e-3f);
    EXPECT_NEAR(left[1], 1.0f + ambient, 1e-3f);
    EXPECT_NEAR(left[2], 0.5f + ambient, 1e-3f);
    EXPECT_NEAR(right[0], 2.0f * 0.2158f + ambient, 2e-3f);
    EXPECT_EQ(naive.hdr.at(2, 2)[0], 0.0f);  // background
}

// Metallic-roughness and occlusion maps: the left half metallic and fully occluded, the right half
// dielectric and open, against the shading model's formula at the pixel.
TEST_F(GltfMaterials, MetallicRoughnessAndOcclusionMapsFollowTheMapping) {
    Gltf g;
    // B: metallic, G: roughness (x factor 1); R of the occlusion map.
    const int mr = addTexture(g, 2, 1, {0, 128, 255, 255, 0, 255, 0, 255}, kNearest);
    const int ao = addTexture(g, 2, 1, {0, 0, 0, 255, 255, 255, 255, 255}, kNearest);
    json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.6, 0.2, 1.0}}, {"metallicRoughnessTexture", {{"index", mr}}}}},
                     {"occlusionTexture", {{"index", ao}, {"strength", 1.0}}}};
    const Scene scene = writeAndLoad(g, {square(g, 0.0f, 1.5f, g.add("materials", material))}, "metallic_roughness");
    EXPECT_NE(materialFeatures(scene) & ML_FEATURE_METALLIC_ROUGHNESS_MAP, 0u);
    EXPECT_NE(materialFeatures(scene) & ML_FEATURE_OCCLUSION_MAP, 0u);
    const test::ReferenceFrame naive = expectEveryMethodMatchesNaive(scene, kOneLight, "metallic-roughness");
    // Without lights only the ambient term is left: zero where occluded, ambient x (diffuse + f0) elsewhere.
    FrameRenderer dark(scene, {}, test::smallFrame(scene, kFrontView, kWidth, kHeight));
    dark.render(0);
    const FloatImage hdr = dark.readHdr();
    EXPECT_EQ(hdr.at(kWidth / 2 - 10, kHeight / 2)[0], 0.0f);
    const float open = hdr.at(kWidth / 2 + 10, kHeight / 2)[1];
    EXPECT_NEAR(open, dark.settings().ambient * (0.6f + 0.04f), 1e-4f);
    // Lit: the metallic half reflects its base colour in the highlight, the dielectric half grey.
    const float* metal = naive.hdr.at(kWidth / 2 - 10, kHeight / 2);
    EXPECT_GT(metal[0], 1.5f * metal[2]);
}

// KHR_texture_transform (offset, rotation, scale) on TEXCOORD_1 gives the same image as the same
// texture on UVs transformed beforehand, and COLOR_0 tints the base colour.
TEST_F(GltfMaterials, TextureTransformOnTexCoord1MatchesPretransformedUvs) {
    const std::vector<std::uint8_t> colours = pixels(8, 8, [](int x, int y) {
        return std::array<std::uint8_t, 4>{std::uint8_t(32 * x), std::uint8_t(32 * y), std::uint8_t(255 - 20 * (x + y)), 255};
    });
    const glm::vec2 offset(0.25f, -0.5f), scale(2.0f, 1.5f);
    const float rotation = 0.4f;
    const auto transformUv = [&](glm::vec2 uv) {
        const float c = std::cos(rotation), s = std::sin(rotation);
        const glm::vec2 scaled = uv * scale;
        return glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + offset;
    };
    const std::vector<glm::vec2> uv = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    const auto build = [&](bool transformed, const char* name) {
        Gltf g;
        const int texture = addTexture(g, 8, 8, colours);
        json info = {{"index", texture}, {"texCoord", transformed ? 1 : 0}};
        if (transformed) {
            info["extensions"] = {{"KHR_texture_transform", {{"offset", {offset.x, offset.y}}, {"rotation", rotation}, {"scale", {scale.x, scale.y}}}}};
            g.doc["extensionsUsed"] = {"KHR_texture_transform"};
        }
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", info}, {"metallicFactor", 0.0}}}});
        std::vector<glm::vec2> direct;
        for (const glm::vec2& t : uv) direct.push_back(transformUv(t));
        const std::vector<float> tint = {1, 0.5f, 0.5f, 1, 1, 0.5f, 0.5f, 1, 1, 0.5f, 0.5f, 1, 1, 0.5f, 0.5f, 1};
        json extra = {{"COLOR_0", g.accessor(g.view(tint.data(), tint.size() * 4), kFloat, 4, "VEC4")}};
        if (transformed) extra["TEXCOORD_1"] = g.vec2(uv);
        else extra["TEXCOORD_0"] = g.vec2(direct);
        return writeAndLoad(g, {square(g, 0.0f, 1.5f, material, extra)}, name);
    };
    const Scene viaTransform = build(true, "texture_transform");
    const Scene pretransformed = build(false, "texture_pretransformed");
    EXPECT_EQ(materialFeatures(viaTransform) & (ML_FEATURE_TEXTURE_TRANSFORM | ML_FEATURE_UV1 | ML_FEATURE_VERTEX_COLOR),
              std::uint32_t(ML_FEATURE_TEXTURE_TRANSFORM | ML_FEATURE_UV1 | ML_FEATURE_VERTEX_COLOR));
    EXPECT_EQ(materialFeatures(pretransformed) & (ML_FEATURE_TEXTURE_TRANSFORM | ML_FEATURE_UV1), 0u);
    const test::ReferenceFrame a = expectEveryMethodMatchesNaive(viaTransform, kOneLight, "texture transform");
    FrameRenderer renderer(pretransformed, kOneLight, test::smallFrame(pretransformed, kFrontView, kWidth, kHeight));
    renderer.render(0);
    test::expectWithinContract(renderer, a, "texture transform against pretransformed UVs", "texture_pretransformed");
    const float* centre = a.hdr.at(kWidth / 2, kHeight / 2);
    EXPECT_GT(centre[0], 0.0f);
}

// Samplers: CLAMP_TO_EDGE holds the edge texel past u = 1 where REPEAT starts over; the visibility
// buffer's own gradients pick the raster's mip levels on a texture seen at a grazing angle.
TEST_F(GltfMaterials, SamplerWrapModesAndMipSelectionAgreeAcrossMethods) {
    const std::vector<std::uint8_t> stripes = pixels(16, 16, [](int x, int y) {
        const bool on = ((x / 2) + (y / 2)) % 2 == 0;  // strong mips: fine checks average to grey
        return std::array<std::uint8_t, 4>{std::uint8_t(on ? 250 : 10), std::uint8_t(x * 16), std::uint8_t(on ? 40 : 200), 255};
    });
    const auto build = [&](int wrap, const char* name) {
        Gltf g;
        const int texture = addTexture(g, 16, 16, stripes, {{"wrapS", wrap}, {"wrapT", wrap}});
        const int material = g.add("materials", {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", texture}}}, {"metallicFactor", 0.0}}}});
        return writeAndLoad(g, {square(g, 0.0f, 2.0f, material, json::object(), 6.0f)}, name);
    };
    const Scene repeat = build(10497, "sampler_repeat");
    const Scene clamp = build(33071, "sampler_clamp");
    // Grazing: from low over the plane, so the mip level changes across the image.
    const CameraPose grazing{{0.0f, -3.2f, 1.2f}, {0.0f, 0.5f, 0.0f}, 60.0f};
    const test::ReferenceFrame r = expectEveryMethodMatchesNaive(repeat, kOneLight, "repeat", grazing);
    const test::ReferenceFrame c = expectEveryMethodMatchesNaive(clamp, kOneLight, "clamp", grazing);
    // UVs run to 6: clamped, most of the plane shows the last texel's colour; repeated, it does not.
    EXPECT_GT(compareImages(r.hdr, c.hdr).badPixelShare, 0.3);
}

}  // namespace
}  // namespace ml
