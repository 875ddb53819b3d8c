// The results of a sweep: one row per point, written as CSV (loadable by Python's csv module:
// one header line, no comments) and as the rows of the JSON record beside it. Columns are a
// fixed list (docs/bench/README.md describes each) with the per-pass times in the middle,
// `pass_<name>_ms` (+ _p10, _p90), one set for every pass any point ran.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/timing_csv.h"
#include "renderer/pass_timer.h"

namespace ml::app {

using BenchRow = nlohmann::ordered_json;  // column -> number, string, or null (an empty cell)

class BenchTable {
public:
    // Throws std::logic_error for a column that is neither fixed nor a pass column (a typo).
    void add(BenchRow row);
    const std::vector<BenchRow>& rows() const { return rows_; }
    std::vector<std::string> columns() const;

    // Written to a temporary file and renamed, so a reader (or a Ctrl-C) never sees half a file.
    // Throw std::runtime_error naming the path.
    void writeCsv(const std::string& path) const;
    nlohmann::ordered_json rowsJson() const;

private:
    std::vector<BenchRow> rows_;
    std::vector<std::string> passColumns_;  // in the order first seen
};


}  // namespace ml::app
