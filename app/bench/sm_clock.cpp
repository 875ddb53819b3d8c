#include "app/bench/sm_clock.h"

#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace ml::app {
namespace {

// The four NVML entry points used, declared here: the driver ships the library, Debian main
// ships no header for it (nvml.h: nvmlReturn_t 0 is NVML_SUCCESS, NVML_CLOCK_SM is 1).
struct Nvml {
    using Device = void*;
    int (*init)() = nullptr;
    int (*deviceByIndex)(unsigned, Device*) = nullptr;
    int (*clockInfo)(Device, int, unsigned*) = nullptr;
    Device gpu0 = nullptr;

    static const Nvml* open() {
        static const Nvml* nvml = [] () -> const Nvml* {
            void* lib = dlopen("libnvidia-ml.so.1", RTLD_NOW | RTLD_LOCAL);
            if (!lib) return nullptr;  // kept open for the process's life
            static Nvml n;
            n.init = reinterpret_cast<int (*)()>(dlsym(lib, "nvmlInit_v2"));
            n.deviceByIndex = reinterpret_cast<int (*)(unsigned, Device*)>(dlsym(lib, "nvmlDeviceGetHandleByIndex_v2"));
            n.clockInfo = reinterpret_cast<int (*)(Device, int, unsigned*)>(dlsym(lib, "nvmlDeviceGetClockInfo"));
            if (!n.init || !n.deviceByIndex || !n.clockInfo || n.init() != 0 || n.deviceByIndex(0, &n.gpu0) != 0) return nullptr;
            return &n;
        }();
        return nvml;
    }
};

constexpr int kNvmlClockSm = 1;

std::optional<int> nvidiaSmiSmClockMhz() {
    // stderr goes away with the shell's "command not found" where nvidia-smi is absent.
    FILE* pipe = popen("nvidia-smi --query-gpu=clocks.sm --format=csv,noheader,nounits -i 0 2>/dev/null", "r");
    if (!pipe) return std::nullopt;
    char line[64] = {};
    const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
    const int status = pclose(pipe);
    if (!read || status != 0) return std::nullopt;
    try {
        std::size_t used = 0;
        const int mhz = std::stoi(line, &used);
        if (mhz <= 0) return std::nullopt;
        return mhz;
    } catch (const std::exception&) {
        return std::nullopt;  // "[N/A]" and the like
    }
}

}  // namespace

std::optional<int> querySmClockMhz() {
    if (const Nvml* nvml = Nvml::open()) {
        unsigned mhz = 0;
        if (nvml->clockInfo(nvml->gpu0, kNvmlClockSm, &mhz) == 0 && mhz > 0) return static_cast<int>(mhz);
        return std::nullopt;
    }
    return nvidiaSmiSmClockMhz();
}

SmClockSampler::~SmClockSampler() {
    if (thread_.joinable()) stop();
}

void SmClockSampler::start() {
    if (thread_.joinable()) stop();
    reads_.clear();
    lateRead_.reset();
    running_ = true;
    thread_ = std::thread([this] {
        while (true) {
            const std::optional<int> mhz = querySmClockMhz();
            const bool ended = !running_;
            if (!mhz) return;  // nothing to read here (no NVIDIA GPU): no process starts every millisecond
            if (ended) {
                if (reads_.empty()) lateRead_ = mhz;
                return;
            }
            reads_.push_back(*mhz);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    });
}

std::optional<SmClockReading> SmClockSampler::stop() {
    running_ = false;
    if (thread_.joinable()) thread_.join();
    if (reads_.empty()) {
        if (!lateRead_) return std::nullopt;
        return SmClockReading{*lateRead_, *lateRead_};
    }
    std::vector<int> sorted = reads_;
    std::sort(sorted.begin(), sorted.end());
    return SmClockReading{sorted[sorted.size() / 2], sorted.front()};
}

}  // namespace ml::app
