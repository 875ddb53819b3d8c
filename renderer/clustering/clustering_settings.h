// How the clustered methods build their light lists (the flags of `render`, `view`, `bench`).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/clustering/cluster_grid.h"
#include "renderer/debug_view.h"
#include "renderer/gl/shader_sources.h"
#include "renderer/lights/light_model.h"
#include "renderer/lights/light_sum.h"

namespace ml {

enum class AssignMode {
    Exact,       // count, prefix sum, fill: one compact list sized by what the frame needs
    Capped,      // the seeds' baseline: fixed lists of maxPerCluster entries; overflow counted
    PerCluster,  // seed 003: one invocation per cluster loops over every light; exact lists
    ZBin,        // z-binning (Drobot 2017): depth-sorted lights, index ranges per z-bin, bit masks per tile
};
AssignMode parseAssignMode(const std::string& text);  // throws std::invalid_argument
const char* assignModeName(AssignMode mode);

// The light-vs-cluster test (glsl/include/light_cluster_test.glsl; ML_CULL_* in bindings.h).
enum class CullMode {
    Aabb,    // sphere against the cluster's view-space AABB
    Sphere,  // sphere against the cluster's six frustum planes
    Cone,    // seed 001's spherical-sliced cone
};
CullMode parseCullMode(const std::string& text);  // throws std::invalid_argument
const char* cullModeName(CullMode mode);

struct ClusteringSettings {
    ClusterGridConfig grid;
    AssignMode assign = AssignMode::Exact;
    std::uint32_t maxPerCluster = 2048;  // capped lists only (seed 000's analysis used 2048)
    bool activeOnly = false;             // skip clusters that hold no visible sample
    CullMode cull = CullMode::Aabb;
    // Lists per (cluster, view-space normal bin) (Olsson et al. 2012): deferred and visibility
    // only, exact lists only. Forward+ knows no normal before it shades and ignores it.
    bool normalCones = false;
    DebugView view = DebugView::Shaded;
    // Whether the light set holds spots. FrameRenderer sets it from its lights; without spots
    // every program that reads lights compiles its spot paths out (ML_SPOT_LIGHTS 0).
    bool spotLights = true;
    // The light model's switches, compiled into every program that shades lights. FrameRenderer
    // sets them from its frame settings (and rebuilds the method when they change); unset, the
    // programs branch on the frame's uniforms.
    std::optional<ShadingSwitches> shading;
    // --light-sum, for every method's shading (naive's too). With Fixed the lists are not sorted
    // (glsl/include/light_sum.glsl says why they need not be).
    LightSum lightSum = LightSum::Float;
    // Samples per pixel of the depth the passes read (--msaa, Forward+): each compiles with
    // ML_MSAA_SAMPLES and reads every sample, so the lists hold for every shaded sample.
    std::uint32_t depthSamples = 1;
};

// Defines of every program that shades point and spot lights, naive's included: ML_SPOT_LIGHTS,
// ML_FIXED_LIGHT_SUM and, where the settings carry them, the shading switches.
shaders::Defines lightShadingDefines(const ClusteringSettings& settings);
// Defines of the shading programs that read the lists (cluster_lists.glsl picks its light loop,
// and with --normal-cones its list by the normal's bin).
shaders::Defines lightListDefines(const ClusteringSettings& settings);
// ML_MSAA_SAMPLES: how many depth samples a pixel has (glsl/include/depth_samples.glsl).
std::pair<std::string, std::string> depthSamplesDefine(const ClusteringSettings& settings);

}  // namespace ml
