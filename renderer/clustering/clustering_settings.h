// How the clustered methods build their light lists (the flags of `render`, `view`, `bench`).
#pragma once

#include <cstdint>
#include <string>

#include "renderer/clustering/cluster_grid.h"
#include "renderer/debug_view.h"
#include "renderer/gl/shader_sources.h"

namespace ml {

enum class AssignMode {
    Exact,   // count, prefix sum, fill: one compact list sized by what the frame needs
    Capped,  // the seeds' baseline: fixed lists of maxPerCluster entries; overflow counted
    ZBin,    // z-binning (Drobot 2017): depth-sorted lights, index ranges per z-bin, bit masks per tile
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

// Defines of the shading programs that read the lists (cluster_lists.glsl picks its light loop).
shaders::Defines lightListDefines(const ClusteringSettings& settings);

}  // namespace ml
