// Deferred's G-buffer is not cleared between frames (a colour clear costs a full-screen layer of
// writes on an H100): every reader takes depth 1.0 as background; the visibility buffer's ids
// are cleared by compute. A frame whose background was covered in the frame before must be
// identical to the same frame rendered first, for both.
#include <gtest/gtest.h>

#include "gpu_test.h"

namespace ml::test {
namespace {

class UnclearedTargets : public GpuTest {};

TEST_F(UnclearedTargets, AFrameAfterAnotherViewEqualsTheSameFrameRenderedFirst) {
    const TestScene t = testScene("atrium", 64, 7);
    // Covered: the atrium's suggested view. Open: up from the courtyard, the sky beyond the roof.
    const CameraPose open{{0.0f, 2.0f, 0.0f}, {0.0f, 30.0f, 1.0f}, 60.0f};
    for (MethodKind kind : {MethodKind::Deferred, MethodKind::Visibility}) {
        SCOPED_TRACE(methodName(kind));
        FrameSettings covered = smallFrame(t.scene, 160, 90);
        covered.method.kind = kind;
        FrameSettings openFrame = smallFrame(t.scene, open, 160, 90);
        openFrame.method.kind = kind;

        FrameRenderer fresh(t.scene, t.lights, openFrame);
        fresh.render(0);
        const FloatImage first = fresh.readHdr();

        FrameRenderer reused(t.scene, t.lights, covered);
        reused.render(0);
        const FloatImage coveredImage = reused.readHdr();
        reused.setCamera(openFrame.camera);
        reused.render(0);
        const FloatImage after = reused.readHdr();

        // The test means something only if the open view's background was drawn over before.
        std::size_t uncovered = 0;
        for (std::size_t i = 0; i < first.pixels.size(); i += 3)
            if (first.pixels[i] == 0.0f && first.pixels[i + 1] == 0.0f && first.pixels[i + 2] == 0.0f &&
                coveredImage.pixels[i] + coveredImage.pixels[i + 1] + coveredImage.pixels[i + 2] > 0.0f)
                ++uncovered;
        EXPECT_GT(uncovered, first.pixels.size() / 3 / 20) << "the open view must show background where the covered view drew";
        EXPECT_EQ(compareImages(after, first).maxAbs, 0.0) << "the previous frame leaked through the uncleared targets";
    }
}

}  // namespace
}  // namespace ml::test
