// Screenshots of the view's window: what is on screen, the panel included (F12,
// --screenshot-window), as opposed to the renderer's own image (--screenshot).
#pragma once

#include <filesystem>

#include "renderer/image/image.h"

namespace ml::app {

// The default framebuffer's back buffer (call after drawing, before swapping), top row first.
// Alpha is forced to 255: ImGui's blending leaves partial alpha, which a PNG would show as holes.
RgbaImage readWindowPixels(int width, int height);

// manylights-YYYYMMDD-HHMMSS.png in `dir`, with -2, -3, ... added rather than overwrite a file.
std::filesystem::path freeScreenshotPath(const std::filesystem::path& dir);

}  // namespace ml::app
