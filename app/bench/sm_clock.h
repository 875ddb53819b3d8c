// The GPU's SM clock as nvidia-smi reads it, for the `sm_clock_mhz` column of `bench`: clock
// drops (thermal or power) slowed every pass of whole sweeps by 40 % on an H200 before, and a
// timing is only comparable with the clock it ran at.
#pragma once

#include <optional>

namespace ml::app {

// clocks.sm of GPU 0 in MHz; nullopt where nvidia-smi is absent or says nothing usable (llvmpipe,
// other vendors). Costs a process start (~0.1 s): call it between frames, never inside them.
std::optional<int> querySmClockMhz();

}  // namespace ml::app
