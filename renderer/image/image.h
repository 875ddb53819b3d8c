// CPU images: 8-bit RGBA (tonemapped sRGB) and float RGB (linear HDR). Rows top to bottom.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ml {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 4
    const std::uint8_t* at(int x, int y) const { return &pixels[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

struct FloatImage {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;  // width * height * 3
    const float* at(int x, int y) const { return &pixels[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

// Throw std::runtime_error naming the path on failure.
void writePng(const std::string& path, const RgbaImage& image);
RgbaImage readPng(const std::string& path);
// Portable float map ("PF", little-endian, rows bottom to top on disk as the format says).
void writePfm(const std::string& path, const FloatImage& image);
FloatImage readPfm(const std::string& path);

}  // namespace ml
