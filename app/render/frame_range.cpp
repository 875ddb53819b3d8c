#include "app/render/frame_range.h"

#include <stdexcept>

namespace ml::app {

namespace {

// The limit prepareFrame puts on --frames.
constexpr unsigned long long kMaxFrame = 100'000'000;

std::uint32_t parseFrameNumber(const std::string& whole, const std::string& part) {
    const std::string usage = "--frames '" + whole + "': expected K or A..B (whole numbers 0 to 100000000, A <= B)";
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos || part.size() > 9)
        throw std::invalid_argument(usage);
    const unsigned long long v = std::stoull(part);
    if (v > kMaxFrame) throw std::invalid_argument(usage);
    return static_cast<std::uint32_t>(v);
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
    const std::size_t dots = text.find("..");
    if (dots == std::string::npos) {
        const std::uint32_t k = parseFrameNumber(text, text);
        return {k, k};
    }
    FrameRange r{parseFrameNumber(text, text.substr(0, dots)), parseFrameNumber(text, text.substr(dots + 2))};
    if (r.last < r.first)
        throw std::invalid_argument("--frames '" + text + "': the first frame is after the last (A..B needs A <= B)");
    return r;
}

}  // namespace ml::app
