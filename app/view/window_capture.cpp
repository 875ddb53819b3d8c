#include "app/view/window_capture.h"

#include <cstring>
#include <ctime>

#include "renderer/gl/gl_api.h"

namespace ml::app {

RgbaImage readWindowPixels(int width, int height) {
    RgbaImage image{width, height, {}};
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> bottomUp(row * height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadnPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bottomUp.size()), bottomUp.data());
    image.pixels.resize(bottomUp.size());
    // GL's first row is the bottom one; images are stored top row first.
    for (int y = 0; y < height; ++y) std::memcpy(&image.pixels[y * row], &bottomUp[(height - 1 - y) * row], row);
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 255;
    return image;
}

std::filesystem::path freeScreenshotPath(const std::filesystem::path& dir) {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::filesystem::path path = dir / ("manylights-" + std::string(stamp) + ".png");
    for (int n = 2; std::filesystem::exists(path); ++n)
        path = dir / ("manylights-" + std::string(stamp) + "-" + std::to_string(n) + ".png");
    return path;
}

}  // namespace ml::app
