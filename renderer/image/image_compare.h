// How far an image drifts from a reference: the accuracy contract's numbers (design.md).
#pragma once

#include "renderer/image/image.h"

namespace ml {

struct ImageDifference {
    double maxAbs = 0.0;         // largest per-channel difference (float: linear units; 8-bit: /255)
    double meanAbs = 0.0;
    double rmse = 0.0;
    double psnrDb = 0.0;         // peak: the reference's maximum value (1 for 8-bit); +inf when identical
    double badPixelShare = 0.0;  // pixels with any channel off by more than 1/255 (8-bit) or by more than 1/255 of peak (float)
};

// Throws std::invalid_argument if the sizes differ.
ImageDifference compareImages(const FloatImage& test, const FloatImage& reference);
ImageDifference compareImages(const RgbaImage& test, const RgbaImage& reference);

// |test - reference| * gain per channel, for a person to look at.
RgbaImage differenceImage(const RgbaImage& test, const RgbaImage& reference, float gain = 8.0f);

}  // namespace ml
