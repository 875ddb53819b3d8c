// --view overdraw (renderer/passes/overdraw_pass.h): the count is the fragments that pass the depth
// test at their turn in the draw order, per pixel; the view shows them as colours, black where
// nothing was drawn.
#include <gtest/gtest.h>

#include "gpu_test.h"
#include "renderer/passes/overdraw_pass.h"

namespace ml::test {
namespace {

class OverdrawView : public GpuTest {};

constexpr int kWidth = 160, kHeight = 90;

// A large far quad and a small near one in front of its middle, drawn in the order given.
Scene farAndNearQuads(bool farFirst) {
    const TestQuad far{{0, 0, -1}, {1.5f, 0, 0}, {0, 1.0f, 0}};
    const TestQuad near{{0, 0, 0}, {0.4f, 0, 0}, {0, 0.4f, 0}};
    return farFirst ? quadScene({far, near}) : quadScene({near, far});
}

struct OverdrawFrame {
    std::vector<std::uint32_t> counts;
    RgbaImage ldr;
};

OverdrawFrame renderOverdraw(const Scene& scene, MethodKind kind) {
    FrameSettings s = smallFrame(scene, CameraPose{{0, 0, 3}, {0, 0, 0}, 60.0f}, kWidth, kHeight);
    s.method.kind = kind;
    s.method.clustering.view = DebugView::Overdraw;
    const std::vector<Light> lights = {Light{{0.0f, 0.0f, 1.0f}, 4.0f, {1.0f, 1.0f, 1.0f}}};
    FrameRenderer renderer(scene, lights, s);
    renderer.render(0);
    EXPECT_NE(renderer.overdraw(), nullptr);
    return {renderer.overdraw() ? renderer.overdraw()->readCounts() : std::vector<std::uint32_t>{}, renderer.readLdr()};
}

std::uint32_t at(const OverdrawFrame& f, int x, int y) { return f.counts[static_cast<std::size_t>(y) * kWidth + x]; }
const std::uint8_t* pixel(const OverdrawFrame& f, int x, int y) { return &f.ldr.pixels[(static_cast<std::size_t>(y) * kWidth + x) * 4]; }

TEST_F(OverdrawView, CountsTheFragmentsThatPassTheDepthTestInDrawOrder) {
    // Pixels: the middle (both quads), beside the near quad on the far one (the near quad spans
    // about 10 px either side of the middle, the far one 29), a corner (background).
    const int mx = kWidth / 2, my = kHeight / 2, sx = kWidth / 2 + 20, cx = 2, cy = 2;
    for (MethodKind kind : {MethodKind::Naive, MethodKind::Visibility}) {
        SCOPED_TRACE(methodName(kind));
        const OverdrawFrame farFirst = renderOverdraw(farAndNearQuads(true), kind);
        const OverdrawFrame nearFirst = renderOverdraw(farAndNearQuads(false), kind);
        ASSERT_EQ(farFirst.counts.size(), std::size_t(kWidth) * kHeight);
        ASSERT_EQ(nearFirst.counts.size(), std::size_t(kWidth) * kHeight);
        EXPECT_EQ(at(farFirst, mx, my), 2u) << "far quad first: the near one is shaded over it";
        EXPECT_EQ(at(nearFirst, mx, my), 1u) << "near quad first: the far one fails the depth test there";
        EXPECT_EQ(at(farFirst, sx, my), 1u);
        EXPECT_EQ(at(nearFirst, sx, my), 1u);
        EXPECT_EQ(at(farFirst, cx, cy), 0u);
        const OverdrawStatistics s = overdrawStatistics(farFirst.counts);
        EXPECT_GT(s.coveredPixels, 0u);
        EXPECT_EQ(s.maxPerPixel, 2u);
        EXPECT_EQ(overdrawStatistics(nearFirst.counts).fragments, s.coveredPixels) << "near first shades each pixel once";

        // The colours: black background; one count, one colour; 2 another.
        const std::uint8_t* bg = pixel(farFirst, cx, cy);
        EXPECT_EQ(bg[0] + bg[1] + bg[2], 0);
        const std::uint8_t* once = pixel(farFirst, sx, my);
        const std::uint8_t* twice = pixel(farFirst, mx, my);
        const std::uint8_t* onceAgain = pixel(nearFirst, mx, my);
        EXPECT_GT(once[0] + once[1] + once[2], 0);
        EXPECT_TRUE(once[0] == onceAgain[0] && once[1] == onceAgain[1] && once[2] == onceAgain[2]);
        EXPECT_FALSE(once[0] == twice[0] && once[1] == twice[1] && once[2] == twice[2]);
    }
}

}  // namespace
}  // namespace ml::test
