// What the live view relies on when its window changes size: every method's screen-sized
// targets (G-buffer, cluster grid, HDR/LDR) follow FrameRenderer::resize without a GL error, and
// the frame after a resize is the frame a renderer made at that size gives. Also the swaps the
// panel makes (method, lights) while the renderer lives on.
#include <gtest/gtest.h>

#include "gpu_test.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

class ViewResize : public GpuTest {
protected:
    Scene scene() {
        std::vector<std::string> warnings;
        return loadScene(SceneRequest{"boxes", 0.25f}, warnings);
    }
    static std::vector<Light> lights(const Scene& scene, std::uint32_t count) {
        LightGeneration gen;
        gen.count = count;
        gen.seed = 11;
        gen.radius = defaultLightRadius(scene.bounds);
        return generateLights(lightVolume(scene.bounds), gen);
    }
};

TEST_F(ViewResize, EveryMethodFollowsTheNewSize) {
    const Scene s = scene();
    for (const std::string& method : methodNames()) {
        FrameSettings settings = smallFrame(s, 96, 64);
        settings.method.kind = parseMethod(method);
        FrameRenderer resized(s, lights(s, 40), settings);
        resized.render(3);
        // Wider, then tiny, then taller than wide: the tile count, tiles down and G-buffer change.
        for (auto [w, h] : {std::pair{160, 90}, std::pair{1, 1}, std::pair{7, 3}, std::pair{72, 120}}) {
            resized.resize(w, h);
            resized.render(3);
            const RgbaImage image = resized.readLdr();
            ASSERT_EQ(image.width, w);
            ASSERT_EQ(image.height, h);
        }
        settings.width = 72;
        settings.height = 120;
        FrameRenderer fresh(s, lights(s, 40), settings);
        fresh.render(3);
        const ImageDifference d = compareImages(resized.readLdr(), fresh.readLdr());
        EXPECT_EQ(d.maxAbs, 0.0) << method << ": images in "
                                 << writeFailureImages(method, resized.readLdr(), fresh.readLdr());
    }
}

TEST_F(ViewResize, NewLightsAndMethodsMatchAFreshRenderer) {
    const Scene s = scene();
    FrameSettings settings = smallFrame(s, 96, 64);
    settings.method.kind = MethodKind::Naive;
    FrameRenderer live(s, lights(s, 8), settings);
    live.render(0);
    // What the panel does: more lights, then Forward+ with a coarser grid, then deferred.
    live.setLights(lights(s, 300));
    MethodSettings m;
    m.kind = MethodKind::ForwardPlus;
    m.clustering.grid.tilesX = 8;
    m.clustering.grid.slices = 6;
    live.setMethod(m);
    live.render(7);
    m.kind = MethodKind::Deferred;
    live.setMethod(m);
    live.renderAt(7 * kSecondsPerFrame);

    settings.method = m;
    FrameRenderer fresh(s, lights(s, 300), settings);
    fresh.render(7);
    EXPECT_EQ(live.lights().count(), 300u);
    const ImageDifference d = compareImages(live.readLdr(), fresh.readLdr());
    EXPECT_EQ(d.maxAbs, 0.0) << "images in " << writeFailureImages("swaps", live.readLdr(), fresh.readLdr());
}

TEST_F(ViewResize, LatestTimingNeverWaitsAndCatchesUp) {
    const Scene s = scene();
    FrameSettings settings = smallFrame(s, 64, 48);
    settings.method.kind = MethodKind::ForwardPlus;
    settings.timing = true;
    settings.clock = TimingClock::GpuQueries;
    settings.readback = TimingReadback::Latest;
    FrameRenderer renderer(s, lights(s, 16), settings);
    bool gotTimes = false;
    for (int i = 0; i < 12 && !gotTimes; ++i) {
        const std::vector<PassTime> times = renderer.render(static_cast<std::uint32_t>(i));
        if (!times.empty()) {
            gotTimes = true;
            EXPECT_EQ(times.front().name, "lights.animate");
            EXPECT_EQ(times.back().name, "tonemap");
        }
    }
    EXPECT_TRUE(gotTimes) << "no frame's queries were read within 12 frames (at most 4 may be in flight)";
}

}  // namespace
}  // namespace ml::test
