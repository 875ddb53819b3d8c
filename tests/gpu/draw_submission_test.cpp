// --draw indirect (multi-draw indirect, one call per base-colour texture) against --draw direct
// (one call per draw range): the same ranges in the same order through the same shaders, so
// every method's frame is bit-identical, and fewer calls are issued.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "gpu_test.h"

namespace ml::test {
namespace {

class DrawSubmissionTest : public GpuTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(DrawSubmissionTest, IndirectEqualsDirectForEveryMethod) {
    const TestScene t = testScene(GetParam(), 256, 3);
    FrameSettings s = smallFrame(t.scene, 160, 90);
    FrameRenderer renderer(t.scene, t.lights, s);
    for (MethodKind kind : {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        MethodSettings m;
        m.kind = kind;
        renderer.setMethod(m);
        renderer.setDrawSubmission(DrawSubmission::Direct);
        renderer.render(10);
        const std::size_t directCalls = renderer.scene().drawCallsPerPass();
        const FloatImage directHdr = renderer.readHdr();
        const RgbaImage directLdr = renderer.readLdr();
        renderer.setDrawSubmission(DrawSubmission::Indirect);
        renderer.render(10);
        const ImageDifference d = compareImages(renderer.readHdr(), directHdr);
        EXPECT_EQ(d.maxAbs, 0.0) << methodName(kind) << ": images in "
                                 << writeFailureImages(std::string(GetParam()) + "-" + methodName(kind), renderer.readLdr(), directLdr);
        EXPECT_EQ(directCalls, renderer.scene().drawRangeCount());
        EXPECT_LE(renderer.scene().drawCallsPerPass(), directCalls);
        EXPECT_GE(renderer.scene().drawCallsPerPass(), 1u);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, DrawSubmissionTest, ::testing::Values("atrium", "boxes", "plane"),
                         [](const auto& info) { return testNameOf(info.param); });

TEST(DrawSubmissionFlag, BadValueIsOneLine) {
    std::string output;
    EXPECT_NE(runManylights("render --draw bundles --out /dev/null", output), 0);
    EXPECT_NE(output.find("--draw 'bundles': expected direct or indirect"), std::string::npos) << output;
}

// The bench's --draw axis reaches the renderer: an indirect point issues fewer draw calls than a
// direct one (the renderer is kept between points of the same frame, so the submission must be
// set for each point).
TEST(DrawSubmissionFlag, BenchAxisSetsTheSubmissionPerPoint) {
    const std::string dir = testOutputDir().string();
    std::string output;
    ASSERT_EQ(runManylights("bench --size 64x36 --lights 4 --method visibility --draw indirect,direct "
                            "--warmup 0 --timed-frames 1 --name draw --out " + dir, output), 0) << output;
    std::ifstream csv(dir + "/draw.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    std::map<std::string, std::size_t> column;
    std::stringstream header(line);
    for (std::string name; std::getline(header, name, ',');) column[name] = column.size();
    ASSERT_TRUE(column.count("draw") && column.count("draw_calls")) << line;
    std::map<std::string, std::vector<int>> calls;
    while (std::getline(csv, line)) {
        std::vector<std::string> fields;
        std::stringstream row(line);
        for (std::string f; std::getline(row, f, ',');) fields.push_back(f);
        ASSERT_GT(fields.size(), column["draw_calls"]) << line;
        calls[fields[column["draw"]]].push_back(std::stoi(fields[column["draw_calls"]]));
    }
    ASSERT_EQ(calls["direct"].size(), 1u);
    ASSERT_EQ(calls["indirect"].size(), 1u);
    // The renderer was built for the indirect point; the direct one must not keep its submission.
    EXPECT_LT(calls["indirect"][0], calls["direct"][0]);
}

}  // namespace
}  // namespace ml::test
