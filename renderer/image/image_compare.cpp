#include "renderer/image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ml {

namespace {

template <typename Pixel>
ImageDifference compareChannels(const Pixel* test, const Pixel* ref, std::size_t pixels, int channels, int stride,
                                double scale, double peak, double badThreshold) {
    ImageDifference d;
    double sumSq = 0.0, sumAbs = 0.0;
    std::size_t bad = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        double pixelMax = 0.0;
        for (int c = 0; c < channels; ++c) {
            const double a = static_cast<double>(test[p * stride + c]) * scale;
            const double b = static_cast<double>(ref[p * stride + c]) * scale;
            const double diff = std::isfinite(a) && std::isfinite(b) ? std::abs(a - b) : std::numeric_limits<double>::infinity();
            pixelMax = std::max(pixelMax, diff);
            sumSq += diff * diff;
            sumAbs += diff;
        }
        d.maxAbs = std::max(d.maxAbs, pixelMax);
        if (pixelMax > badThreshold) ++bad;
    }
    const double n = static_cast<double>(std::max<std::size_t>(pixels * channels, 1));
    d.rmse = std::sqrt(sumSq / n);
    d.meanAbs = sumAbs / n;
    d.psnrDb = d.rmse > 0.0 ? 20.0 * std::log10(peak / d.rmse) : std::numeric_limits<double>::infinity();
    d.badPixelShare = static_cast<double>(bad) / static_cast<double>(std::max<std::size_t>(pixels, 1));
    return d;
}

template <typename Image>
void checkSameSize(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                    " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
}

}  // namespace

ImageDifference compareImages(const FloatImage& test, const FloatImage& reference) {
    checkSameSize(test, reference);
    float peak = 0.0f;
    for (float v : reference.pixels) peak = std::max(peak, v);
    if (peak <= 0.0f) peak = 1.0f;  // an all-black reference: judge against unit range
    const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
    return compareChannels(test.pixels.data(), reference.pixels.data(), pixels, 3, 3, 1.0, peak, peak / 255.0);
}

ImageDifference compareImages(const RgbaImage& test, const RgbaImage& reference) {
    checkSameSize(test, reference);
    const std::size_t pixels = static_cast<std::size_t>(test.width) * test.height;
    // Colour channels only: alpha is always opaque in our output.
    return compareChannels(test.pixels.data(), reference.pixels.data(), pixels, 3, 4, 1.0 / 255.0, 1.0, 1.0 / 255.0 + 1e-9);
}

RgbaImage differenceImage(const RgbaImage& test, const RgbaImage& reference, float gain) {
    checkSameSize(test, reference);
    RgbaImage out{test.width, test.height, std::vector<std::uint8_t>(test.pixels.size(), 255)};
    for (std::size_t i = 0; i < test.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const float diff = std::abs(float(test.pixels[i]) - float(reference.pixels[i])) * gain;
        out.pixels[i] = static_cast<std::uint8_t>(std::min(diff, 255.0f));
    }
    return out;
}

}  // namespace ml
