// `manylights compare TEST REFERENCE`: the accuracy contract's numbers between two images of
// the same size (PNG: 8-bit, in 1/255 steps; PFM: linear floats), from renderer/image/image_compare.h,
// and, with --diff, a strip a person can look at: the reference, the test and their difference
// (times --gain) side by side, cropped around the pixel that differs most. tools/gpu-accuracy
// uses it on the worst frame of each file.
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

// Registers the subcommand; the callback returns the process exit code through `exitCode`.
void addCompareCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
