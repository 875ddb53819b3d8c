// `manylights info FILE`: what a scene holds and what `render` would do with it by default,
// before anything is drawn (no GL context is opened).
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

void addInfoCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
