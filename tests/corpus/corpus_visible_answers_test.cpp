// The corpus models whose right answer can be seen (../shared/corpus/README.md), seen from the
// front in a white directional light from the camera, by naive and by every other method: what
// each model tests must show, in every method. The measures are coarse on purpose (colours of
// known regions, statistics that a symmetric answer makes equal) so that they hold at 240x135
// on llvmpipe and on a GPU alike. The images are written under ML_TEST_TMP for a person to look at.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "renderer/camera/camera.h"
#include "scenes/scene_library.h"
#include "tests/corpus/corpus.h"
#include "tests/gpu/gpu_test.h"

namespace ml::test {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 240, kHeight = 135;

// The pixels of a region, as fractions of the image (x0, y0 top-left; y grows downwards).
struct Region {
    float x0, y0, x1, y1;
};

struct PixelCounts {
    int total = 0, matching = 0;
    double meanLuminance = 0.0;
    double share() const { return total ? double(matching) / total : 0.0; }
};

// Counts the region's pixels that `test` accepts (r, g, b in 0..255), and their mean luminance.
PixelCounts countPixels(const RgbaImage& image, Region r, const std::function<bool(int, int, int)>& test) {
    PixelCounts c;
    double luminance = 0.0;
    for (int y = int(r.y0 * image.height); y < int(r.y1 * image.height); ++y)
        for (int x = int(r.x0 * image.width); x < int(r.x1 * image.width); ++x) {
            const std::uint8_t* p = image.at(x, y);
            ++c.total;
            if (test(p[0], p[1], p[2])) ++c.matching;
            luminance += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        }
    c.meanLuminance = c.total ? luminance / c.total : 0.0;
    return c;
}

bool lit(int r, int g, int b) { return r + g + b > 24; }
bool yellow(int r, int g, int b) { return r > 120 && g > 120 && b < r / 2 && b < g / 2; }
bool white(int r, int g, int b) { return r > 170 && g > 170 && b > 170; }

// The file's model seen straight along -z, filling most of the frame, lit by one white
// directional light from behind the camera (no generated lights: nothing but the model's answer).
struct FrontView {
    Scene scene;
    std::vector<Light> lights;
    FrameSettings settings;
};
FrontView frontView(const std::string& relative, float margin = 1.15f) {
    std::vector<std::string> warnings;
    FrontView v{loadScene(SceneRequest{corpusPath(relative), 1.0f}, warnings), {}, {}};
    const glm::vec3 c = v.scene.bounds.center(), size = v.scene.bounds.size();
    const float fovy = 40.0f, aspect = float(kWidth) / kHeight;
    const float halfHeight = 0.5f * std::max(size.y, size.x / aspect) * margin;
    CameraPose pose{{c.x, c.y, v.scene.bounds.max.z + halfHeight / std::tan(glm::radians(0.5f * fovy))}, c, fovy};
    v.settings = smallFrame(v.scene, pose, kWidth, kHeight);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.0f, 0.0f, -1.0f};
    sun.color = glm::vec3(2.5f);
    v.lights.push_back(sun);
    return v;
}

// Renders the view in every method and hands each image to `check`, the method's name in the
// failure message; each image is written as <method>.png under the test's output folder.
void forEveryMethod(const FrontView& v, const std::function<void(const RgbaImage&, const std::string&)>& check) {
    FrameRenderer renderer(v.scene, v.lights, v.settings);
    for (MethodKind kind : kEveryMethod) {
        MethodSettings method;
        method.kind = kind;
        renderer.setMethod(method);
        renderer.render(0);
        const RgbaImage image = renderer.readLdr();
        const std::string name = methodName(kind);
        writePng((testOutputDir() / (name + ".png")).string(), image);
        SCOPED_TRACE(name);
        check(image, name);
    }
}

class CorpusVisibleAnswer : public GpuTest {
protected:
    void SetUp() override {
        if (!fs::is_directory(ML_CORPUS_DIR)) GTEST_SKIP();  // Corpus.IsPresent says why, once
        GpuTest::SetUp();
    }
};

TEST_F(CorpusVisibleAnswer, TextureTransformShowsItsCheckmarks) {
    // The top row: three offset tests, each a checkmark on green, blue or teal when the offset is
    // applied, a yellow image when not (the model's README).
    const FrontView v = frontView("khronos/TextureTransformTest/glTF/TextureTransformTest.gltf");
    forEveryMethod(v, [](const RgbaImage& image, const std::string&) {
        const Region topRow{0.0f, 0.0f, 1.0f, 0.45f};
        const PixelCounts yellows = countPixels(image, topRow, yellow);
        const PixelCounts whites = countPixels(image, topRow, white);
        const PixelCounts any = countPixels(image, topRow, lit);
        std::printf("top row: lit %.3f  white %.3f  yellow %.4f\n", any.share(), whites.share(), yellows.share());
        EXPECT_GT(any.share(), 0.25) << "the top row's quads are missing";
        EXPECT_GT(whites.share(), 0.02) << "no white checkmarks";
        EXPECT_LT(yellows.share(), 0.002) << "yellow: an offset was not applied";
    });
}


TEST_F(CorpusVisibleAnswer, NormalTangentMirrorLightsEachPairAlike) {
    // Each test pair is a cell of real bumps beside a flat cell whose normal map (mirrored UVs,
    // supplied tangents) copies them: lit from the front, the two cells of a pair must look alike
    // (the model's README). Measured on the left panel's four columns (pairs 1|2 and 3|4) as the
    // columns' mean luminance.
    const FrontView v = frontView("khronos/NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf");
    forEveryMethod(v, [](const RgbaImage& image, const std::string&) {
        double mean[4];
        for (int c = 0; c < 4; ++c) {
            const float x0 = 0.195f + 0.068f * c;
            mean[c] = countPixels(image, {x0 + 0.01f, 0.12f, x0 + 0.058f, 0.78f}, lit).meanLuminance;
        }
        std::printf("left panel columns: %.1f %.1f %.1f %.1f\n", mean[0], mean[1], mean[2], mean[3]);
        EXPECT_GT(mean[0], 60.0) << "the left panel is not lit";
        EXPECT_NEAR(mean[1], mean[0], 0.1 * mean[0]) << "the first pair is lit differently";
        EXPECT_NEAR(mean[3], mean[2], 0.1 * mean[2]) << "the second pair is lit differently";
    });
}

TEST_F(CorpusVisibleAnswer, MeshPrimitiveModesDrawStripsAndFansAsTriangles) {
    // Three shapes side by side, each the same outline drawn as TRIANGLES, TRIANGLE_STRIP and
    // TRIANGLE_FAN (points and lines are skipped with a warning): each third of the frame holds
    // the same covered area.
    const FrontView v = frontView("khronos/MeshPrimitiveModes/glTF/MeshPrimitiveModes.gltf");
    forEveryMethod(v, [](const RgbaImage& image, const std::string&) {
        const PixelCounts a = countPixels(image, {0.0f, 0.0f, 1.0f / 3.0f, 1.0f}, lit);
        const PixelCounts b = countPixels(image, {1.0f / 3.0f, 0.0f, 2.0f / 3.0f, 1.0f}, lit);
        const PixelCounts c = countPixels(image, {2.0f / 3.0f, 0.0f, 1.0f, 1.0f}, lit);
        std::printf("covered: %.3f %.3f %.3f\n", a.share(), b.share(), c.share());
        EXPECT_GT(a.share(), 0.1);
        EXPECT_NEAR(b.share(), a.share(), 0.05 * a.share());
        EXPECT_NEAR(c.share(), a.share(), 0.05 * a.share());
    });
}

TEST_F(CorpusVisibleAnswer, AlphaBlendModeCutsOutAndBlends) {
    // Five striped panels on a marble wall: OPAQUE, BLEND, then MASK at three cutoffs over an
    // alpha that fades upwards. The stripes (cyan and yellow, told from the grey-white marble by
    // their saturation; yellow counts only in part) must cover the opaque panel, show faintly through the blended one, and
    // cover less of each masked panel the higher its cutoff.
    const FrontView v = frontView("khronos/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
    forEveryMethod(v, [](const RgbaImage& image, const std::string&) {
        const float panels[5][2] = {{0.19f, 0.27f}, {0.335f, 0.405f}, {0.475f, 0.545f}, {0.62f, 0.69f}, {0.765f, 0.83f}};
        const auto striped = [](int r, int g, int b) { return std::max(g, b) - r > 14; };
        double share[5];
        for (int i = 0; i < 5; ++i) share[i] = countPixels(image, {panels[i][0], 0.3f, panels[i][1], 0.65f}, striped).share();
        std::printf("striped: opaque %.3f  blend %.3f  mask %.3f %.3f %.3f\n", share[0], share[1], share[2], share[3], share[4]);
        EXPECT_GT(share[0], 0.3) << "the opaque panel's stripes are missing";
        EXPECT_LT(share[1], 0.8 * share[0]) << "the blended panel is as opaque as the opaque one";
        EXPECT_GT(share[2], share[3] + 0.05) << "the masks' cutoffs do not cut";
        EXPECT_GT(share[3], share[4] + 0.05) << "the masks' cutoffs do not cut";
    });
}

TEST_F(CorpusVisibleAnswer, SimpleInstancingDrawsItsHundredAndTwentyFiveCubes) {
    // One cube mesh drawn by EXT_mesh_gpu_instancing 125 times (a 5 x 5 x 5 grid, each turned and
    // scaled): 125 cubes' worth of triangles, and in every method each cube's centre lands on a
    // drawn pixel (its own, or a cube's in front of it). One cube drawn would leave most dark.
    const FrontView v = frontView("khronos/SimpleInstancing/glTF/SimpleInstancing.gltf");
    constexpr std::size_t kCubes = 125, kCubeVertices = 24;
    ASSERT_EQ(v.scene.triangleCount(), kCubes * 12);
    ASSERT_EQ(v.scene.vertices.size(), kCubes * kCubeVertices);
    std::vector<glm::vec3> centres;
    for (std::size_t c = 0; c < kCubes; ++c) {
        glm::vec3 sum(0.0f);
        for (std::size_t i = 0; i < kCubeVertices; ++i) sum += v.scene.vertices[c * kCubeVertices + i].position;
        centres.push_back(sum / float(kCubeVertices));
    }
    for (std::size_t a = 0; a < kCubes; ++a)
        for (std::size_t b = a + 1; b < kCubes; ++b)
            ASSERT_GT(glm::length(centres[a] - centres[b]), 0.5f) << "cubes " << a << " and " << b << " share a place";
    const glm::mat4 clip = v.settings.camera.projection(float(kWidth) / kHeight) * v.settings.camera.view();
    forEveryMethod(v, [&](const RgbaImage& image, const std::string&) {
        int dark = 0;
        for (const glm::vec3& centre : centres) {
            const glm::vec4 p = clip * glm::vec4(centre, 1.0f);
            const int x = int((p.x / p.w * 0.5f + 0.5f) * image.width);
            const int y = int((0.5f - p.y / p.w * 0.5f) * image.height);
            ASSERT_TRUE(x >= 0 && x < image.width && y >= 0 && y < image.height) << "a cube is outside the frame";
            const std::uint8_t* px = image.at(x, y);
            dark += !lit(px[0], px[1], px[2]);
        }
        const PixelCounts any = countPixels(image, {0, 0, 1, 1}, lit);
        std::printf("cube centres on dark pixels: %d of %zu; lit %.3f of the frame\n", dark, kCubes, any.share());
        EXPECT_EQ(dark, 0);
    });
}

}  // namespace
}  // namespace ml::test
