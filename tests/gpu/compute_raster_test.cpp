// The visibility buffer's compute raster (renderer/passes/compute_raster.h) against the hardware
// raster it replaces: the same triangle id at every pixel, but where two surfaces tie in depth.
// On llvmpipe its two-pass (32-bit) atomics run; the one-pass 64-bit path runs on GPUs that have
// GL_NV_shader_atomic_int64 (the H100 record, docs/bench/nvidia-h100/compute-raster/).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "gpu_test.h"
#include "raster_ids.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/methods/visibility_buffer.h"
#include "renderer/passes/compute_raster.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

class ComputeRasterTest : public GpuTest {};

// Both resolves: `compute` is the one-pass 64-bit path where the GPU has it (the H100), and the
// two-pass path again where not (llvmpipe).
TEST_F(ComputeRasterTest, BuiltInScenesGiveTheHardwareIds) {
    for (const std::string& name : builtinSceneNames()) {
        const TestScene t = testScene(name, 64, 7);
        FrameRenderer renderer(t.scene, t.lights, smallFrame(t.scene, 320, 180));
        const RasterResult hardware = visibilityRaster(renderer, VisibilityRaster::Hardware);
        for (VisibilityRaster raster : {VisibilityRaster::ComputeTwoPass, VisibilityRaster::Compute}) {
            const std::string label = name + " " + visibilityRasterName(ComputeRaster::resolve(raster));
            SCOPED_TRACE(label);
            const RasterResult compute = visibilityRaster(renderer, raster);
            ASSERT_EQ(hardware.ids.size(), compute.ids.size());
            const IdDifference d = compareIds(hardware, compute, 320, label);
            EXPECT_EQ(d.coverage, 0u) << d.pixels << " pixels differ";
        }
    }
}

// For fitted slicing the finish reduces the view depth it writes (cluster.depth-range then reads
// no depth): the sliced range is the least and greatest view depth of the drawn pixels, as the
// CPU finds them in the same depth read back. At sizes whose rows end inside a finishing
// workgroup; the atrium with its glass left out (the glass's extent widens the range).
TEST_F(ComputeRasterTest, TheFinishReducesTheSlicedDepthRange) {
    for (const std::string& name : {std::string("atrium"), std::string("boxes")}) {
        for (const auto& [width, height] : {std::pair{320, 180}, std::pair{333, 187}}) {
            const std::string label = name + " " + std::to_string(width) + "x" + std::to_string(height);
            SCOPED_TRACE(label);
            const TestScene t = testScene(name, 64, 7);
            FrameSettings s = smallFrame(t.scene, width, height);
            s.transparency = false;
            FrameRenderer renderer(t.scene, t.lights, s);
            const RasterResult compute = visibilityRaster(renderer, VisibilityRaster::Compute);
            const glm::mat4 inverseProj = glm::inverse(renderer.uniforms().proj);
            float nearest = INFINITY, farthest = 0.0f;
            for (float depth : compute.depth) {
                if (depth <= 0.0f) continue;
                const glm::vec4 v = inverseProj * glm::vec4(0.0f, 0.0f, depth, 1.0f);
                nearest = std::min(nearest, -v.z / v.w);
                farthest = std::max(farthest, -v.z / v.w);
            }
            ASSERT_LT(nearest, farthest) << "the frame draws something";
            const ClusterGridGpu grid = renderer.method().clustering()->downloadGrid();
            EXPECT_NEAR(grid.slicing.x, nearest, 1e-5f * nearest);
            EXPECT_NEAR(grid.slicing.y, farthest, 1e-5f * farthest);
        }
    }
}

// Pixel centres on edges: a camera square on a grid of quads whose corners land on pixel centres
// and pixel edges, so the fill rule decides every shared edge.
TEST_F(ComputeRasterTest, EdgesThroughPixelCentresFollowTheFillRule) {
    std::vector<TestQuad> quads;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 10; ++x)
            quads.push_back({{-4.5f + float(x), -2.5f + float(y), 0.0f}, {0.5f, 0.0f, 0.0f}, {0.0f, 0.5f, 0.0f},
                             {0.1f * float(x), 0.15f * float(y), 0.5f}});
    const Scene scene = quadScene(quads);
    // 60 degrees vertically at distance d = 3 / tan(30 deg) spans y in [-3, 3] over 180 pixels: 30
    // pixels a unit, quad corners on pixel edges (half units: centres too, after the offset).
    for (float offset : {0.0f, 1.0f / 60.0f}) {
        SCOPED_TRACE(offset);
        const float d = 3.0f / std::tan(glm::radians(30.0f));
        FrameRenderer renderer(scene, {}, smallFrame(scene, CameraPose{{offset, offset, d}, {offset, offset, 0.0f}, 60.0f}, 320, 180));
        const RasterResult hardware = visibilityRaster(renderer, VisibilityRaster::Hardware);
        const RasterResult compute = visibilityRaster(renderer, VisibilityRaster::ComputeTwoPass);
        const IdDifference d2 = compareIds(hardware, compute, 320, "grid");
        EXPECT_EQ(d2.pixels, 0u);
    }
}

// The atrium (64 lights, seed 7) from `pose` (its default view where none), rastered by the
// hardware and by the compute raster's two-pass path, with where the compute raster sent its
// triangles and how many pixels differ.
struct AtriumRasters {
    ComputeRaster::Work work;
    IdDifference difference;
};
AtriumRasters atriumRasters(std::optional<CameraPose> pose, int width, int height, bool clipsToViewport, const std::string& label) {
    const TestScene t = testScene("atrium", 64, 7);
    FrameRenderer renderer(t.scene, t.lights, pose ? smallFrame(t.scene, *pose, width, height) : smallFrame(t.scene, width, height));
    const RasterResult hardware = visibilityRaster(renderer, VisibilityRaster::Hardware);
    const RasterResult compute = visibilityRaster(renderer, VisibilityRaster::ComputeTwoPass, clipsToViewport);
    const ComputeRaster::Work work = dynamic_cast<const VisibilityBuffer&>(renderer.method()).computeRaster()->lastWork();
    return {work, compareIds(hardware, compute, width, label)};
}

// With the viewport clipping llvmpipe does turned off, the triangles that cross the eye plane
// are rastered unclipped, by homogeneous edge planes. A camera inside the atrium has them. The
// hardware (llvmpipe) clips triangles that cross the viewport's sides, moving their edges by
// up to half a sub-pixel step: a few silhouette pixels may differ, none in large numbers.
TEST_F(ComputeRasterTest, TrianglesAcrossTheEyePlaneAreRasteredUnclipped) {
    const AtriumRasters r = atriumRasters(CameraPose{{-15.0f, 1.7f, -6.3f}, {15.0f, 1.7f, -6.3f}, 60.0f}, 320, 180, false, "atrium inside");
    EXPECT_GT(r.work.clipped, 0u) << "no triangle crossed the eye plane: the test tests nothing";
    EXPECT_LE(r.difference.coverage, 320u * 180u / 2000u) << r.difference.pixels << " pixels differ";
}

// The atrium's floor, from its default camera, reaches so far beside the eye that its window
// positions pass the guard band (2^14 pixels), where snapped 64-bit edges would overflow: it is
// rastered as homogeneous planes too, with the viewport clipping llvmpipe does turned off (the
// silhouette pixels of triangles that cross the viewport's sides may differ, as above).
TEST_F(ComputeRasterTest, TrianglesPastTheGuardBandAreRasteredAsPlanes) {
    const AtriumRasters r = atriumRasters(std::nullopt, 640, 360, false, "atrium default");
    EXPECT_GT(r.work.clipped, 0u) << "no triangle went to the planes: the test tests nothing";
    EXPECT_EQ(r.work.hardware, 0u);
    EXPECT_LE(r.difference.coverage, 640u * 360u / 2000u) << r.difference.pixels << " pixels differ";
}

// The atrium's foliage is alpha-tested: rastered in compute by the setup where small and by the
// alpha-tested tile pass where large, each pixel alpha-tested as the hardware raster's fragments
// are, so the ids are the hardware's.
TEST_F(ComputeRasterTest, AlphaTestedTrianglesAreRasteredInCompute) {
    const AtriumRasters r = atriumRasters(std::nullopt, 640, 360, true, "atrium foliage");
    EXPECT_GT(r.work.alphaLarge, 0u) << "no alpha-tested triangle reached the tile pass: the test tests it not";
    EXPECT_GT(r.work.alphaTested, r.work.alphaLarge + r.work.alphaHardware) << "no alpha-tested triangle was small";
    EXPECT_EQ(r.difference.coverage, 0u) << r.difference.pixels << " pixels differ";
}

// A large triangle whose bounds span at most ML_RASTER_FINE_EXTENT pixels takes 8x8 tiles, a
// pixel an invocation, the others 16x16 tiles, four pixels of a column an invocation; an opaque
// one of at most ML_RASTER_SETUP_BIN_TILES 8x8 tiles is binned by its setup invocation, the rest
// by the binning: at 640x360 the atrium has each, opaque and alpha-tested, and every pixel keeps
// the hardware's id.
TEST_F(ComputeRasterTest, LargeTrianglesOfSmallBoundsTakeEightByEightTiles) {
    for (const std::optional<CameraPose>& pose : {std::optional<CameraPose>(), std::optional<CameraPose>(CameraPose{{-16.0f, 3.0f, -4.5f}, {16.0f, 1.5f, 4.5f}, 60.0f})}) {
        const AtriumRasters r = atriumRasters(pose, 640, 360, true, "atrium fine tiles");
        EXPECT_GT(r.work.fineTiles, 0u) << "no 8x8 tile: the test tests them not";
        EXPECT_LT(r.work.fineTiles, r.work.tiles) << "no 16x16 tile";
        EXPECT_GT(r.work.setupBinned, 0u) << "no triangle binned by its setup";
        EXPECT_LT(r.work.setupBinned, r.work.large) << "no triangle binned by the binning";
        EXPECT_GT(r.work.alphaFineTiles, 0u) << "no alpha-tested 8x8 tile";
        EXPECT_EQ(r.difference.coverage, 0u) << r.difference.pixels << " pixels differ";
    }
}

// Past the pair list (more than 64 layers of the screen's tiles) a triangle goes to the hardware,
// and the tile pass reads only the pairs written before the first that did not fit: never a slot
// an earlier frame left. Two stacks of 1,500 quads seen from afar fill the list with pairs whose
// triangles are the right stack's; then, close to the left stack alone (the right one out of
// view), the list overflows again with fewer large triangles, and a stale pair would raster a
// record of the frame before: the right stack where this view has nothing.
TEST_F(ComputeRasterTest, PairsPastTheListGoToTheHardwareAndNoStaleSlotIsRead) {
    std::vector<TestQuad> quads;
    for (float side : {-2.0f, 2.0f})
        for (int i = 0; i < 1500; ++i)
            quads.push_back({{side, 0.0f, -0.0005f * float(i)}, {0.8f, 0.0f, 0.0f}, {0.0f, 0.8f, 0.0f}, {0.5f + side * 0.1f, 0.5f, 0.0005f * float(i)}});
    const Scene scene = quadScene(quads);
    const CameraPose far{{0.0f, 0.0f, 8.0f}, {0.0f, 0.0f, 0.0f}, 60.0f}, close{{-2.0f, 0.0f, 3.0f}, {-2.0f, 0.0f, 0.0f}, 60.0f};
    FrameSettings s = smallFrame(scene, far, 320, 180);
    s.method.kind = MethodKind::Visibility;
    s.method.visibilityRaster = VisibilityRaster::ComputeTwoPass;
    FrameRenderer renderer(scene, {}, s);
    renderer.render(0);
    const auto& method = dynamic_cast<const VisibilityBuffer&>(renderer.method());
    const ComputeRaster::Work farWork = method.computeRaster()->lastWork();
    EXPECT_GT(farWork.hardware, 0u) << "the far view's pairs fit the list: the test tests nothing";
    renderer.setCamera(smallFrame(scene, close, 320, 180).camera);
    renderer.render(0);
    const ComputeRaster::Work closeWork = method.computeRaster()->lastWork();
    EXPECT_GT(closeWork.hardware, 0u) << "the close view's pairs fit the list: the test tests nothing";
    EXPECT_LT(closeWork.large, farWork.large) << "the close view has as many large triangles: no stale record to read";
    const RasterResult compute = lastRaster(renderer);
    FrameRenderer fresh(scene, {}, smallFrame(scene, close, 320, 180));
    const RasterResult hardware = visibilityRaster(fresh, VisibilityRaster::Hardware);
    const IdDifference d = compareIds(hardware, compute, 320, "close after far");
    EXPECT_EQ(d.coverage, 0u) << d.pixels << " pixels differ";
}

// The store is not reset between frames (every other frame inverts its words; the finish empties
// only the pixels a frame left): views in turn, a covered one and one up at the sky, each frame's
// ids against the hardware raster's of the same view, so a pixel drawn two frames before, left
// the frame before, or drawn in both orders is held to what the view alone gives.
TEST_F(ComputeRasterTest, FramesInTurnGiveEachViewsHardwareIds) {
    const TestScene t = testScene("atrium", 64, 7);
    const CameraPose open{{0.0f, 2.0f, 0.0f}, {0.0f, 30.0f, 1.0f}, 60.0f};
    FrameSettings covered = smallFrame(t.scene, 320, 180);
    const FrameSettings openFrame = smallFrame(t.scene, open, 320, 180);
    covered.method.kind = MethodKind::Visibility;
    covered.method.visibilityRaster = VisibilityRaster::Compute;
    FrameRenderer renderer(t.scene, t.lights, covered);
    RasterResult expected[2];
    for (int view = 0; view < 2; ++view) {
        FrameRenderer fresh(t.scene, t.lights, view == 0 ? covered : openFrame);
        expected[view] = visibilityRaster(fresh, VisibilityRaster::Hardware);
    }
    std::size_t background = 0;
    for (std::uint32_t id : expected[1].ids) background += id == 0u ? 1u : 0u;
    ASSERT_GT(background, 320u * 180u / 10u) << "the open view shows no sky: the test tests nothing";
    for (int frame = 0; frame < 6; ++frame) {
        const int view = (frame / 2 + frame) % 2;  // covered, open, open, covered, covered, open
        const std::string label = "frame " + std::to_string(frame) + (view == 0 ? " covered" : " open");
        SCOPED_TRACE(label);
        renderer.setCamera((view == 0 ? covered : openFrame).camera);
        renderer.render(0);
        const IdDifference d = compareIds(expected[view], lastRaster(renderer), 320, label);
        EXPECT_EQ(d.coverage, 0u) << d.pixels << " pixels differ";
    }
}

}  // namespace
}  // namespace ml::test
