// Viewports far from the usual shape (issue: stability where methods fail): a single pixel,
// one pixel wide or tall strips, sizes smaller than the grid. Every clustered method stays
// exact against naive, with no GL error.
#include <gtest/gtest.h>

#include <cstdio>

#include "gpu_test.h"
#include "renderer/clustering/clustered_lighting.h"

namespace ml::test {
namespace {

struct Viewport {
    int width, height;
};

class ExtremeViewport : public GpuTest, public ::testing::WithParamInterface<Viewport> {};

TEST_P(ExtremeViewport, ClusteredMethodsMatchNaive) {
    const Viewport v = GetParam();
    const TestScene t = testScene("boxes", 64, 3);
    FrameSettings s = smallFrame(t.scene, v.width, v.height);
    FrameRenderer renderer(t.scene, t.lights, s);
    renderer.render(10);
    const FloatImage reference = renderer.readHdr();
    const RgbaImage referenceLdr = renderer.readLdr();
    for (MethodKind kind : {MethodKind::ForwardPlus, MethodKind::Deferred, MethodKind::Visibility}) {
        MethodSettings m;
        m.kind = kind;
        renderer.setMethod(m);
        renderer.render(10);
        const ImageDifference hdr = compareImages(renderer.readHdr(), reference);
        const ImageDifference ldr = compareImages(renderer.readLdr(), referenceLdr);
        EXPECT_LE(ldr.maxAbs, 1.0 / 255.0 + 1e-9) << methodName(kind);
        EXPECT_GE(hdr.psnrDb, 50.0) << methodName(kind);
        const ClusterGrid& grid = renderer.method().clustering()->grid();
        EXPECT_GE(grid.tilesX, 1u);
        EXPECT_GE(grid.tilesY, 1u);
    }
}

// Offscreen size changes between frames: every target follows, and the frame after each
// change matches naive at that size.
class ViewportResize : public GpuTest {};

TEST_F(ViewportResize, SizeChangesBetweenFramesStayExact) {
    const TestScene t = testScene("boxes", 64, 3);
    FrameSettings s = smallFrame(t.scene, 64, 36);
    FrameRenderer naive(t.scene, t.lights, s);
    s.method.kind = MethodKind::Visibility;
    FrameRenderer clustered(t.scene, t.lights, s);
    for (const Viewport v : {Viewport{200, 100}, Viewport{1, 1}, Viewport{33, 97}, Viewport{64, 36}}) {
        naive.resize(v.width, v.height);
        clustered.resize(v.width, v.height);
        naive.render(5);
        clustered.render(5);
        EXPECT_GE(compareImages(clustered.readHdr(), naive.readHdr()).psnrDb, 50.0) << v.width << "x" << v.height;
    }
}


INSTANTIATE_TEST_SUITE_P(Sizes, ExtremeViewport,
    ::testing::Values(Viewport{1, 1}, Viewport{3, 2}, Viewport{4096, 16}, Viewport{16, 4096}),
    [](const auto& info) { return std::to_string(info.param.width) + "x" + std::to_string(info.param.height); });

}  // namespace
}  // namespace ml::test
