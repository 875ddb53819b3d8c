// How the clustered methods build their light lists (the flags of `render`, `view`, `bench`).
#pragma once

#include <cstdint>
#include <string>

#include "renderer/clustering/cluster_grid.h"
#include "renderer/debug_view.h"

namespace ml {

enum class AssignMode {
    Exact,   // count, prefix sum, fill: one compact list sized by what the frame needs
    Capped,  // the seeds' baseline: fixed lists of maxPerCluster entries; overflow counted
};
AssignMode parseAssignMode(const std::string& text);  // throws std::invalid_argument
const char* assignModeName(AssignMode mode);

struct ClusteringSettings {
    ClusterGridConfig grid;
    AssignMode assign = AssignMode::Exact;
    std::uint32_t maxPerCluster = 2048;  // capped lists only (seed 000's analysis used 2048)
    bool activeOnly = false;             // skip clusters that hold no visible sample
    DebugView view = DebugView::Shaded;
};

}  // namespace ml
