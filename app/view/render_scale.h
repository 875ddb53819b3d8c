// The view's internal resolution: the renderer draws at `scale` times the window's size and the
// image is scaled up (bilinear) to fill the window. On a software GL renderer (Mesa llvmpipe or
// softpipe) the cost of a frame is about proportional to its pixels, so `view` starts at a scale
// that keeps the pixels under a budget there: an answer in well under a second a frame on two
// cores instead of seconds (docs/desktop-demo.md: the times).
#pragma once

#include <string>

namespace ml::app {

inline constexpr float kMinRenderScale = 0.1f;
// About 320x180: the default atrium, 1024 lights, deferred, answered in ~0.3 s a frame under
// Xvfb on two shared cores (docs/desktop-demo.md).
inline constexpr double kSoftwarePixelBudget = 320.0 * 180.0;

// The scale that brings width x height under kSoftwarePixelBudget (1 when it already is),
// rounded down to a multiple of 1/20 so the panel shows a plain number.
float softwareRenderScale(int width, int height);

// Tiles across the automatic scale starts with when --tiles-x is not given: the light
// assignment's cost follows the cluster count, not the pixels, and was most of a software frame
// at 320x180 with the default 16 (0.36 of 0.45 s); 8 keeps tiles 40 pixels wide there.
inline constexpr unsigned kSoftwareTilesX = 8;

// A side at `scale`, at least one pixel.
int scaledSide(int side, float scale);

// "--render-scale 1.5: must be between 0.1 and 1". Throws std::invalid_argument.
void validateRenderScale(float scale);

}  // namespace ml::app
