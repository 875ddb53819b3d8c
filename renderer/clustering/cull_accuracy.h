// How loose the --cull test was on a built frame: of the light references in the lists, how
// many belong to lights that reach no point of the cluster's volume (the exact sphere-frustum
// distance of cluster_culling.h, and for spots their lit sector against it by GJK, on the CPU). A read-back and a CPU pass over
// the lists, for `render --stats`, bench and the tests only; never per frame.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/gpu_types.h"
#include "renderer/lights/light_set.h"

namespace ml {

class ClusteredLighting;

struct CullAccuracy {
    std::uint64_t references = 0;      // list entries examined
    std::uint64_t falsePositives = 0;  // of those, lights that reach no point of the cluster
    std::uint64_t spotReferences = 0;      // the entries of spot lights (counted in references too)
    std::uint64_t spotFalsePositives = 0;  // of those, spots whose lit sector reaches no point of the cluster
    std::uint32_t clustersExamined = 0;
    std::uint32_t clusterStride = 1;   // every k-th cluster examined; 1: all of them
};

// Examines every cluster, or every k-th with k chosen so that about maxReferences entries are
// tested (a million take about a second on one core). `drawn`: the lights as drawn (animated), any types.
CullAccuracy measureCullAccuracy(const ClusteredLighting& clustering, const std::vector<Light>& lights,
                                 const FrameUniforms& uniforms, std::uint64_t maxReferences = 1'000'000);

}  // namespace ml
