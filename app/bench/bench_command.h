// `manylights bench`: sweeps methods and their settings, measures speed against accuracy on
// every point, and writes <out>/<name>.csv with <out>/<name>.json beside it (docs/bench/README.md).
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

// Registers the subcommand; the callback returns the process exit code through `exitCode`:
// 0, 1 when a point failed (its row says why), 130 when stopped by Ctrl-C.
void addBenchCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
