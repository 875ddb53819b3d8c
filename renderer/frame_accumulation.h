// The mean of K draws of one frame (render --accumulate K, bench's "accumulate"): the lights and
// camera held still, the stochastic cut-off's ranges drawn anew each time, so the mean converges
// to the untruncated image as 1/sqrt(K). Deterministic: draw k of frame F is the same every run.
#pragma once

#include <cstdint>

#include "renderer/frame_renderer.h"
#include "renderer/image/image.h"

namespace ml {

// Renders draws 0..K-1 of `frameIndex` and returns the mean of their linear HDR outputs.
FloatImage renderAccumulated(FrameRenderer& renderer, std::uint32_t frameIndex, std::uint32_t draws);

}  // namespace ml
