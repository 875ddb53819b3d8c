// `manylights render`: one frame offscreen, to PNG (and PFM), with per-pass times.
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

// Registers the subcommand; the callback returns the process exit code through `exitCode`.
void addRenderCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
