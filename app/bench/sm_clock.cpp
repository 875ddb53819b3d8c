#include "app/bench/sm_clock.h"

#include <cstdio>
#include <string>

namespace ml::app {

std::optional<int> querySmClockMhz() {
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

}  // namespace ml::app
