// `manylights raster-floors`: the visibility raster's floors per camera (renderer/passes/raster_floors.h)
// and the scene's overdraw, as CSV. For a GPU; llvmpipe's timer queries mean nothing.
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

// Registers the subcommand; the callback returns the process exit code through `exitCode`.
void addRasterFloorsCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
