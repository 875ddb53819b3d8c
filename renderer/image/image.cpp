#include "renderer/image/image.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

namespace ml {

void writePng(const std::string& path, const RgbaImage& image) {
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.pixels.data(), image.width * 4))
        throw std::runtime_error(path + ": cannot write PNG");
}

RgbaImage readPng(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) throw std::runtime_error(path + ": cannot read image (" + std::string(stbi_failure_reason()) + ")");
    RgbaImage image{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 4)};
    stbi_image_free(data);
    return image;
}

void writePfm(const std::string& path, const FloatImage& image) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot write PFM");
    // A negative scale marks little-endian data; PFM stores the bottom row first.
    out << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
    for (int y = image.height - 1; y >= 0; --y)
        out.write(reinterpret_cast<const char*>(image.at(0, y)), static_cast<std::streamsize>(image.width) * 3 * sizeof(float));
    if (!out) throw std::runtime_error(path + ": write failed");
}

FloatImage readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open PFM");
    std::string magic;
    FloatImage image;
    float scale = 0.0f;
    in >> magic >> image.width >> image.height >> scale;
    in.get();
    if (magic != "PF" || image.width <= 0 || image.height <= 0 || image.width > 65536 || image.height > 65536 || scale >= 0.0f)
        throw std::runtime_error(path + ": not a little-endian RGB PFM file");
    image.pixels.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = image.height - 1; y >= 0; --y)
        in.read(reinterpret_cast<char*>(&image.pixels[static_cast<std::size_t>(y) * image.width * 3]),
                static_cast<std::streamsize>(image.width) * 3 * sizeof(float));
    if (!in) throw std::runtime_error(path + ": truncated PFM");
    return image;
}

}  // namespace ml
