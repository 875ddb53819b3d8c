// The vocabulary of the timing CSVs that `bench` (app/bench/bench_table.h) and `render
// --timing-csv` (app/render/sequence_timing.h) both write: the per-pass column names, the clock
// column, and a write that never leaves half a file.
#pragma once

#include <string>

#include "renderer/pass_timer.h"

namespace ml::app {

// "deferred.lighting-compute" -> "pass_deferred_lighting_compute_ms", "forward+.shade" ->
// "pass_forward_plus_shade_ms": '.', '-' and '+' become '_' ('+' as "_plus").
std::string passColumn(const std::string& passName);

// The `clock` column: "gpu-timer-queries" or "wall-clock-after-glfinish".
const char* clockColumnValue(TimingClock clock);

// Writes `text` to `path` through a temporary file and a rename.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace ml::app
