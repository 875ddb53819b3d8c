// What the light assignment built this frame, read back on request (--stats).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ml {

// --assign zbin (renderer/clustering/zbin_assignment.h).
struct ZBinStatistics {
    std::uint32_t bins = 0, tiles = 0, wordsPerTile = 0, listedLights = 0;
    std::size_t maskBytes = 0;        // tiles x words x 4 B
    std::size_t totalBytes = 0;       // masks, bins, per-light buffers and the sort's scratch
    double meanWalkedPerPixel = 0.0;  // lights in the bin's index range, per visible pixel
    double meanPassedPerPixel = 0.0;  // of those, lights whose tile bit is set (the ones shaded)
};

struct ClusterStatistics {
    std::uint32_t tilesX = 0, tilesY = 0, slices = 0, clusters = 0;
    std::string slicing;
    std::string cull;                         // the light-vs-cluster test (--cull)
    float zNear = 0.0f, zFar = 0.0f;          // the depth range sliced
    double emptyShare = 0.0;                  // clusters with no light
    double meanLightsPerCluster = 0.0;        // over all clusters
    double meanLightsPerNonEmptyCluster = 0.0;
    std::uint32_t maxLightsPerCluster = 0;    // demand, before any cap
    std::uint64_t listEntries = 0;            // light references stored
    std::uint32_t overflowClusters = 0;       // capped lists: clusters over the cap
    std::uint64_t droppedReferences = 0;      // capped lists: light references lost at the cap
    std::uint32_t activeClusters = 0;         // with --active-only: clusters holding a visible sample
    bool activeOnly = false;
    std::uint32_t listsPerCluster = 1;        // --normal-cones: one list per normal bin
    std::uint64_t normalConePairs = 0;        // --normal-cones: light-cluster pairs passing the cull test in clusters with samples
    std::uint64_t normalConePairsKept = 0;    //   of those, pairs listed in at least one occupied normal bin
    std::size_t listBytes = 0;                // light index list memory in use
    std::size_t gridBytes = 0;                // counts, offsets, bounds and flags
    bool zbin = false;                        // --assign zbin: the fields below, not the per-cluster ones
    ZBinStatistics zbinStats;
};

}  // namespace ml
