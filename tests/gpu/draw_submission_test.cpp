// --draw indirect (multi-draw indirect, one call per base-colour texture) against --draw direct
// (one call per draw range): the same ranges in the same order through the same shaders, so
// every method's frame is bit-identical, and fewer calls are issued.
#include <gtest/gtest.h>

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

INSTANTIATE_TEST_SUITE_P(Scenes, DrawSubmissionTest, ::testing::Values("atrium", "boxes", "plane"));

TEST(DrawSubmissionFlag, BadValueIsOneLine) {
    std::string output;
    EXPECT_NE(runManylights("render --draw bundles --out /dev/null", output), 0);
    EXPECT_NE(output.find("--draw 'bundles': expected direct or indirect"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
