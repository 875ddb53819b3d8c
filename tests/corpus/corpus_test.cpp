// The accuracy contract on files nobody here wrote (../shared/corpus, issue 23): every glTF file
// of the corpus, at its suggested view and at each camera it defines, with its own lights plus
// generated ones, rendered by naive and by every other method on the same frame. Each method is
// held to the 8-bit contract of design.md: at least 99.99 % of pixels within 1/255 of naive (at
// 160x90, at most one pixel off); the max error is printed. Where a model has a visible right
// answer (TextureTransformTest's checkmarks, AlphaBlendModeTest's cut-outs and blends,
// NormalTangentMirrorTest's spheres, MeshPrimitiveModes' strips and fans) it is asserted too.
// No file and no method has an exception: every method shades the surface rebuilt from its
// triangle alike (glsl/include/triangle_surface.glsl), and the exact G-buffer loses nothing.
//
// The corpus lives beside the checkout (ML_CORPUS_DIR), and the Draco files beside it
// (ML_COMPRESSED_DIR, instantiated as Compressed/...); where they are absent (a user's clone)
// the target says so in one line and skips.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/camera/camera.h"
#include "scenes/scene_library.h"
#include "tests/corpus/corpus.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/raster_ids.h"

namespace ml::test {
namespace {

namespace fs = std::filesystem;

// The share of pixels allowed over 1/255: design.md's 99.99 %.
constexpr double kMaxBadShare = 1e-4;
constexpr int kWidth = 160, kHeight = 90;

// The glTF files under `dir`, relative to the corpus ("../compressed/..." for ML_COMPRESSED_DIR).
std::vector<std::string> gltfFilesIn(const char* dir) {
    std::vector<std::string> files;
    std::error_code error;
    if (!fs::is_directory(dir, error) || !fs::is_directory(ML_CORPUS_DIR, error)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(dir, error)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
            files.push_back(fs::relative(entry.path(), ML_CORPUS_DIR).string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::string> corpusFiles() { return gltfFilesIn(ML_CORPUS_DIR); }
// Draco files (../shared/compressed), held to the same contract.
std::vector<std::string> compressedFiles() { return gltfFilesIn(ML_COMPRESSED_DIR); }

Scene loadCorpusScene(const std::string& relative) {
    std::vector<std::string> warnings;
    return loadScene(SceneRequest{corpusPath(relative), 1.0f}, warnings);
}

// The suggested view (as `--camera` left out gives), then each camera of the file (gltf:N).
struct NamedCamera {
    std::string name;
    Camera camera;
};
std::vector<NamedCamera> corpusCameras(const Scene& scene) {
    std::vector<NamedCamera> cameras;
    Camera suggested = cameraFromPose(scene.suggestedView.value_or(framingView(scene.bounds)));
    fitClipPlanes(suggested, scene.bounds);
    cameras.push_back({"default", suggested});
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        Camera c = cameraFromSceneCamera(scene.cameras[i]);
        fitClipPlanes(c, scene.bounds, scene.cameras[i]);
        cameras.push_back({"gltf:" + std::to_string(i), c});
    }
    return cameras;
}

class CorpusFile : public GpuTest, public ::testing::WithParamInterface<std::string> {};

// Every method against naive on the same frame, at every camera of `relative`; animated files
// posed at frame 30, with shadow rays too (the structure follows the pose: ShadowRays::refit).
void expectTheContractOnEveryCamera(const std::string& relative, Shadows shadows) {
    const Scene scene = loadCorpusScene(relative);
    const std::vector<Light> lights = ownAndGeneratedLights(scene);
    const std::uint32_t frame = 30;
    for (const NamedCamera& camera : corpusCameras(scene)) {
        FrameSettings s;
        s.width = kWidth;
        s.height = kHeight;
        s.camera = camera.camera;
        s.animation = verticalDrift(lightVolume(scene.bounds), 0.5f);
        s.shadows = shadows;
        FrameRenderer renderer(scene, lights, s);
        const ReferenceFrame reference = renderReference(renderer, frame);
        expectEveryMethodHoldsTheContract(renderer, frame, reference,
                                          relative + " " + camera.name + (shadows == Shadows::Rays ? ", shadows" : ""), kMaxBadShare);
    }
}

TEST_P(CorpusFile, EveryMethodHoldsTheContractAgainstNaive) { expectTheContractOnEveryCamera(GetParam(), Shadows::Off); }

// The same contract with --shadows rays (issue 62): naive traces the same rays as every other
// method, so a shadow changes nothing of the rule.
TEST_P(CorpusFile, EveryMethodHoldsTheContractWithShadows) { expectTheContractOnEveryCamera(GetParam(), Shadows::Rays); }

// The visibility buffer's compute raster gives the hardware raster's ids on every file and camera,
// but where two surfaces tie in depth (tests/gpu/compute_raster_test.cpp says why), and at no
// more pixels than the accuracy contract's share (1 in 10,000) elsewhere: a vertex whose window
// position lies within a rounding step of a sub-pixel boundary snaps by the last bit of the
// vertex transform, which the hardware computes its own way (ToyCar shows 1 or 2 such pixels at
// some cameras; the built-in scenes none). At 320x180: at 160x90 most triangles of most files
// are smaller than a pixel and few edges are tested.
TEST_P(CorpusFile, ComputeRasterGivesTheHardwareIds) {
    const Scene scene = loadCorpusScene(GetParam());
    for (const NamedCamera& camera : corpusCameras(scene)) {
        FrameSettings s;
        s.width = 320;
        s.height = 180;
        s.camera = camera.camera;
        FrameRenderer renderer(scene, {}, s);
        const RasterResult hardware = visibilityRaster(renderer, VisibilityRaster::Hardware);
        const RasterResult compute = visibilityRaster(renderer, VisibilityRaster::ComputeTwoPass);
        const std::string label = GetParam() + " " + camera.name;
        const IdDifference d = compareIds(hardware, compute, s.width, label);
        std::printf("%-70s ids differ at %zu pixels, %zu not a tie\n", label.c_str(), d.pixels, d.coverage);
        EXPECT_LE(double(d.coverage), kMaxBadShare * s.width * s.height) << label;
    }
}

// gtest names: "khronos/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf" -> "AlphaBlendModeTest_gltf".
std::string fileTestName(const std::string& relative) { return testNameOf(fs::path(relative).filename().string()); }

INSTANTIATE_TEST_SUITE_P(Corpus, CorpusFile, ::testing::ValuesIn(corpusFiles()),
                         [](const auto& info) { return fileTestName(info.param); });
INSTANTIATE_TEST_SUITE_P(Compressed, CorpusFile, ::testing::ValuesIn(compressedFiles()),
                         [](const auto& info) { return fileTestName(info.param); });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusFile);

// The one line a clone without the corpus prints.
TEST(Corpus, IsPresent) {
    if (corpusFiles().empty()) GTEST_SKIP() << "no glTF corpus at " << ML_CORPUS_DIR << " (../shared/corpus): corpus tests skipped";
}

}  // namespace
}  // namespace ml::test
