// `render --frames`: one animation frame K (what it has always meant), or the sequence A..B,
// both ends included. Frame numbers are the animation's, so frame K of a sequence is the frame
// `render --frames K` writes.
#pragma once

#include <cstdint>
#include <string>

namespace ml::app {

struct FrameRange {
    std::uint32_t first = 0;
    std::uint32_t last = 0;

    std::uint32_t count() const { return last - first + 1; }
    bool several() const { return last > first; }
};

// "K" or "A..B" with A <= B, each at most 100000000. Throws std::invalid_argument naming the value.
FrameRange parseFrameRange(const std::string& text);

}  // namespace ml::app
