// The transparent pass's capture and compute shading (renderer/passes/transparent_pass.h):
// per-pixel depth order where panes intersect (which no order of whole ranges can give), many
// layers blended as the ROPs blend them, a pane with a normal map, a texture transform and
// vertex colours (glass over two texture sets), every method held to naive on each, and the
// deep tiles' split over several workgroups to the one pass, bit for bit; a frame
// whose fragments do not fit is refused in one line; a scene without BLEND builds none of it.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "glsl/include/bindings.h"
#include "renderer/passes/glass_fragments.h"
#include "renderer/scene/material_features.h"
#include "tests/gpu/gpu_test.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml {
namespace {

using namespace gltf_test;
using test::GpuTest;

constexpr int kWidth = 160, kHeight = 90;
const CameraPose kBackView{{0.0f, 0.0f, -4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f};
const std::vector<Light> kFrontAndBackLights{{{0.3f, 0.2f, 3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}, {{-0.3f, 0.1f, -3.0f}, 12.0f, {3.0f, 3.0f, 3.0f}}};

// Every surface here is seen from both sides: double-sided, roughness 0.5.
int paneMaterial(Gltf& g, glm::vec4 colour, const char* alphaMode) { return colourMaterial(g, colour, alphaMode, true, 0.5f); }

// A quad from four corners, its normal from the first three (counter-clockwise seen from the front).
json quad(Gltf& g, const std::array<glm::vec3, 4>& c, int material, const json& extra = json::object()) {
    const glm::vec3 n = glm::normalize(glm::cross(c[1] - c[0], c[2] - c[0]));
    json attributes = {{"POSITION", g.vec3({c[0], c[1], c[2], c[3]})},
                       {"NORMAL", g.vec3({n, n, n, n})},
                       {"TEXCOORD_0", g.vec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}})}};
    attributes.update(extra);
    return primitive(attributes, g.indices({0, 1, 2, 0, 2, 3}), material);
}

FrameSettings frame(const Scene& scene, const CameraPose& pose, MethodKind kind = MethodKind::Naive, int msaa = 1) {
    FrameSettings s = test::smallFrame(scene, pose, kWidth, kHeight);
    s.method.kind = kind;
    s.method.msaa = msaa;
    return s;
}

FloatImage render(const Scene& scene, const std::vector<Light>& lights, const FrameSettings& s) {
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    return renderer.readHdr();
}

glm::vec3 pixel(const FloatImage& image, int x, int y) {
    const float* p = image.at(x, y);
    return {p[0], p[1], p[2]};
}

void expectColourNear(glm::vec3 actual, glm::vec3 expected, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], 1e-4f + 1e-3f * std::abs(expected[c])) << what << " channel " << c;
}

// Every clustered method against naive on the scene (the images written where one fails).
void expectMethodsMatchNaive(const Scene& scene, const std::vector<Light>& lights, const CameraPose& pose, const std::string& label) {
    FrameRenderer renderer(scene, lights, frame(scene, pose));
    test::expectClusteredVariantsMatchNaive(renderer, label);
}

// A count the last frame's split kept (ML_GLASS_DEEP_TILE_COUNT: the deep tiles;
// ML_GLASS_SHALLOW_COUNT: the other tiles with glass), 0 where the frame kept no list.
std::uint32_t tilesListed(const FrameRenderer& renderer, std::uint32_t countWord = ML_GLASS_DEEP_TILE_COUNT) {
    const GlassFragments* capture = renderer.method().transparentCapture();
    if (!capture || !capture->hasDeepTileList()) return 0;
    std::uint32_t count = 0;
    capture->fragmentBuffer().download(&count, sizeof(count), (std::size_t(capture->deepTileWordOffset()) + countWord) * 4);
    return count;
}

// Channels of two same-sized HDR images that differ in any bit.
std::size_t channelsDiffering(const FloatImage& a, const FloatImage& b) {
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    return differing;
}

// The deep tiles' split (MethodSettings::glassLayerGroups: 2, 3, 4) against the one-pass
// shading (1), bit for bit, in every clustered method. Returns the fewest tiles a split listed.
std::uint32_t expectSplitMatchesOnePass(const Scene& scene, const std::vector<Light>& lights, const FrameSettings& base,
                                        const std::string& label) {
    std::uint32_t fewest = ~0u;
    for (MethodKind kind : {MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        FrameSettings s = base;
        s.method.kind = kind;
        s.method.glassLayerGroups = 1;
        FrameRenderer renderer(scene, lights, s);
        renderer.render(0);
        EXPECT_EQ(tilesListed(renderer), 0u) << methodName(kind) << ": listed with no split";
        const FloatImage onePass = renderer.readHdr();
        for (std::uint32_t groups : {2u, 3u, 4u}) {
            s.method.glassLayerGroups = groups;
            renderer.setMethod(s.method);
            renderer.render(0);
            const std::uint32_t listed = tilesListed(renderer);
            fewest = std::min(fewest, listed);
            EXPECT_EQ(channelsDiffering(renderer.readHdr(), onePass), 0u)
                << label << ", " << methodName(kind) << ", " << groups << " workgroups a deep tile (" << listed
                << " listed): channels differing from one pass";
        }
    }
    return fewest;
}

class GlassCapture : public GpuTest {};

// A red pane in z = 0 and a blue one tilted through it (z = 0.5 x): right of the crossing the
// blue is nearer from the front, left of it the red, and from behind the other way round. Each
// pixel blends its own two fragments far first, which no order of the two whole panes gives.
TEST_F(GlassCapture, IntersectingPanesBlendInDepthOrderOnBothSidesOfTheCrossing) {
    const auto scene = [&](const char* alphaMode, bool red, bool blue) {
        Gltf g;
        const int redPane = paneMaterial(g, {0.9f, 0.05f, 0.05f, 0.5f}, alphaMode);
        const int bluePane = paneMaterial(g, {0.05f, 0.05f, 0.9f, 0.5f}, alphaMode);
        std::vector<json> prims;
        if (red) prims.push_back(quad(g, {{{-2, -1, 0}, {2, -1, 0}, {2, 1, 0}, {-2, 1, 0}}}, redPane));
        if (blue) prims.push_back(quad(g, {{{-2, -1.2f, -1}, {2, -1.2f, 1}, {2, 1.2f, 1}, {-2, 1.2f, -1}}}, bluePane));
        return writeAndLoad(g, prims, std::string("crossing_") + alphaMode + (red ? "_red" : "") + (blue ? "_blue" : ""));
    };
    const Scene both = scene("BLEND", true, true);
    for (const auto& [pose, front] : {std::pair{kFrontView, true}, std::pair{kBackView, false}}) {
        const FloatImage mix = render(both, kFrontAndBackLights, frame(both, pose));
        const FloatImage red = render(scene("OPAQUE", true, false), kFrontAndBackLights, frame(both, pose));
        const FloatImage blue = render(scene("OPAQUE", false, true), kFrontAndBackLights, frame(both, pose));
        // 20 pixels either side of the centre: world x = +-1 on the red pane, 0.5 from the crossing.
        for (int dx : {-20, 20}) {
            const int x = kWidth / 2 + dx, y = kHeight / 2;
            // Seen from behind, screen right is world -x.
            const bool worldRight = front == (dx > 0);
            const bool blueNearer = worldRight == front;
            const glm::vec3 nearer = blueNearer ? pixel(blue, x, y) : pixel(red, x, y);
            const glm::vec3 farther = blueNearer ? pixel(red, x, y) : pixel(blue, x, y);
            expectColourNear(pixel(mix, x, y), 0.5f * nearer + 0.25f * farther,
                             std::string(front ? "front" : "back") + (dx > 0 ? ", screen right" : ", screen left"));
        }
        expectMethodsMatchNaive(both, kFrontAndBackLights, pose, std::string("crossing panes from the ") + (front ? "front" : "back"));
        EXPECT_GT(expectSplitMatchesOnePass(both, kFrontAndBackLights, frame(both, pose), "crossing panes"), 0u);
    }
}

// Twelve parallel panes over a wall, listed in no depth order: the capture and the compute
// blend give, away from the edges, what the ROPs give the forward pass (naive with --msaa 2,
// whose per-range order is right for parallel panes); every method holds to naive.
TEST_F(GlassCapture, ManyLayersBlendAsTheForwardPassBlendsThem) {
    Gltf g;
    std::vector<json> prims{square(g, -2.0f, 4.0f, paneMaterial(g, {0.6f, 0.6f, 0.6f, 1.0f}, "OPAQUE"))};
    for (int i = 0; i < 12; ++i) {
        const float z = -1.5f + 0.25f * float((i * 5) % 12);
        const glm::vec4 colour(0.2f + 0.06f * float(i), 0.9f - 0.07f * float(i), 0.3f + 0.05f * float(i % 4), 0.2f + 0.05f * float(i % 5));
        prims.push_back(square(g, z, 1.0f + 0.05f * float(i), paneMaterial(g, colour, "BLEND")));
    }
    const Scene scene = writeAndLoad(g, prims, "twelve_layers");
    FrameRenderer renderer(scene, kFrontAndBackLights, frame(scene, kFrontView));
    renderer.render(0);
    const FloatImage captured = renderer.readHdr();
    ASSERT_NE(renderer.method().transparentCapture(), nullptr);
    const std::uint64_t fragments = renderer.method().transparentCapture()->fragmentCount();
    EXPECT_GT(fragments, 12u * 20u * 20u) << "every pane's pixels, twelve deep in the middle";
    const FloatImage forward = render(scene, kFrontAndBackLights, frame(scene, kFrontView, MethodKind::Naive, 2));
    for (int y = kHeight / 2 - 12; y <= kHeight / 2 + 12; y += 4)
        for (int x = kWidth / 2 - 12; x <= kWidth / 2 + 12; x += 4)
            expectColourNear(pixel(captured, x, y), pixel(forward, x, y), "pixel " + std::to_string(x) + "," + std::to_string(y));
    expectMethodsMatchNaive(scene, kFrontAndBackLights, kFrontView, "twelve layers");
    // Twelve deep: the parts hold 3 to 6 fragments each, their boundaries at every depth.
    EXPECT_GT(expectSplitMatchesOnePass(scene, kFrontAndBackLights, frame(scene, kFrontView), "twelve layers"), 0u);
}

// A pane with a normal map, a base-colour texture read through KHR_texture_transform on
// TEXCOORD_1 and COLOR_0, half in front of a plain glass pane (so the glass spans two texture
// sets: the shading stores colours and blends after the last set): the compute rebuild (UVs,
// gradients, tangents, vertex colours) gives what the forward pass's varyings give.
TEST_F(GlassCapture, TexturedNormalMappedPaneMatchesTheForwardPass) {
    Gltf g;
    const auto image = [](int w, int h, auto texel) {
        std::vector<std::uint8_t> out;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::array<std::uint8_t, 4> t = texel(x, y);
                out.insert(out.end(), t.begin(), t.end());
            }
        return out;
    };
    const auto texture = [&](const std::vector<std::uint8_t>& rgba) {
        const int img = g.add("images", {{"uri", "data:image/png;base64," + base64(encodePng(8, 8, rgba))}});
        return g.add("textures", {{"source", img}});
    };
    const int colourMap = texture(image(8, 8, [](int x, int y) {
        return std::array<std::uint8_t, 4>{std::uint8_t(30 * x), std::uint8_t(30 * y), std::uint8_t(240 - 25 * (x + y) / 2), 200};
    }));
    const int normalMap = texture(image(8, 8, [](int x, int) {
        return std::array<std::uint8_t, 4>{std::uint8_t(x < 4 ? 204 : 51), 128, 230, 255};
    }));
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    const json transform = {{"KHR_texture_transform", {{"offset", {0.25, -0.5}}, {"rotation", 0.4}, {"scale", {2.0, 1.5}}}}};
    const int textured = g.add("materials", {{"pbrMetallicRoughness",
                                              {{"baseColorTexture", {{"index", colourMap}, {"texCoord", 1}, {"extensions", transform}}},
                                               {"baseColorFactor", {1.0, 1.0, 1.0, 0.7}},
                                               {"metallicFactor", 0.0},
                                               {"roughnessFactor", 0.6}}},
                                             {"normalTexture", {{"index", normalMap}}},
                                             {"alphaMode", "BLEND"}});
    const std::vector<float> tint = {1, 0.5f, 0.5f, 1, 0.5f, 1, 0.5f, 1, 0.5f, 0.5f, 1, 0.8f, 1, 1, 1, 0.6f};
    const std::vector<float> tangents = {1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1};
    const json extra = {{"COLOR_0", g.accessor(g.view(tint.data(), tint.size() * 4), kFloat, 4, "VEC4")},
                        {"TANGENT", g.accessor(g.view(tangents.data(), tangents.size() * 4), kFloat, 4, "VEC4")},
                        {"TEXCOORD_1", g.vec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}})}};
    const Scene scene = writeAndLoad(g,
                                     {square(g, -2.0f, 4.0f, paneMaterial(g, {0.5f, 0.6f, 0.7f, 1.0f}, "OPAQUE")),
                                      square(g, 0.5f, 1.3f, textured, extra),
                                      quad(g, {{{-0.5f, -1.5f, -0.5f}, {2.5f, -1.5f, -0.5f}, {2.5f, 1.5f, -0.5f}, {-0.5f, 1.5f, -0.5f}}},
                                           paneMaterial(g, {0.2f, 0.8f, 0.4f, 0.4f}, "BLEND"))},
                                     "textured_glass");
    const std::uint32_t needed = ML_FEATURE_NORMAL_MAP | ML_FEATURE_TEXTURE_TRANSFORM | ML_FEATURE_UV1 | ML_FEATURE_VERTEX_COLOR | ML_FEATURE_BLEND;
    ASSERT_EQ(materialFeatures(scene) & needed, needed);
    const std::vector<Light> fromRight{{{3.0f, 0.5f, 2.5f}, 20.0f, {4.0f, 4.0f, 4.0f}}};
    const FloatImage captured = render(scene, fromRight, frame(scene, kFrontView));
    const FloatImage forward = render(scene, fromRight, frame(scene, kFrontView, MethodKind::Naive, 2));
    // Away from the panes' edges and the texels' edges (the forward pass's samples see them
    // from a pixel centre too, but a texel border may fall between two samples' resolve).
    double worst = 0.0, sum = 0.0;
    int count = 0;
    for (int y = kHeight / 2 - 20; y <= kHeight / 2 + 20; ++y)
        for (int x = kWidth / 2 - 26; x <= kWidth / 2 + 26; ++x) {
            const glm::vec3 d = glm::abs(pixel(captured, x, y) - pixel(forward, x, y));
            worst = std::max(worst, double(std::max(d.x, std::max(d.y, d.z))));
            sum += d.x + d.y + d.z;
            ++count;
        }
    std::printf("textured glass: capture against forward, max %.5f, mean %.6f\n", worst, sum / (3.0 * count));
    EXPECT_LT(sum / (3.0 * count), 2e-3);
    const glm::vec3 centre = pixel(captured, kWidth / 2, kHeight / 2);
    EXPECT_GT(centre.r + centre.g + centre.b, 0.05f);
    expectMethodsMatchNaive(scene, fromRight, kFrontView, "textured glass");
    // Two texture sets: every dispatch stores colours already, and no tile is split.
    EXPECT_EQ(expectSplitMatchesOnePass(scene, fromRight, frame(scene, kFrontView), "textured glass"), 0u);
}

// More listed tiles than one dispatch row holds (ML_GLASS_DEEP_ROW, 65,535: GL's least maximum
// work-group count): at 2560x1648 (65,920 tiles) horizontal glass strips, one every 7 pixel rows,
// put a fragment in every tile. With two layers of them every tile holds a pixel of two fragments
// and is listed deep; with one, every tile is listed shallow. Either way the listed tiles go on in
// the dispatches' second row, and the frame is the one pass's, bit for bit.
TEST_F(GlassCapture, ListedTilesPastOneDispatchRowAreAllShaded) {
    constexpr int kWide = 2560, kTall = 1648;
    const float pixel = 2.0f * 4.0f * std::tan(glm::radians(30.0f)) / float(kTall);  // world units a pixel at z = 0
    for (int layers : {2, 1}) {
        Gltf g;
        std::vector<json> prims;
        const std::pair<float, glm::vec4> strips[] = {{0.0f, {0.9f, 0.3f, 0.2f, 0.5f}}, {-0.05f, {0.2f, 0.4f, 0.9f, 0.5f}}};
        for (int layer = 0; layer < layers; ++layer) {
            const auto& [z, colour] = strips[layer];
            const float scale = (4.0f - z) / 4.0f;  // the back layer's strips on the front's pixel rows
            std::vector<glm::vec3> corners, normals;
            std::vector<std::uint16_t> indices;
            for (float y = -0.5f * float(kTall) * pixel; y < 0.5f * float(kTall) * pixel; y += 7.0f * pixel) {
                const auto first = std::uint16_t(corners.size());
                for (glm::vec2 c : {glm::vec2(-4, 0), glm::vec2(4, 0), glm::vec2(4, 2.5f * pixel), glm::vec2(-4, 2.5f * pixel)})
                    corners.push_back({c.x * scale, (y + c.y) * scale, z});
                normals.insert(normals.end(), 4, glm::vec3(0, 0, 1));
                for (int i : {0, 1, 2, 0, 2, 3}) indices.push_back(std::uint16_t(first + i));
            }
            prims.push_back(primitive({{"POSITION", g.vec3(corners)}, {"NORMAL", g.vec3(normals)}}, g.indices(indices),
                                      paneMaterial(g, colour, "BLEND")));
        }
        const Scene scene = writeAndLoad(g, prims, "glass_strips_" + std::to_string(layers));
        FrameSettings s = test::smallFrame(scene, kFrontView, kWide, kTall);
        s.method.kind = MethodKind::Visibility;
        s.method.glassLayerGroups = 1;
        FrameRenderer renderer(scene, kFrontAndBackLights, s);
        renderer.render(0);
        const FloatImage onePass = renderer.readHdr();
        s.method.glassLayerGroups = 4;
        renderer.setMethod(s.method);
        renderer.render(0);
        const std::uint32_t deep = tilesListed(renderer), shallow = tilesListed(renderer, ML_GLASS_SHALLOW_COUNT);
        std::printf("glass strips, %d layer(s), at %dx%d: %llu fragments, %u deep and %u shallow tiles listed\n", layers, kWide,
                    kTall, static_cast<unsigned long long>(renderer.method().transparentCapture()->fragmentCount()), deep, shallow);
        EXPECT_GT(layers == 2 ? deep : shallow, std::uint32_t(ML_GLASS_DEEP_ROW)) << layers << " layer(s)";
        if (layers == 1) {
            EXPECT_EQ(deep, 0u);
        }
        EXPECT_EQ(channelsDiffering(renderer.readHdr(), onePass), 0u) << layers << " layer(s): channels differing from one pass";
    }
}

// The capture keeps pixels for a window of whole screen tiles around the glass's projected
// bounds, its rasters scissored to it: a window too small would drop fragments in every method
// alike, naive included, so the methods' agreement cannot see it. Here one pane alone captures a
// fragment for every pixel the same pane covers when opaque: on screen at an odd size and odd
// places, half off two edges, and as a floor through the camera's plane (its box behind the
// eye: the whole screen).
TEST_F(GlassCapture, TheWindowHoldsEveryFragment) {
    constexpr int kOddWide = 157, kOddTall = 93;
    struct Case {
        const char* name;
        std::array<glm::vec3, 4> corners;
        CameraPose pose;
    };
    const Case cases[] = {
        {"on screen", {{{-0.93f, -0.41f, 0.1f}, {0.77f, -0.57f, -0.2f}, {0.61f, 0.83f, 0.05f}, {-0.71f, 0.67f, 0.3f}}}, kFrontView},
        {"half off two edges", {{{-4.1f, -0.3f, 0}, {-1.3f, -0.3f, 0}, {-1.3f, 3.7f, 0}, {-4.1f, 3.7f, 0}}}, kFrontView},
        {"through the camera's plane", {{{-6, -1, 8}, {6, -1, 8}, {6, -1, -8}, {-6, -1, -8}}}, {{0.0f, 0.0f, 0.0f}, {0.0f, -0.2f, -1.0f}, 60.0f}},
    };
    for (const Case& c : cases) {
        const auto pane = [&](const char* alphaMode) {
            Gltf g;
            return writeAndLoad(g, {quad(g, c.corners, paneMaterial(g, {0.5f, 0.6f, 0.7f, 0.5f}, alphaMode))},
                                std::string("window_pane_") + alphaMode + "_" + std::to_string(&c - cases));
        };
        const Scene glass = pane("BLEND"), opaque = pane("OPAQUE");
        for (MethodKind kind : {MethodKind::Naive, MethodKind::Visibility}) {
            FrameSettings s = test::smallFrame(glass, c.pose, kOddWide, kOddTall);
            s.method.kind = kind;
            FrameRenderer renderer(glass, kFrontAndBackLights, s);
            renderer.render(0);
            ASSERT_NE(renderer.method().transparentCapture(), nullptr);
            const std::uint64_t fragments = renderer.method().transparentCapture()->fragmentCount();
            const FloatImage solid = render(opaque, kFrontAndBackLights, s);
            std::uint64_t covered = 0;
            for (int y = 0; y < kOddTall; ++y)
                for (int x = 0; x < kOddWide; ++x) covered += pixel(solid, x, y) != glm::vec3(0.0f);
            EXPECT_GT(covered, 200u) << c.name;
            EXPECT_EQ(fragments, covered) << c.name << ", " << methodName(kind) << ": fragments captured, pixels the opaque pane covers";
        }
    }
}

// With the compute raster the capture tests against the raster's depth in its own shader (no
// depth buffer holds it), or, with --active-only, in hardware against a copy: either way it keeps
// the fragments the hardware raster's depth keeps. A glass pane behind an opaque square that
// hides half of it and one in front of it all: every front fragment and half the back ones.
TEST_F(GlassCapture, TheComputeRastersDepthHidesWhatTheHardwareRastersDoes) {
    const auto panes = [](bool hidden) {
        Gltf g;
        std::vector<json> prims{square(g, -0.5f, 1.5f, paneMaterial(g, {0.2f, 0.4f, 0.9f, 0.5f}, "BLEND")),
                                square(g, 0.5f, 0.6f, paneMaterial(g, {0.9f, 0.3f, 0.2f, 0.5f}, "BLEND"))};
        if (hidden) prims.push_back(quad(g, {{{-3, -2, 0}, {0, -2, 0}, {0, 2, 0}, {-3, 2, 0}}}, paneMaterial(g, {0.6f, 0.6f, 0.6f, 1.0f}, "OPAQUE")));
        return writeAndLoad(g, prims, hidden ? "half_hidden_glass" : "unhidden_glass");
    };
    const Scene scene = panes(true);
    const auto captured = [&](VisibilityRaster raster, bool activeOnly, const Scene& from) {
        FrameSettings s = frame(from, kFrontView, MethodKind::Visibility);
        s.method.visibilityRaster = raster;
        s.method.clustering.activeOnly = activeOnly;
        FrameRenderer renderer(from, kFrontAndBackLights, s);
        renderer.render(0);
        return renderer.method().transparentCapture()->fragmentCount();
    };
    const std::uint64_t hardware = captured(VisibilityRaster::Hardware, false, scene);
    EXPECT_LT(hardware, captured(VisibilityRaster::Hardware, false, panes(false))) << "the opaque square hides some glass";
    for (bool activeOnly : {false, true})
        EXPECT_EQ(captured(VisibilityRaster::ComputeTwoPass, activeOnly, scene), hardware) << (activeOnly ? "--active-only" : "the shader's test");
}

// The fragments are sized by what the frame needs; a frame whose need passes the budget (the
// GPU's storage-buffer limit, lowered here) is refused in one line that names the numbers.
TEST_F(GlassCapture, AFrameWhoseFragmentsDoNotFitIsRefusedInOneLine) {
    Gltf g;
    const Scene scene = writeAndLoad(g, {square(g, 0.0f, 1.5f, paneMaterial(g, {0.9f, 0.1f, 0.1f, 0.5f}, "BLEND"))}, "one_pane");
    for (MethodKind kind : {MethodKind::Naive, MethodKind::Visibility}) {
        FrameSettings s = frame(scene, kFrontView, kind);
        s.method.transparentCaptureBudget = 1024;
        FrameRenderer renderer(scene, kFrontAndBackLights, s);
        try {
            renderer.render(0);
            ADD_FAILURE() << methodName(kind) << ": a frame of more than 128 fragments was drawn";
        } catch (const std::runtime_error& e) {
            const std::string message = e.what();
            std::printf("%s refused: %s\n", methodName(kind).c_str(), message.c_str());
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_NE(message.find("fragments x 8 B"), std::string::npos) << message;
            EXPECT_NE(message.find("160x90"), std::string::npos) << message;
        }
    }
}

// A scene with no BLEND material builds no capture and no shading program in any method.
TEST_F(GlassCapture, ASceneWithoutBlendBuildsNoneOfIt) {
    Gltf g;
    const Scene scene = writeAndLoad(g, {square(g, 0.0f, 1.5f, paneMaterial(g, {0.9f, 0.1f, 0.1f, 1.0f}, "OPAQUE"))}, "opaque_only");
    ASSERT_EQ(materialFeatures(scene) & ML_FEATURE_BLEND, 0u);
    FrameRenderer renderer(scene, kFrontAndBackLights, frame(scene, kFrontView));
    for (MethodKind kind : {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        MethodSettings m;
        m.kind = kind;
        renderer.setMethod(m);
        renderer.render(0);
        EXPECT_EQ(renderer.method().transparentCapture(), nullptr) << methodName(kind);
    }
}

}  // namespace
}  // namespace ml
