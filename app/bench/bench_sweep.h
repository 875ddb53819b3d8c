// A benchmark sweep: named experiments, each the product of a few axes (methods, light counts,
// sizes, grid settings, ...), expanded into the points `manylights bench` measures. One JSON
// form serves the built-in presets, a --sweep file and the command-line flags:
//
//   {
//     "name": "quick",
//     "description": "...",
//     "run":      {"warmup": 1, "timed_frames": 3, "frame": 60, "naive_budget": 2e9},
//     "defaults": {"scene": "atrium", "size": "320x180"},          axis -> value or [values]
//     "experiments": [
//       {"name": "lights", "method": ["naive", "forward-plus", "deferred"], "lights": [64, 256]},
//       {"name": "workgroup", "method": "forward-plus", "workgroup": [32, 64, 128]}
//     ]
//   }
//
// An experiment's points are the product of its axes (defaults fill what it leaves out). Axes
// a method does not use (the grid for naive, resolve for forward-plus, the cap for exact lists)
// are dropped from its points, so a product never measures the same thing twice.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/frame_options.h"
#include "app/light_radius.h"
#include "renderer/camera/camera_path.h"

namespace ml::app {

// A sweep's "radius" takes what --light-radius takes (app/light_radius.h).

// How each point is measured.
struct RunSettings {
    int warmupFrames = 3;
    int timedFrames = 10;
    std::uint32_t firstFrame = 60;      // animation frame index of the first timed frame and of the accuracy frame
    std::optional<double> naiveBudget;  // pixels x lights a naive frame may cost; unset: by renderer
    // "reference": "supersampled:K" (--reference): every point is also compared with naive drawn
    // at K x K samples per pixel, box-filtered (aa_rmse, aa_psnr_db); 0: "naive" alone.
    int supersampledReference = 0;
    // --camera-path: every point's timed frames follow it (and its first frame is the accuracy frame).
    std::optional<CameraPath> cameraPath;
    // "reference": "physical" (--reference physical): every point is also compared with naive
    // with no cut-off, every light reaching every pixel with its untruncated inverse square, in
    // the point's BRDF (physical_* columns): what the cut-off throws away.
    bool physicalReference = false;
};
// "naive", "supersampled:K" or "physical" into `run`. Throws std::invalid_argument with the reason.
void applyReferenceSetting(RunSettings& run, const std::string& text);
std::string referenceSettingName(const RunSettings& run);

// "naive" -> 0, "supersampled:K" (K in 2..8) -> K. Throws std::invalid_argument with the reason.
int parseReferenceSetting(const std::string& text);
std::string referenceSettingName(int supersampled);


struct BenchPoint {
    std::string experiment;
    FrameOptions frame;       // the point's flags, as `render` would take them
    bool clustered = false;   // forward-plus or deferred: the grid axes apply
    bool deferred = false;    // resolve applies
    bool gbuffered = false;   // deferred or visibility: gbuffer and normal_cones apply
    bool prepassed = false;   // forward-plus or deferred: prepass applies
    bool visibility = false;  // vis_raster applies
    bool capped = false;      // max_per_cluster applies
    int accumulate = 1;       // the physical_* columns on the mean of this many stochastic draws
};

// "lights: deferred, 256 lights, 160x90, grid 16 across x 16 fitted, exact, wg 64, ..."
std::string describePoint(const BenchPoint& point);

struct Sweep {
    std::string name;
    std::string description;
    RunSettings run;
    std::vector<std::string> experiments;  // names, in order
    std::vector<BenchPoint> points;
    nlohmann::json document;               // the sweep as run (after flag overrides), for the record
};

// One sweep axis: its JSON key, its `bench` flag and what it means.
struct SweepAxis {
    const char* key;
    const char* flag;
    const char* help;
};
const std::vector<SweepAxis>& sweepAxes();

// Expands a sweep document. `overrides` maps axis keys to values that replace the axis in the
// defaults and in every experiment (the flags given beside a preset); `only` keeps the named
// experiments. Throws std::invalid_argument with one line naming the sweep, the experiment,
// the key and the value at fault.
Sweep expandSweep(const nlohmann::json& document, const nlohmann::json& overrides, const std::vector<std::string>& only);

// The value of a comma-separated flag ("64,256,1024") as the JSON list the sweep takes, typed
// by the axis ("64" becomes 64). Throws std::invalid_argument naming the flag.
nlohmann::json axisValuesFromFlag(const std::string& key, const std::string& commaList);

}  // namespace ml::app
