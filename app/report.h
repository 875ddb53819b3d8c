// Console reports shared by the subcommands.
#pragma once

#include <vector>

#include "app/frame_options.h"
#include "renderer/clustering/cluster_statistics.h"
#include "renderer/clustering/cull_accuracy.h"
#include "renderer/pass_timer.h"
#include "renderer/raytracing/shadow_mode.h"
#include "renderer/raytracing/shadow_rays.h"

#include <nlohmann/json.hpp>

namespace ml::app {

void printPassTimes(const std::vector<PassTime>& times, TimingClock clock);
void printSceneSummary(const PreparedFrame& frame);
// PreparedFrame::notes, one line each, on stdout.
void printNotes(const PreparedFrame& frame);
void printClusterStatistics(const ClusterStatistics& stats);
// The shading options of the frame (--specular, --gbuffer, --prepass, --bloom) and what they cost in memory.
void printShadingOptions(const FrameSettings& settings, std::uint32_t materialFeatures);
// "shadows: rays, 262087 casting triangles (34778 alpha-tested), 132223 nodes of 2 children, depth 28,
// 24.1 MiB, built in 0.21 s" (Sponza), or "shadows: off".
void printShadowStructure(Shadows shadows, const ShadowRays* rays);
// "cull aabb: 548,302 references, of which 40.1 % reach no point of their cluster".
void printCullAccuracy(const ClusterStatistics& stats, const CullAccuracy& accuracy);
// Throws std::runtime_error naming the path.
void writeJsonFile(const std::string& path, const nlohmann::json& doc);

}  // namespace ml::app
