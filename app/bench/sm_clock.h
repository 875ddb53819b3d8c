// The GPU's SM clock for the `sm_clock_mhz` column of `bench` and `raster-floors`: clock drops
// (thermal or power) slowed every pass of whole sweeps by 40 % on an H200 before, and a timing is
// only comparable with the clock it ran at.
#pragma once

#include <atomic>
#include <optional>
#include <thread>

namespace ml::app {

// clocks.sm of GPU 0 in MHz; nullopt where neither NVML (libnvidia-ml.so.1, opened at run time)
// nor nvidia-smi answers (llvmpipe, other vendors). NVML reads in microseconds; nvidia-smi, the
// fallback, costs a process start (~0.1 s).
std::optional<int> querySmClockMhz();

// The lowest SM clock read while some frames run. A clock read after glFinish can catch the GPU
// already back at its idle clock (an H100 read 345-600 MHz after four-million-light points whose
// frame times matched 1980 MHz runs), so the clock is read on a thread while the GPU works,
// every millisecond or so, and a read that ends after stop() is kept only if none ended before.
class SmClockSampler {
public:
    SmClockSampler() = default;
    SmClockSampler(const SmClockSampler&) = delete;
    SmClockSampler& operator=(const SmClockSampler&) = delete;
    ~SmClockSampler();

    void start();
    // The lowest clock read while running; nullopt where no clock can be read.
    std::optional<int> stop();

private:
    std::thread thread_;
    std::atomic<bool> running_{false};
    std::optional<int> lowest_;       // reads that ended while running
    std::optional<int> lateRead_;     // the first read that ended after stop()
};

}  // namespace ml::app
