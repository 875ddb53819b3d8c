// The naive method, the reference of every other method, checked against the shading formula
// computed on the CPU, and the light animation against its CPU mirror; its frames drawn in bands.
#include <gtest/gtest.h>

#include "gpu_test.h"
#include "renderer/methods/naive_forward.h"
#include "renderer/reference/shading_reference.h"
#include "scenes/procedural_scenes.h"

namespace ml::test {
namespace {

class NaiveForwardTest : public GpuTest {};

TEST_F(NaiveForwardTest, MatchesTheFormulaOnThePlane) {
    const Scene plane = makePlane();
    ASSERT_FALSE(plane.materials.empty());
    const Material& m = plane.materials[plane.draws.at(0).material];
    ASSERT_FALSE(m.baseColorTexture.present()) << "this test assumes an untextured plane";

    std::vector<Light> lights{
        {{0.0f, 1.0f, 0.0f}, 4.0f, {1.0f, 0.5f, 0.25f}},
        {{3.0f, 0.5f, -2.0f}, 3.0f, {0.2f, 1.0f, 0.4f}},
        {{-4.0f, 2.0f, 3.0f}, 6.0f, {0.5f, 0.5f, 2.0f}},
        {{8.0f, -1.0f, 0.0f}, 5.0f, {5.0f, 5.0f, 5.0f}},  // below the plane: must add nothing
    };
    FrameSettings s;
    s.width = 96;
    s.height = 64;
    s.camera.eye = {0.0f, 6.0f, 8.0f};
    s.camera.target = {0.0f, 0.0f, 0.0f};
    s.camera.fovyDegrees = 60.0f;
    s.camera.nearPlane = 0.1f;
    s.camera.farPlane = 50.0f;
    s.animation.driftSpeed = 0.0f;
    s.ambient = 0.03f;
    FrameRenderer renderer(plane, lights, s);
    renderer.render(0);
    const FloatImage hdr = renderer.readHdr();

    const glm::mat4 invViewProj = glm::inverse(renderer.uniforms().viewProj);
    int checked = 0;
    for (int y = 2; y < s.height; y += 7) {
        for (int x = 3; x < s.width; x += 9) {
            // The pixel centre's ray, intersected with the plane y = 0.
            const glm::vec2 ndc((x + 0.5f) / s.width * 2.0f - 1.0f, 1.0f - (y + 0.5f) / s.height * 2.0f);
            glm::vec4 nearP = invViewProj * glm::vec4(ndc, 1.0f, 1.0f);  // reversed depth: 1 near, 0 far
            glm::vec4 farP = invViewProj * glm::vec4(ndc, 0.0f, 1.0f);
            const glm::vec3 a = glm::vec3(nearP) / nearP.w, b = glm::vec3(farP) / farP.w;
            const float t = a.y / (a.y - b.y);
            const glm::vec3 p = a + t * (b - a);
            const float* gpu = hdr.at(x, y);
            if (t < 0.0f || t > 1.0f || std::abs(p.x) > 9.9f || std::abs(p.z) > 9.9f) {
                if (std::abs(p.x) > 10.1f || std::abs(p.z) > 10.1f || t < 0.0f) {
                    EXPECT_EQ(gpu[0] + gpu[1] + gpu[2], 0.0f) << "background at " << x << "," << y;
                }
                continue;
            }
            SurfaceSample sample{p, {0, 1, 0}, glm::vec3(m.baseColorFactor), m.metallic, m.roughness};
            const glm::vec3 expected = shadeReference(sample, s.camera.eye, lights, s.ambient, s.specular, s.lightModel);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(gpu[c], expected[c], 2e-3f + 2e-3f * expected[c]) << "pixel " << x << "," << y << " channel " << c;
            ++checked;
        }
    }
    EXPECT_GT(checked, 40);
}

TEST_F(NaiveForwardTest, LightAnimationMatchesItsCpuMirror) {
    const Scene boxes = makeBoxes();
    LightGeneration gen;
    gen.count = 1000;
    gen.radius = 2.0f;
    const std::vector<Light> lights = generateLights(lightVolume(boxes.bounds), gen);
    FrameSettings s = smallFrame(boxes, 32, 32);
    FrameRenderer renderer(boxes, lights, s);
    const std::uint32_t frame = 377;
    renderer.render(frame);
    const std::vector<Light> gpu = renderer.lights().downloadAnimated();
    ASSERT_EQ(gpu.size(), lights.size());
    const float time = frame * kSecondsPerFrame;
    for (std::uint32_t i = 0; i < lights.size(); ++i) {
        const Light cpu = animateLight(lights[i], i, time, s.animation);
        EXPECT_NEAR(gpu[i].position.y, cpu.position.y, 1e-4f) << i;
        EXPECT_EQ(gpu[i].position.x, cpu.position.x) << i;
        EXPECT_GE(gpu[i].position.y, lightVolume(boxes.bounds).min.y - 1e-4f);
        EXPECT_LE(gpu[i].position.y, lightVolume(boxes.bounds).max.y + 1e-4f);
    }
}

TEST_F(NaiveForwardTest, ZeroLightsGivesAmbientOnly) {
    const Scene boxes = makeBoxes();
    FrameSettings s = smallFrame(boxes, 48, 32);
    FrameRenderer renderer(boxes, {}, s);
    renderer.render(0);
    const FloatImage hdr = renderer.readHdr();
    float maxValue = 0.0f;
    for (float v : hdr.pixels) maxValue = std::max(maxValue, v);
    EXPECT_GT(maxValue, 0.0f);                 // ambient is visible
    EXPECT_LE(maxValue, s.ambient + 1e-6f);    // and nothing else (albedo <= 1)
}

// A frame past the pixel-lights of one draw is drawn in scissored bands. Each band's passes,
// the glass's capture among them with a scissor of its own, keep to the band: the bands together
// pass the depth test on as many samples as one draw of the frame (a pass that turned the
// scissor off, as the capture once did, made every later band a whole frame: naive on an H100
// 3.2 times slower), and the frame is the same to the bit.
TEST_F(NaiveForwardTest, BandsDrawEachPixelOnceAndTheFrameOfOneDraw) {
    const TestScene t = testScene("atrium", 64, 5);  // glass on
    FrameSettings s = smallFrame(t.scene, 160, 90);
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(0);
    ASSERT_TRUE(renderer.scene().hasTransparent());
    PassTimer timer;
    const FrameContext ctx = renderer.frameContext(timer);
    const double pixelLights = 160.0 * 90.0 * double(t.lights.size());

    struct Drawn {
        GLuint samples = 0;
        FloatImage hdr;
    };
    const auto draw = [&](double pixelLightsPerDraw) {
        NaiveForward naive(renderer.scene().materialFeatures(), s.method.clustering, {}, pixelLightsPerDraw);
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_SAMPLES_PASSED, query);
        naive.render(ctx);
        glEndQuery(GL_SAMPLES_PASSED);
        Drawn d;
        glGetQueryObjectuiv(query, GL_QUERY_RESULT, &d.samples);
        glDeleteQueries(1, &query);
        EXPECT_EQ(glIsEnabled(GL_SCISSOR_TEST), GL_FALSE) << "the scissor left on";
        d.hdr = renderer.readHdr();
        return d;
    };
    const Drawn once = draw(kNaivePixelLightsPerDraw);
    const Drawn banded = draw(pixelLights / 4.5);  // five bands
    EXPECT_GT(once.samples, 160u * 90u);
    EXPECT_EQ(banded.samples, once.samples);
    ASSERT_EQ(banded.hdr.pixels.size(), once.hdr.pixels.size());
    EXPECT_TRUE(banded.hdr.pixels == once.hdr.pixels) << "the banded frame differs from one draw's";
}

}  // namespace
}  // namespace ml::test
