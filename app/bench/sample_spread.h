// The median and spread of repeated timings: what `bench` reports per frame and per pass.
#pragma once

#include <vector>

namespace ml::app {

struct SampleSpread {
    double median = 0.0;
    double p10 = 0.0;  // 10th percentile
    double p90 = 0.0;  // 90th percentile
};

// Percentiles by linear interpolation between the sorted samples (numpy's default), so ten
// frames give p10 between the fastest two. Empty input gives zeros.
SampleSpread spreadOf(std::vector<double> samples);

// The q-quantile (q in [0, 1]) of sorted samples, by the same interpolation.
double quantileOfSorted(const std::vector<double>& sorted, double q);

}  // namespace ml::app
