// The sweeps that ship with manylights (`bench --preset NAME`), compiled into the binary so they
// work from any directory. Each is a sweep document in the form bench_sweep.h describes;
// `bench --preset NAME --print-sweep` shows it, and a copy edited into a file runs with --sweep.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ml::app {

const std::vector<std::string>& benchPresetNames();

// Throws std::invalid_argument listing the presets for an unknown name.
nlohmann::json benchPreset(const std::string& name);

}  // namespace ml::app
