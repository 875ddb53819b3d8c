// Naive-forward reference images kept by frame, so the points that share a frame (scene,
// lights, size, camera, animation frame) pay for the naive render once, not once per point.
// Bounded in bytes (a 2560x1440 reference takes 59 MB); the least recently used goes first.
#pragma once

#include <cstddef>
#include <list>
#include <string>

#include "renderer/image/image.h"

namespace ml::app {

struct ReferenceImages {
    FloatImage hdr;  // linear colour: the accuracy numbers
    RgbaImage ldr;   // tonemapped sRGB: what a person sees
    float exposure = 1.0f;  // the multiplier the tonemap applied (measured, with --exposure auto)
    std::size_t bytes() const { return hdr.pixels.size() * sizeof(float) + ldr.pixels.size(); }
};

class ReferenceCache {
public:
    explicit ReferenceCache(std::size_t maxBytes) : maxBytes_(maxBytes) {}

    // Null when the frame has no reference yet.
    const ReferenceImages* find(const std::string& frameKey);
    // Keeps the images (evicting older ones past the byte budget, never the newest).
    const ReferenceImages& insert(const std::string& frameKey, ReferenceImages images);

private:
    std::size_t maxBytes_;
    std::size_t bytes_ = 0;
    std::list<std::pair<std::string, ReferenceImages>> entries_;  // most recently used first
};

}  // namespace ml::app
