#include "gpu_test.h"

#include <array>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/gl/debug_output.h"
#include "scenes/scene_library.h"

namespace ml::test {

void GpuTest::SetUp() {
    try {
        context_ = createEglContext(ContextOptions{OffscreenBackend::Egl, true});
    } catch (const ContextError& e) {
        GTEST_FAIL() << "no EGL context for GPU tests: " << e.what();
    }
    gl::enableDebugOutput(gl::DebugVerbosity::ErrorsOnly);
    gl::resetDebugErrors();
}

void GpuTest::TearDown() {
    if (context_) {
        EXPECT_EQ(gl::drainGlErrors(), "");
        EXPECT_EQ(gl::debugErrorCount(), 0) << "KHR_debug error: " << gl::lastDebugError();
    }
    context_.reset();
}

std::filesystem::path testOutputDir() {
    const char* env = std::getenv("ML_TEST_TMP");
    std::filesystem::path root = env ? env : std::filesystem::temp_directory_path() / "manylights-tests";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    if (info) root /= std::string(info->test_suite_name()) + "." + info->name();
    std::filesystem::create_directories(root);
    return root;
}

std::string writeFailureImages(const std::string& name, const RgbaImage& test, const RgbaImage& reference) {
    const std::filesystem::path dir = testOutputDir() / name;
    std::filesystem::create_directories(dir);
    writePng((dir / "test.png").string(), test);
    writePng((dir / "reference.png").string(), reference);
    if (test.width == reference.width && test.height == reference.height)
        writePng((dir / "diff.png").string(), differenceImage(test, reference));
    return dir.string();
}

TestScene testScene(const std::string& name, std::uint32_t count, std::uint32_t seed, float radiusScale, float spotShare) {
    std::vector<std::string> warnings;
    TestScene t{loadScene(SceneRequest{name, 0.25f}, warnings), {}};
    LightGeneration gen;
    gen.count = count;
    gen.seed = seed;
    gen.radius = defaultLightRadius(t.scene.bounds) * radiusScale;
    gen.spotShare = spotShare;
    t.lights = generateLights(lightVolume(t.scene.bounds), gen);
    return t;
}

Scene quadScene(const std::vector<TestQuad>& quads) {
    Scene scene;
    scene.name = "quads";
    for (const TestQuad& q : quads) {
        const glm::vec3 n = glm::normalize(glm::cross(q.u, q.v));
        const auto first = static_cast<std::uint32_t>(scene.vertices.size());
        const glm::vec3 corners[4] = {q.center - q.u - q.v, q.center + q.u - q.v, q.center + q.u + q.v, q.center - q.u + q.v};
        const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int i = 0; i < 4; ++i) scene.vertices.push_back(Vertex{corners[i], n, uvs[i]});
        const auto firstIndex = static_cast<std::uint32_t>(scene.indices.size());
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(first + i);
        Material m;
        m.name = "quad" + std::to_string(scene.materials.size());
        m.baseColorFactor = glm::vec4(q.color, 1.0f);
        scene.draws.push_back(DrawRange{firstIndex, 6, static_cast<std::uint32_t>(scene.materials.size())});
        scene.materials.push_back(m);
    }
    computeBounds(scene);
    return scene;
}

std::vector<MethodError> clusteredErrors(const Scene& scene, const std::vector<Light>& lights, FrameSettings s,
                                         std::uint32_t frame) {
    const ClusteringSettings clustering = s.method.clustering;
    s.method = MethodSettings{};
    FrameRenderer renderer(scene, lights, s);
    renderer.render(frame);
    const FloatImage referenceHdr = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();
    std::vector<MethodError> errors;
    for (MethodKind kind : {MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        MethodSettings m;
        m.kind = kind;
        m.clustering = clustering;
        renderer.setMethod(m);
        renderer.render(frame);
        const ClusterStatistics stats = renderer.method().clustering()->statistics();
        MethodError e;
        e.method = methodName(kind);
        e.max8Bit = compareImages(renderer.readLdr(), referenceLdr).maxAbs * 255.0;
        e.psnrDb = compareImages(renderer.readHdr(), referenceHdr).psnrDb;
        e.droppedReferences = stats.droppedReferences;
        e.listEntries = stats.listEntries;
        e.emptyClusterShare = stats.emptyShare;
        errors.push_back(e);
    }
    return errors;
}

void expectWithinContract(const std::vector<MethodError>& errors, const std::string& label) {
    for (const MethodError& e : errors) {
        std::printf("%-28s %-13s max8 %.3f  psnr %6.1f dB  entries %llu  empty %.1f %%  dropped %llu\n", label.c_str(),
                    e.method.c_str(), e.max8Bit, e.psnrDb, static_cast<unsigned long long>(e.listEntries),
                    100.0 * e.emptyClusterShare, static_cast<unsigned long long>(e.droppedReferences));
        EXPECT_LE(e.max8Bit, 1.0 + 1e-6) << label << ": " << e.method;
        EXPECT_GE(e.psnrDb, 50.0) << label << ": " << e.method;
        EXPECT_EQ(e.droppedReferences, 0u) << label << ": " << e.method;
    }
}

FrameSettings smallFrame(const Scene& scene, int width, int height) {
    FrameSettings s = smallFrame(scene, scene.suggestedView.value_or(framingView(scene.bounds)), width, height);
    s.animation = verticalDrift(lightVolume(scene.bounds), 0.5f);
    return s;
}

FrameSettings smallFrame(const Scene& scene, const CameraPose& pose, int width, int height) {
    FrameSettings s;
    s.width = width;
    s.height = height;
    s.camera = cameraFromPose(pose);
    fitClipPlanes(s.camera, scene.bounds);
    s.animation = verticalDrift(lightVolume(scene.bounds), 0.0f);
    setLightModel(s, s.lightModel);
    return s;
}

void setLightModel(FrameSettings& s, const LightModel& model) {
    s.lightModel = model;
    s.exposure = unitlessLightExposure(model.brdf);
    s.ambient = FrameSettings{}.ambient / unitlessLightExposure(model.brdf);
}

ReferenceFrame readReference(const FrameRenderer& renderer) { return {renderer.readHdr(), renderer.readLdr()}; }

ReferenceFrame renderReference(FrameRenderer& renderer, std::uint32_t frame) {
    renderer.render(frame);
    return readReference(renderer);
}

ReferenceFrame expectClusteredVariantsMatchNaive(FrameRenderer& renderer, const std::string& label, std::uint32_t frame) {
    const ReferenceFrame naive = renderReference(renderer, frame);
    for (const ClusteredVariant& v : kClusteredVariants) {
        MethodSettings m;
        m.kind = v.kind;
        m.resolve = v.resolve;
        renderer.setMethod(m);
        renderer.render(frame);
        expectWithinContract(renderer, naive, label + " " + v.name, label + "_" + std::to_string(int(v.kind)) + "_" + std::to_string(int(v.resolve)));
    }
    return naive;
}

ImageDifference expectWithinContract(const FrameRenderer& renderer, const ReferenceFrame& reference, const std::string& label,
                                     const std::string& imageName) {
    const ImageDifference hdr = compareImages(renderer.readHdr(), reference.hdr);
    const RgbaImage ldr = renderer.readLdr();
    const ImageDifference ldrDiff = compareImages(ldr, reference.ldr);
    std::printf("%-50s max8 %.4f  psnr %.1f dB\n", label.c_str(), ldrDiff.maxAbs * 255.0, hdr.psnrDb);
    EXPECT_LE(ldrDiff.maxAbs, kMaxAbs8Bit) << label << ": images in " << writeFailureImages(imageName.empty() ? label : imageName, ldr, reference.ldr);
    EXPECT_GE(hdr.psnrDb, kMinPsnrDb) << label;
    return hdr;
}

NaiveReferenceScene::NaiveReferenceScene(const char* scene, std::uint32_t lights, std::uint32_t frameIndex)
    : test(testScene(scene, lights, 5, lights >= 1024 ? 0.5f : 1.0f)),
      renderer(test.scene, test.lights, smallFrame(test.scene, 160, 90)),
      frame(frameIndex) {
    renderer.render(frame);
    reference = readReference(renderer);
}

std::string testNameOf(const std::string& text) {
    std::string name;
    for (char c : text) {
        const bool word = std::isalnum(static_cast<unsigned char>(c)) != 0;
        if (word) name += c;
        else if (!name.empty() && name.back() != '_') name += '_';
    }
    while (!name.empty() && name.back() == '_') name.pop_back();
    return name.empty() ? "empty" : name;
}

int runManylights(const std::string& args, std::string& output, const std::string& workingDir, const std::string& wrapper) {
    const std::string cd = workingDir.empty() ? "" : "cd \"" + workingDir + "\" && ";
    const std::string prefix = wrapper.empty() ? "" : wrapper + " ";
    const std::string command = cd + prefix + "\"" + ML_MANYLIGHTS_EXE + "\" " + args + " 2>&1";
    output.clear();
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return -1;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool haveXvfb() { return std::system("command -v xvfb-run >/dev/null 2>&1") == 0; }

int runViewUnderXvfb(const std::string& args, std::string& output) {
    const std::string server = std::to_string(100 + getpid() % 800);
    return runManylights("view " + args, output, "", "xvfb-run -a -n " + server + " -s '-screen 0 1024x768x24'");
}

}  // namespace ml::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
