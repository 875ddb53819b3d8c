// `manylights view`: the scene in a window with live controls, statistics and debug views.
#pragma once

#include <CLI/CLI.hpp>

namespace ml::app {

void addViewCommand(CLI::App& app, int& exitCode);

}  // namespace ml::app
