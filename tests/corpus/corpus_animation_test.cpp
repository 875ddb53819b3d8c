// A skinned, animated figure nobody here made: CesiumMan (../shared/corpus) walking, at t = 0.5 s,
// in every method against naive at 320x180 (the contract: 99.99 % of pixels within 1/255), its
// legs moved from where they are at t = 0, and its bounds moving with it.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "renderer/camera/camera.h"
#include "scenes/animation_pose.h"
#include "scenes/scene_library.h"
#include "tests/corpus/corpus.h"
#include "tests/gpu/gpu_test.h"

namespace ml::test {
namespace {

constexpr int kWidth = 320, kHeight = 180;

class CorpusAnimation : public GpuTest {
protected:
    void SetUp() override {
        const std::string path = corpusPath("khronos/CesiumMan/glTF/CesiumMan.gltf");
        if (!std::filesystem::exists(path)) GTEST_SKIP() << "no CesiumMan in " << ML_CORPUS_DIR;
        GpuTest::SetUp();
        std::vector<std::string> warnings;
        scene_ = loadScene(SceneRequest{path, 1.0f}, warnings);
        EXPECT_TRUE(warnings.empty());
    }
    Scene scene_;
};

TEST_F(CorpusAnimation, CesiumMansBoundsMove) {
    ASSERT_NE(scene_.animation, nullptr);
    const Bounds a = posedBounds(scene_, 0, 0.0), b = posedBounds(scene_, 0, 0.5);
    std::printf("CesiumMan bounds at 0 s: (%.3f %.3f %.3f)..(%.3f %.3f %.3f); at 0.5 s: (%.3f %.3f %.3f)..(%.3f %.3f %.3f)\n", a.min.x,
                a.min.y, a.min.z, a.max.x, a.max.y, a.max.z, b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
    EXPECT_GT(glm::length(a.min - b.min) + glm::length(a.max - b.max), 0.05f);
}

TEST_F(CorpusAnimation, CesiumManWalkingHoldsTheContractInEveryMethod) {
    const std::vector<Light> lights = ownAndGeneratedLights(scene_);
    const Bounds swept = sweptBounds(scene_, 0, 0.0, kSecondsPerFrame);
    Camera camera = cameraFromPose(framingView(swept));
    fitClipPlanes(camera, swept);
    FrameSettings s;
    s.width = kWidth;
    s.height = kHeight;
    s.camera = camera;
    s.animation = verticalDrift(lightVolume(swept), 0.0f);  // still lights: what moves is the figure
    const std::uint32_t frame = 30;  // 0.5 s
    FrameRenderer renderer(scene_, lights, s);
    const ReferenceFrame reference = renderReference(renderer, frame);
    renderer.render(0);
    const ImageDifference moved = compareImages(renderer.readLdr(), reference.ldr);
    std::printf("CesiumMan naive, 0 s against 0.5 s: %.2f %% of pixels differ by more than 1/255\n", moved.badPixelShare * 100.0);
    EXPECT_GT(moved.badPixelShare, 0.005);
    expectEveryMethodHoldsTheContract(renderer, frame, reference, "CesiumMan at 0.5 s " + std::to_string(kWidth) + "x" + std::to_string(kHeight), 1e-4);
}

}  // namespace
}  // namespace ml::test
