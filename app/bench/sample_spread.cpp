#include "app/bench/sample_spread.h"

#include <algorithm>
#include <cmath>

namespace ml::app {

double quantileOfSorted(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0.0;
    const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(sorted.size() - 1);
    const std::size_t below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    const double t = position - static_cast<double>(below);
    return sorted[below] + (sorted[above] - sorted[below]) * t;
}

SampleSpread spreadOf(std::vector<double> samples) {
    std::sort(samples.begin(), samples.end());
    return {quantileOfSorted(samples, 0.5), quantileOfSorted(samples, 0.1), quantileOfSorted(samples, 0.9)};
}

}  // namespace ml::app
