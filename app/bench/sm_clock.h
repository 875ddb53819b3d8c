// The GPU's SM clock for the `sm_clock_mhz` column of `bench` and `raster-floors`: clock drops
// (thermal or power) slowed every pass of whole sweeps by 40 % on an H200 before, and a timing is
// only comparable with the clock it ran at.
#pragma once

#include <atomic>
#include <optional>
#include <thread>
#include <vector>

namespace ml::app {

// clocks.sm of GPU 0 in MHz; nullopt where neither NVML (libnvidia-ml.so.1, opened at run time)
// nor nvidia-smi answers (llvmpipe, other vendors). NVML reads in microseconds; nvidia-smi, the
// fallback, costs a process start (~0.1 s).
std::optional<int> querySmClockMhz();

// The SM clock read while some frames run: a read after glFinish can catch the GPU already back
// at its idle clock, so the clock is read on a thread while the GPU works, about every
// millisecond. The median of the reads is the clock most frames ran at (compare it with the
// median frame time); the lowest shows a drop that some frames met (an H100 at four million
// lights dipped to 345 MHz for a few frames of a point whose median frame ran at 1980).
struct SmClockReading {
    int medianMhz = 0;
    int lowestMhz = 0;
};

class SmClockSampler {
public:
    SmClockSampler() = default;
    SmClockSampler(const SmClockSampler&) = delete;
    SmClockSampler& operator=(const SmClockSampler&) = delete;
    ~SmClockSampler();

    void start();
    // The reads that ended while running (or, where none did, the first that ended after);
    // nullopt where no clock can be read or start() never ran.
    std::optional<SmClockReading> stop();

private:
    std::thread thread_;
    std::atomic<bool> running_{false};
    std::vector<int> reads_;          // reads that ended while running
    std::optional<int> lateRead_;     // the first read that ended after stop()
};

}  // namespace ml::app
