// The visibility buffer's ids and depth by one raster or another (--vis-raster), read back, and
// how two of them differ: the compute raster's tests (tests/gpu/compute_raster_test.cpp, the
// corpus's) hold it to the hardware raster's ids.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/frame_renderer.h"

namespace ml::test {

// One frame's ids (triangle index + 1, 0 where nothing was drawn) and depth at every pixel.
struct RasterResult {
    std::vector<std::uint32_t> ids;
    std::vector<float> depth;
};

// Renders frame 0 by the visibility buffer with `raster` and reads its ids and depth back.
// `clipsToViewport` false runs the compute raster's homogeneous path where the GPU clips at the
// viewport (llvmpipe), which otherwise leaves the triangles that need it to the hardware.
RasterResult visibilityRaster(FrameRenderer& renderer, VisibilityRaster raster, bool clipsToViewport = true);
// The ids and depth of the frame `renderer` (running the visibility buffer) drew last.
RasterResult lastRaster(const FrameRenderer& renderer);

// Pixels whose ids differ, and of those, the ones whose depths differ too: a different surface,
// not a tie between two at one depth (which of them wins comes down to the depth's last bit; two
// triangles that share an edge tie on it).
struct IdDifference {
    std::size_t pixels = 0;
    std::size_t coverage = 0;
};
// Prints the first few differing pixels, labelled.
IdDifference compareIds(const RasterResult& reference, const RasterResult& test, int width, const std::string& label);

}  // namespace ml::test
