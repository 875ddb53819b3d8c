#include "app/bench/bench_presets.h"

#include <stdexcept>

namespace ml::app {

namespace {

struct Preset {
    const char* name;
    const char* json;
};

// quick: every chart's experiment, small enough for llvmpipe on two cores in about a minute
// (CTest runs it). 160x90 keeps naive affordable; 16 tiles across keep tiles 10 px wide.
constexpr const char* kQuick = R"json({
  "name": "quick",
  "description": "A small sweep touching every chart, for llvmpipe on two cores in about a minute (CTest runs it): the atrium at 160x90, one warm-up and five timed frames per point.",
  "run": {"warmup": 1, "timed_frames": 5, "frame": 60},
  "defaults": {"scene": "atrium", "size": "160x90", "tiles_x": 16, "slices": 16, "lights": 64},
  "experiments": [
    {"name": "lights", "description": "frame time and error against light count, per method",
     "method": ["naive", "forward-plus", "deferred"], "lights": [16, 64, 256]},
    {"name": "workgroup", "description": "light-assignment workgroup size",
     "method": ["forward-plus", "deferred"], "workgroup": [16, 64, 256]},
    {"name": "tiles_by_cap", "description": "tiles across by per-cluster cap (capped lists drop lights; Blinn-Phong, whose PSNR against naive shows the drop: GGX's mirror-like peaks raise the PSNR's peak past 50 dB)",
     "method": "forward-plus", "lights": 256, "assign": "capped", "tiles_x": [8, 16, 32], "max_per_cluster": [4, 16, 64], "brdf": "blinn-phong"},
    {"name": "slicing", "description": "linear, log and fitted slices with the far plane fitted and at 1000",
     "method": "forward-plus", "far": ["auto", 1000], "slicing": ["linear", "log", "fitted"]},
    {"name": "resolve", "description": "deferred lighting as a compute or a fragment pass",
     "method": "deferred", "lights": 256, "resolve": ["compute", "fragment"]},
    {"name": "scale", "description": "more lights, radius shrinking so about 8 reach a point (naive reference only where affordable)",
     "method": ["forward-plus", "deferred"], "lights": [256, 1024, 4096], "radius": "overlap:8"}
  ]
})json";

// seeds: the experiments of ../shared/seeds on our atrium. Seed 000's baseline: 42 tiles
// across (24 down at 16:9), 12 linear slices, capped lists of 2048, a three-target G-buffer
// (standard), 2560x1440, and the seeds' Blinn-Phong (as docs/bench/nvidia-h100/h100-seeds.csv
// was measured).
constexpr const char* kSeeds = R"json({
  "name": "seeds",
  "description": "The seeds' experiments on the atrium at 2560x1440: seed 000's grid 42x24x12 with cap 2048 (and our exact lists beside it), 100 to 8192 lights, workgroup sizes, tile density, tiles by cap, linear/log/fitted slicing at far planes 1000 and 30 (30 clips the atrium's far wall, 34.6 away; auto fits it), and deferred's fragment against compute lighting.",
  "run": {"warmup": 3, "timed_frames": 10, "frame": 60},
  "defaults": {"scene": "atrium", "size": "2560x1440", "tiles_x": 42, "slices": 12, "slicing": "linear",
               "assign": "capped", "max_per_cluster": 2048, "workgroup": 64, "lights": 2000, "gbuffer": "standard",
               "brdf": "blinn-phong"},
  "experiments": [
    {"name": "lights", "description": "frame time against light count per method (seeds 000, 001, 004)",
     "method": ["naive", "forward-plus", "deferred"], "lights": [100, 300, 500, 700, 1000, 2000, 4096, 5000, 8192],
     "assign": ["capped", "exact"]},
    {"name": "workgroup", "description": "seed 000's workgroup sweep at 1600 lights",
     "method": ["forward-plus", "deferred"], "lights": 1600, "workgroup": [8, 16, 32, 64, 128, 256, 512, 1024]},
    {"name": "tile_density", "description": "seed 000: tiles across at 2000 lights, workgroup 128, cap 2048",
     "method": ["forward-plus", "deferred"], "workgroup": 128, "tiles_x": [8, 12, 16, 20, 24, 28, 32, 42, 48, 64]},
    {"name": "tiles_by_cap", "description": "seed 000's heat map: tiles across by per-cluster cap at 2000 lights",
     "method": ["forward-plus", "deferred"], "workgroup": 128, "tiles_x": [8, 16, 24, 32, 42, 64],
     "max_per_cluster": [128, 256, 384, 512, 1024, 2048]},
    {"name": "slicing", "description": "seed 000 found 91.7 % empty clusters with 12 linear slices to far 1000",
     "method": ["forward-plus", "deferred"], "assign": "exact", "far": [1000, 30, "auto"],
     "slicing": ["linear", "log", "fitted"], "lights": [100, 2000, 5000]},
    {"name": "resolve", "description": "deferred lighting as a fragment pass against a compute pass (seed 004)",
     "method": "deferred", "assign": "exact", "resolve": ["fragment", "compute"], "lights": [1000, 8192]},
    {"name": "baseline", "description": "the seeds' configuration (deferred, three-target G-buffer, fragment resolve, linear 42x24x12, cap 2048) at the seeds' radius 2",
     "method": "deferred", "resolve": "fragment", "radius": 2, "lights": [1000, 2000, 4096, 8192]},
    {"name": "ours", "description": "our fast exact path on the same frames: visibility buffer, exact lists, fitted slicing, the default 32 across x 48",
     "method": ["visibility", "deferred"], "assign": "exact", "slicing": "fitted", "tiles_x": 32, "slices": 48,
     "gbuffer": "packed", "radius": 2, "lights": [1000, 2000, 4096, 8192]}
  ]
})json";

// scale: the radius follows r = cbrt(3 * 32 * V / (4 * pi * N)), V the volume of the light
// box, so about 32 lights reach any point whatever N (see overlapRadius).
constexpr const char* kScale = R"json({
  "name": "scale",
  "description": "1k to 1M lights at 2560x1440 for Forward+, deferred and the visibility buffer, naive where the budget allows; the radius shrinks as N^(-1/3), r = cbrt(3 * 32 * V / (4 * pi * N)) with V the light box's volume, so about 32 lights reach any point.",
  "run": {"warmup": 3, "timed_frames": 10, "frame": 60},
  "defaults": {"scene": "atrium", "size": "2560x1440", "radius": "overlap:32", "assign": "exact"},
  "experiments": [
    {"name": "lights", "description": "frame time, error and cluster occupancy from 1024 to 1048576 lights",
     "method": ["naive", "forward-plus", "deferred", "visibility"],
     "lights": [1024, 2048, 4096, 8192, 16384, 32768, 65536, 131072, 262144, 524288, 1048576]}
  ]
})json";

// options: issue 5's closing table, each switchable option against naive on the same frame and
// its cost; sized for llvmpipe (the atrium, 1024 lights, 640x360).
constexpr const char* kOptions = R"json({
  "name": "options",
  "description": "The shading options of issue 5 on the atrium, 1024 lights, 640x360: G-buffer layouts, specular on/off, Forward+ with and without its depth pre-pass, bloom; each against naive on the same frame.",
  "run": {"warmup": 1, "timed_frames": 3, "frame": 60, "naive_budget": 3e8},
  "defaults": {"scene": "atrium", "size": "640x360", "lights": 1024, "assign": "exact"},
  "experiments": [
    {"name": "gbuffer", "description": "exact, standard, packed and two-component G-buffers",
     "method": ["deferred", "visibility"], "gbuffer": ["exact", "standard", "packed", "two-component"]},
    {"name": "specular", "description": "the BRDF's specular term on and off, every method against naive in the same mode",
     "method": ["naive", "forward-plus", "deferred", "visibility"], "specular": ["on", "off"]},
    {"name": "prepass", "description": "Forward+ with and without the depth pre-pass (log slicing for both: fitted needs the pre-pass)",
     "method": "forward-plus", "slicing": "log", "prepass": ["on", "off"]},
    {"name": "bloom", "description": "bloom off and on after shading, the same for every method",
     "method": ["naive", "forward-plus", "deferred"], "bloom": ["off", "on"]}
  ]
})json";


// culling: the light-vs-cluster tests, per-cluster assignment and normal cones (issue 5) on
// the atrium at 1024 lights and 640x360, every point against naive (docs/methods-and-clustering.md).
constexpr const char* kCulling = R"json({
  "name": "culling",
  "description": "The light-vs-cluster tests (aabb, sphere, cone), per-cluster against per-light assignment, and normal cones against active clusters only, on the atrium at 1024 lights and 640x360; naive is the reference of every point.",
  "run": {"warmup": 1, "timed_frames": 3, "frame": 60, "naive_budget": 1e9},
  "defaults": {"scene": "atrium", "size": "640x360", "lights": 1024},
  "experiments": [
    {"name": "cull", "description": "the three cull tests: references, false positives, assignment time",
     "method": "deferred", "cull": ["aabb", "sphere", "cone"]},
    {"name": "assign", "description": "one invocation per cluster over all lights (seed 003)",
     "method": "deferred", "assign": "per-cluster"},
    {"name": "normal_cones", "description": "lists per (cluster, normal bin) against active clusters only",
     "method": ["deferred", "visibility"], "active_only": true, "normal_cones": [false, true]}
  ]
})json";

// spots: issue 15's cost of spot lights on the GPU: half the lights spots (cones of 20 to 60
// degrees, random directions) against points only, at the scale preset's frames and radii.
constexpr const char* kSpots = R"json({
  "name": "spots",
  "description": "Half spots against points only at 65,536 and 1,048,576 lights, 2560x1440, the scale preset's overlap:32 radius; spots are culled by their cones, so they cost what their cones reach.",
  "run": {"warmup": 3, "timed_frames": 10, "frame": 60},
  "defaults": {"scene": "atrium", "size": "2560x1440", "radius": "overlap:32", "assign": "exact"},
  "experiments": [
    {"name": "spot_share", "description": "points only against half spots, deferred and the visibility buffer",
     "method": ["deferred", "visibility"], "lights": [65536, 1048576], "spot_share": [0, 0.5]}
  ]
})json";

// antialiasing: issue 16's time against aliasing error: every method at 1, 2, 4 and 8 samples
// where it takes them, glass on and off, each against naive at the same count and against naive
// supersampled 4 x 4 (the time_vs_aliasing chart). 1,024 lights: the 10240x5760 reference is then
// 6e10 pixel-lights, within what one naive draw gets right on an H100 (docs/transparency-*.md).
constexpr const char* kAntialiasing = R"json({
  "name": "antialiasing",
  "description": "MSAA 1/2/4/8 for naive and Forward+ (deferred and visibility at one sample), glass on and off, at 2560x1440 and 1,024 lights of radius overlap:32, each point against naive at its sample count and against naive supersampled 4 x 4.",
  "run": {"warmup": 5, "timed_frames": 30, "frame": 60, "reference": "supersampled:4"},
  "defaults": {"scene": "atrium", "size": "2560x1440", "lights": 1024, "radius": "overlap:32", "assign": "exact"},
  "experiments": [
    {"name": "msaa", "description": "every method at every sample count it takes",
     "method": ["naive", "forward-plus", "deferred", "visibility"], "msaa": [1, 2, 4, 8], "transparency": ["on", "off"]}
  ]
})json";

// cameras: issue 17's fixed camera set (app/bench/camera_sets.h), at the light counts of its targets;
// 30 timed frames after 5 warm-up, as the H100 numbers are taken.
constexpr const char* kCameras = R"json({
  "name": "cameras",
  "description": "Deferred and the visibility buffer at 65,536 and 1,048,576 lights, 2560x1440, overlap:32, exact lists, on the atrium's fixed camera set (atrium-set: default, gallery, roof, corner); median of 30 frames after 5 warm-up.",
  "run": {"warmup": 5, "timed_frames": 30, "frame": 60},
  "defaults": {"scene": "atrium", "size": "2560x1440", "radius": "overlap:32", "assign": "exact", "camera": "atrium-set"},
  "experiments": [
    {"name": "cameras", "description": "frame and pass times per camera",
     "method": ["deferred", "visibility"], "lights": [65536, 1048576]}
  ]
})json";

constexpr Preset kPresets[] = {{"quick", kQuick},     {"seeds", kSeeds},     {"scale", kScale},
                               {"culling", kCulling}, {"options", kOptions}, {"spots", kSpots},
                               {"antialiasing", kAntialiasing}, {"cameras", kCameras}};

}  // namespace

const std::vector<std::string>& benchPresetNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const Preset& p : kPresets) out.emplace_back(p.name);
        return out;
    }();
    return names;
}

nlohmann::json benchPreset(const std::string& name) {
    for (const Preset& p : kPresets)
        if (name == p.name) return nlohmann::json::parse(p.json);
    std::string list;
    for (const std::string& n : benchPresetNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("--preset '" + name + "': no such preset (expected one of: " + list + ")");
}

}  // namespace ml::app
