#include "app/bench/bench_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

#include "app/bench/camera_sets.h"
#include "app/camera_spec.h"
#include "renderer/camera/camera.h"
#include "renderer/clustering/clustering_settings.h"
#include "renderer/methods/shading_method.h"
#include "scenes/scene_library.h"

namespace ml::app {

using nlohmann::json;

namespace {

constexpr long long kMaxLights = 16'777'216;  // as `render --lights`

// ---- One value of an axis, checked. Each throws std::invalid_argument with the reason only;
// ---- the caller adds the sweep, experiment and key.

std::string asText(const json& v) {
    if (!v.is_string()) throw std::invalid_argument("expected a string");
    return v.get<std::string>();
}

long long asInteger(const json& v, long long lo, long long hi) {
    long long n = 0;
    if (v.is_number_integer()) n = v.get<long long>();
    else if (v.is_number_float() && std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>()) &&
             std::abs(v.get<double>()) < 9e18)
        n = static_cast<long long>(v.get<double>());  // 1e6 in a JSON file
    else throw std::invalid_argument("expected a whole number");
    if (n < lo || n > hi)
        throw std::invalid_argument("must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return n;
}

double asNumber(const json& v) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw std::invalid_argument("expected a finite number");
    return v.get<double>();
}

bool asBoolean(const json& v) {
    if (v.is_boolean()) return v.get<bool>();
    if (v.is_string()) {
        const std::string s = v.get<std::string>();
        if (s == "on" || s == "true" || s == "yes" || s == "1") return true;
        if (s == "off" || s == "false" || s == "no" || s == "0") return false;
    }
    throw std::invalid_argument("expected true or false (on/off)");
}

RadiusSpec asRadius(const json& v) {
    if (v.is_number()) {
        RadiusSpec r;
        r.kind = RadiusSpec::Kind::Fixed;
        r.value = asNumber(v);
        if (r.value < 0.0) throw std::invalid_argument("must be >= 0");
        return r;
    }
    if (v.is_string())
        if (auto r = tryParseRadius(v.get<std::string>())) return *r;
    throw std::invalid_argument(kRadiusSyntax);
}

// ---- The axes, in expansion order: frame-level axes outermost, so consecutive points share a
// ---- scene, a light set and a naive reference; method-level axes innermost.

enum class ValueKind { Text, Integer, Number, Boolean, Radius, NumberOrAuto };
enum class Applies { Always, Clustered, Deferred, GBuffered, PrePassed, Capped, ExactGBuffered, Forward, Visibility };

struct AxisDef {
    SweepAxis info;
    ValueKind kind;
    Applies applies;
    std::function<void(BenchPoint&, const json&)> set;
};

std::optional<float> numberOrAuto(const json& v) {
    if (v.is_string() && v.get<std::string>() == "auto") return std::nullopt;
    const double x = asNumber(v);
    if (!(x > 0.0)) throw std::invalid_argument("must be > 0, or \"auto\" to fit the scene");
    return static_cast<float>(x);
}

const std::vector<AxisDef>& axisDefs() {
    static const std::vector<AxisDef> defs = {
        {{"scene", "--scene", "atrium, plane, boxes, or a .gltf/.glb file"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const std::string s = asText(v);
             const auto& names = builtinSceneNames();
             if (std::find(names.begin(), names.end(), s) == names.end() && !std::filesystem::is_regular_file(s))
                 throw std::invalid_argument("neither a built-in scene (atrium, plane, boxes) nor a file");
             p.frame.scene = s;
         }},
        {{"material_variant", "--material-variant", "a glTF file's KHR_materials_variants variant, by name (default: the file's own materials)"},
         ValueKind::Text, Applies::Always, [](BenchPoint& p, const json& v) { p.frame.materialVariant = asText(v); }},
        {{"detail", "--detail", "tessellation scale of procedural scenes"}, ValueKind::Number, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const double d = asNumber(v);
             if (!(d > 0.0 && d <= 16.0)) throw std::invalid_argument("must be in (0, 16]");
             p.frame.detail = static_cast<float>(d);
         }},
        {{"camera", "--camera", "px,py,pz,tx,ty,tz,fovy_deg, gltf:N (the file's Nth camera), \"default\" (the scene's view), orbit:... (the timed frames follow the turntable, app/camera_spec.h), or a named set of cameras (atrium-set, atrium-above: app/bench/camera_sets.h); the flag separates cameras by ';'"}, ValueKind::Text,
         Applies::Always,
         [](BenchPoint& p, const json& v) {
             const std::string s = asText(v);
             if (isOrbitSpec(s)) (void)parseOrbitSpec(s);
             else if (s != "default" && !namesSceneCamera(s)) (void)parseCamera(s);  // gltf:N is checked with the scene
             p.frame.camera = s == "default" ? "" : s;
         }},
        {{"near", "--near", "near clip plane, or \"auto\" (fits the scene)"}, ValueKind::NumberOrAuto, Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.nearPlane = numberOrAuto(v); }},
        {{"far", "--far", "far clip plane, or \"auto\" (fits the scene); seed 000 measured 1000 against 30"},
         ValueKind::NumberOrAuto, Applies::Always, [](BenchPoint& p, const json& v) { p.frame.farPlane = numberOrAuto(v); }},
        {{"size", "--size", "output size WxH"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             int w = 0, h = 0;
             parseSize(asText(v), w, h);
             p.frame.size = v.get<std::string>();
         }},
        {{"lights", "--lights", "number of generated lights"}, ValueKind::Integer, Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.lights = asInteger(v, 0, kMaxLights); }},
        {{"spot_share", "--spot-share", "share of the generated lights that are spots, in [0, 1]"}, ValueKind::Number, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const double x = asNumber(v);
             if (!(x >= 0.0 && x <= 1.0)) throw std::invalid_argument("must be in [0, 1]");
             p.frame.spotShare = static_cast<float>(x);
         }},
        {{"radius", "--light-radius", "light radius: a number, \"default\", or \"overlap:K\" (r = cbrt(3 K V / (4 pi N)))"},
         ValueKind::Radius, Applies::Always, [](BenchPoint& p, const json& v) { p.frame.lightRadius = asRadius(v); }},
        {{"light_placement", "--light-placement", "where generated lights go: volume or surfaces (default: volume for a built-in scene, surfaces for a file)"},
         ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseLightPlacement(asText(v));
             p.frame.lightPlacement = v.get<std::string>();
         }},
        {{"seed", "--seed", "seed of the light placement"}, ValueKind::Integer, Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.seed = asInteger(v, 0, std::numeric_limits<std::uint32_t>::max()); }},
        {{"intensity", "--light-intensity", "light intensity multiplier"}, ValueKind::Number, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const double x = asNumber(v);
             if (x < 0.0) throw std::invalid_argument("must be >= 0");
             p.frame.lightIntensity = static_cast<float>(x);
         }},
        {{"drift_speed", "--drift-speed", "mean upward drift of the lights, units per second"}, ValueKind::Number,
         Applies::Always, [](BenchPoint& p, const json& v) { p.frame.driftSpeed = static_cast<float>(asNumber(v)); }},
        {{"specular", "--specular", "the BRDF's specular term: on, off (Lambert only)"}, ValueKind::Boolean, Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.specular = asBoolean(v) ? "on" : "off"; }},
        {{"brdf", "--brdf", "ggx (glTF's metallic-roughness BRDF, the default) or blinn-phong (the seeds')"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseBrdf(asText(v));
             p.frame.brdf = v.get<std::string>();
         }},
        {{"shadows", "--shadows", "off, rays (an exact shadow ray for every point and light that adds light) or sampled (a few rays a pixel, the ratio reused and filtered)"}, ValueKind::Text,
         Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseShadows(asText(v));
             p.frame.shadows = v.get<std::string>();
         }},
        {{"shadow_bvh_width", "--shadow-bvh-width", "--shadows rays: the BVH's children a node, 2, 4 or 8"}, ValueKind::Number,
         Applies::Always, [](BenchPoint& p, const json& v) { p.frame.shadowBvhWidth = static_cast<int>(asNumber(v)); }},
        {{"shadow_rays_per_pixel", "--shadow-rays-per-pixel", "--shadows sampled: rays a pixel, 1, 2 or 4"}, ValueKind::Number,
         Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.shadowRaysPerPixel = static_cast<int>(checkShadowRaysPerPixel(static_cast<int>(asNumber(v)))); }},
        {{"shadow_reuse", "--shadow-reuse", "--shadows sampled: temporal or none"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const std::string reuse = asText(v);
             if (reuse != "temporal" && reuse != "none") throw std::invalid_argument("expected temporal or none");
             p.frame.shadowReuse = reuse;
         }},
        {{"shadow_denoise", "--shadow-denoise", "--shadows sampled: the ratio filtered over its neighbours, on or off"}, ValueKind::Boolean,
         Applies::Always, [](BenchPoint& p, const json& v) { p.frame.shadowDenoise = asBoolean(v) ? "on" : "off"; }},
        {{"light_sum", "--light-sum", "how a point adds up its lights: float (lists sorted), fixed (64-bit integers, lists unsorted)"},
         ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseLightSum(asText(v));
             p.frame.lightSum = v.get<std::string>();
         }},
        {{"light_cutoff", "--light-cutoff", "E > 0: generated lights reach as far as max(colour) / d^2 exceeds E, glTF's falloff"},
         ValueKind::Number, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const double x = asNumber(v);
             if (!(x > 0.0 && std::isfinite(x))) throw std::invalid_argument("must be a finite number > 0");
             p.frame.lightCutoff = static_cast<float>(x);
         }},
        {{"cutoff", "--cutoff", "hard, stochastic (ranges drawn per frame; needs light_cutoff) or none (naive only)"}, ValueKind::Text,
         Applies::Always,
         [](BenchPoint& p, const json& v) {
             const std::string s = asText(v);
             if (s != "hard" && s != "stochastic" && s != "none") throw std::invalid_argument("expected hard, stochastic or none");
             p.frame.cutoff = s;
         }},
        {{"accumulate", "--accumulate", "the physical_* columns on the mean of K stochastic draws of the frame (time: K frames)"},
         ValueKind::Integer, Applies::Always,
         [](BenchPoint& p, const json& v) { p.accumulate = static_cast<int>(asInteger(v, 1, 4096)); }},
        {{"bloom", "--bloom", "bloom after shading, before the tonemap: on, off"}, ValueKind::Boolean, Applies::Always,
         [](BenchPoint& p, const json& v) { p.frame.bloom = asBoolean(v); }},
        {{"method", "--method", "naive, forward-plus, deferred, visibility"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             const MethodKind kind = parseMethod(asText(v));
             p.frame.method = v.get<std::string>();
             p.clustered = kind != MethodKind::Naive;
             p.deferred = kind == MethodKind::Deferred;
             p.gbuffered = kind == MethodKind::Deferred || kind == MethodKind::Visibility;
             p.prepassed = kind == MethodKind::ForwardPlus || kind == MethodKind::Deferred;
             p.visibility = kind == MethodKind::Visibility;
         }},
        {{"gbuffer", "--gbuffer", "G-buffer of deferred and visibility: exact, standard, packed, two-component"}, ValueKind::Text,
         Applies::GBuffered,
         [](BenchPoint& p, const json& v) {
             (void)parseGBufferFormat(asText(v));
             p.frame.gbuffer = v.get<std::string>();
         }},
        {{"prepass", "--prepass", "depth pre-pass of forward-plus and deferred: on, off"}, ValueKind::Boolean, Applies::PrePassed,
         [](BenchPoint& p, const json& v) { p.frame.prepass = asBoolean(v) ? "on" : "off"; }},
        {{"msaa", "--msaa", "samples per pixel of naive and forward-plus: 1, 2, 4, 8 (deferred and visibility store one)"},
         ValueKind::Integer, Applies::Forward,
         [](BenchPoint& p, const json& v) { p.frame.msaa = validMsaa(asInteger(v, 1, 8)); }},
        {{"vis_raster", "--vis-raster", "visibility's raster: auto, hardware, compute, compute-two-pass"}, ValueKind::Text,
         Applies::Visibility,
         [](BenchPoint& p, const json& v) {
             (void)parseVisibilityRaster(asText(v));
             p.frame.visRaster = v.get<std::string>();
         }},
        {{"resolve", "--resolve", "deferred lighting pass: compute or fragment"}, ValueKind::Text, Applies::Deferred,
         [](BenchPoint& p, const json& v) {
             (void)parseResolve(asText(v));
             p.frame.resolve = v.get<std::string>();
         }},
        {{"slicing", "--slicing", "linear, log or fitted depth slices"}, ValueKind::Text, Applies::Clustered,
         [](BenchPoint& p, const json& v) {
             (void)parseSlicing(asText(v));
             p.frame.slicing = v.get<std::string>();
         }},
        {{"slices", "--slices", "depth slices"}, ValueKind::Integer, Applies::Clustered,
         [](BenchPoint& p, const json& v) { p.frame.slices = static_cast<unsigned>(asInteger(v, 1, 1024)); }},
        {{"tiles_x", "--tiles-x", "tiles across the screen (tiles down follow, square)"}, ValueKind::Integer,
         Applies::Clustered,
         [](BenchPoint& p, const json& v) { p.frame.tilesX = static_cast<unsigned>(asInteger(v, 1, 1024)); }},
        {{"assign", "--assign", "exact (count, scan, fill), capped (fixed lists) per-cluster (one invocation per cluster over all lights) or zbin (sorted lights, z-bins, tile masks)"}, ValueKind::Text, Applies::Clustered,
         [](BenchPoint& p, const json& v) {
             p.capped = parseAssignMode(asText(v)) == AssignMode::Capped;
             p.frame.assign = v.get<std::string>();
         }},
        {{"max_per_cluster", "--max-per-cluster", "list size of capped assignment"}, ValueKind::Integer, Applies::Capped,
         [](BenchPoint& p, const json& v) { p.frame.maxPerCluster = static_cast<unsigned>(asInteger(v, 1, 1 << 24)); }},
        {{"workgroup", "--workgroup", "light-assignment workgroup size (a power of two)"}, ValueKind::Integer,
         Applies::Clustered,
         [](BenchPoint& p, const json& v) {
             const auto n = static_cast<unsigned>(asInteger(v, 1, 1024));
             if ((n & (n - 1)) != 0) throw std::invalid_argument("must be a power of two");
             p.frame.workgroup = n;
         }},
        {{"active_only", "--active-only", "assign only to clusters holding a visible sample: on, off"},
         ValueKind::Boolean, Applies::Clustered, [](BenchPoint& p, const json& v) { p.frame.activeOnly = asBoolean(v); }},
        {{"draw", "--draw", "scene submission: direct or indirect (multi-draw indirect)"}, ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseDrawSubmission(asText(v));
             p.frame.draw = v.get<std::string>();
         }},
        {{"backface_culling", "--backface-culling", "cull back faces of single-sided materials: on, off"}, ValueKind::Boolean,
         Applies::Always, [](BenchPoint& p, const json& v) { p.frame.backfaceCulling = asBoolean(v) ? "on" : "off"; }},
        {{"transparency", "--transparency", "draw glTF BLEND surfaces blended over the opaque frame: on, off"}, ValueKind::Boolean,
         Applies::Always, [](BenchPoint& p, const json& v) { p.frame.transparency = asBoolean(v) ? "on" : "off"; }},
        {{"triangle_order", "--triangle-order", "each draw range's triangles at upload: as-loaded, vertex-cache, overdraw"},
         ValueKind::Text, Applies::Always,
         [](BenchPoint& p, const json& v) {
             (void)parseTriangleOrder(asText(v));
             p.frame.triangleOrder = v.get<std::string>();
         }},
        {{"cull", "--cull", "light-vs-cluster test: aabb, sphere, cone"}, ValueKind::Text, Applies::Clustered,
         [](BenchPoint& p, const json& v) {
             (void)parseCullMode(asText(v));
             p.frame.cull = v.get<std::string>();
         }},
        {{"normal_cones", "--normal-cones", "deferred and visibility, exact lists: lists per (cluster, normal bin): on, off"},
         ValueKind::Boolean, Applies::ExactGBuffered, [](BenchPoint& p, const json& v) { p.frame.normalCones = asBoolean(v); }},
    };
    return defs;
}

const AxisDef* findAxis(const std::string& key) {
    for (const AxisDef& a : axisDefs())
        if (key == a.info.key) return &a;
    return nullptr;
}

std::string axisKeyList() {
    std::string s;
    for (const AxisDef& a : axisDefs()) s += (s.empty() ? "" : ", ") + std::string(a.info.key);
    return s;
}

bool applies(const AxisDef& axis, const BenchPoint& p) {
    switch (axis.applies) {
    case Applies::Always: return true;
    case Applies::Clustered: return p.clustered;
    case Applies::Deferred: return p.deferred;
    case Applies::GBuffered: return p.gbuffered;
    case Applies::PrePassed: return p.prepassed;
    case Applies::Capped: return p.capped;
    case Applies::ExactGBuffered: return p.gbuffered && !p.capped;  // normal_cones: exact lists of a G-buffer
    case Applies::Forward: return !p.gbuffered;                       // msaa: naive and forward-plus
    case Applies::Visibility: return p.visibility;
    }
    return true;
}

void requireOnly(const json& object, const std::set<std::string>& allowed, const std::string& where) {
    for (const auto& [key, value] : object.items()) {
        if (allowed.count(key)) continue;
        std::string list;
        for (const std::string& k : allowed) list += (list.empty() ? "" : ", ") + k;
        throw std::invalid_argument(where + ": unknown key '" + key + "' (expected one of: " + list + ")");
    }
}

json asList(const json& v) { return v.is_array() ? v : json::array({v}); }

// A camera axis's values with each named set (app/bench/camera_sets.h) replaced by its cameras.
json expandCameraSets(const json& values) {
    json out = json::array();
    for (const json& v : values) {
        const auto set = v.is_string() ? namedCameraSet(v.get<std::string>()) : std::nullopt;
        if (!set) {
            out.push_back(v);
            continue;
        }
        for (const std::string& camera : *set) out.push_back(camera);
    }
    return out;
}

RunSettings parseRun(const json& run, const std::string& where) {
    RunSettings r;
    if (run.is_null()) return r;
    if (!run.is_object()) throw std::invalid_argument(where + ": \"run\" must be an object");
    requireOnly(run, {"warmup", "timed_frames", "frame", "naive_budget", "reference"}, where + ", run");
    auto field = [&](const char* key, auto&& read) {
        if (!run.contains(key)) return;
        try {
            read(run.at(key));
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(where + ", run." + key + " " + run.at(key).dump() + ": " + e.what());
        }
    };
    field("warmup", [&](const json& v) { r.warmupFrames = static_cast<int>(asInteger(v, 0, 1000)); });
    field("timed_frames", [&](const json& v) { r.timedFrames = static_cast<int>(asInteger(v, 1, 10000)); });
    field("frame", [&](const json& v) { r.firstFrame = static_cast<std::uint32_t>(asInteger(v, 0, 100'000'000)); });
    field("naive_budget", [&](const json& v) {
        const double b = asNumber(v);
        if (!(b > 0.0)) throw std::invalid_argument("must be > 0 (pixels x lights)");
        r.naiveBudget = b;
    });
    field("reference", [&](const json& v) { applyReferenceSetting(r, asText(v)); });
    return r;
}

std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// Checks what only the combination can get wrong (the grid's limits), naming the point.
void validatePoint(const BenchPoint& p) {
    validateGridConfig(ClusterGridConfig{p.frame.tilesX, p.frame.slices, parseSlicing(p.frame.slicing), p.frame.workgroup});
    if (p.frame.nearPlane && p.frame.farPlane && !(*p.frame.nearPlane < *p.frame.farPlane))
        throw std::invalid_argument("near " + formatNumber(*p.frame.nearPlane) + " is not below far " +
                                    formatNumber(*p.frame.farPlane));
}

}  // namespace

int parseReferenceSetting(const std::string& text) {
    if (text == "naive") return 0;
    if (text.rfind("supersampled:", 0) == 0) {
        const std::string k = text.substr(13);
        if (k.size() == 1 && k[0] >= '2' && k[0] <= '8') return k[0] - '0';
    }
    throw std::invalid_argument("expected naive or supersampled:K with K from 2 to 8 (naive at K x K samples per pixel)");
}

void applyReferenceSetting(RunSettings& run, const std::string& text) {
    if (text == "physical") {
        run.physicalReference = true;
        return;
    }
    try {
        run.supersampledReference = parseReferenceSetting(text);
    } catch (const std::invalid_argument&) {
        throw std::invalid_argument("expected naive, physical (naive with no cut-off) or supersampled:K with K from 2 to 8");
    }
}

std::string referenceSettingName(const RunSettings& run) {
    return run.physicalReference ? "physical" : referenceSettingName(run.supersampledReference);
}

std::string referenceSettingName(int supersampled) {
    return supersampled > 0 ? "supersampled:" + std::to_string(supersampled) : "naive";
}

std::string describePoint(const BenchPoint& p) {
    const FrameOptions& o = p.frame;
    std::string s = p.experiment + ": " + o.method + ", " + (o.lights ? std::to_string(*o.lights) : std::string("default")) + " lights";
    if (o.spotShare > 0.0f) s += " (" + formatNumber(100.0 * o.spotShare) + " % spots)";
    if (o.lightRadius.kind != RadiusSpec::Kind::SceneDefault) s += " (radius " + o.lightRadius.text() + ")";
    s += ", " + o.size;
    if (o.scene != "atrium") s += ", " + o.scene;
    if (!o.camera.empty()) s += ", camera " + o.camera;
    if (o.nearPlane) s += ", near " + formatNumber(*o.nearPlane);
    if (o.farPlane) s += ", far " + formatNumber(*o.farPlane);
    if (o.transparency != "on") s += ", transparency " + o.transparency;
    if (o.lightSum != FrameOptions{}.lightSum) s += ", " + o.lightSum + " light sum";
    if (p.clustered) {
        s += ", grid " + std::to_string(o.tilesX) + " across x " + std::to_string(o.slices) + " " + o.slicing + ", " + o.assign;
        if (p.capped) s += " cap " + std::to_string(o.maxPerCluster);
        s += ", wg " + std::to_string(o.workgroup);
        if (o.activeOnly) s += ", active only";
        if (o.cull != FrameOptions{}.cull) s += ", cull " + o.cull;
        if (o.normalCones) s += ", normal cones";
    }
    if (p.deferred) s += ", " + o.resolve + " resolve";
    if (p.gbuffered) s += ", " + o.gbuffer + " G-buffer";
    if (p.visibility && o.visRaster != FrameOptions{}.visRaster) s += ", " + o.visRaster + " raster";
    if (p.prepassed && o.prepass == "off") s += ", no pre-pass";
    if (o.msaa > 1) s += ", MSAA " + std::to_string(o.msaa);
    if (o.specular == "off") s += ", specular off";
    if (o.brdf != FrameOptions{}.brdf) s += ", " + o.brdf;
    if (o.lightCutoff) s += ", cut-off " + formatNumber(*o.lightCutoff) + (o.cutoff == "hard" ? "" : " " + o.cutoff);
    if (p.accumulate > 1) s += ", " + std::to_string(p.accumulate) + " draws accumulated";
    if (o.bloom) s += ", bloom";
    return s;
}

const std::vector<SweepAxis>& sweepAxes() {
    static const std::vector<SweepAxis> axes = [] {
        std::vector<SweepAxis> out;
        for (const AxisDef& a : axisDefs()) out.push_back(a.info);
        return out;
    }();
    return axes;
}

json axisValuesFromFlag(const std::string& key, const std::string& commaList) {
    const AxisDef* axis = findAxis(key);
    if (!axis) throw std::invalid_argument("unknown sweep axis '" + key + "'");
    // --camera takes commas itself: one camera per flag value, cameras separated by ';'.
    const char separator = key == std::string("camera") ? ';' : ',';
    json out = json::array();
    std::size_t start = 0;
    while (start <= commaList.size()) {
        std::size_t end = commaList.find(separator, start);
        if (end == std::string::npos) end = commaList.size();
        std::string item = commaList.substr(start, end - start);
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        start = end + 1;
        const std::string where = std::string(axis->info.flag) + " '" + commaList + "'";
        if (item.empty()) throw std::invalid_argument(where + ": empty value in the list");
        auto number = [&](bool whole) -> json {
            std::size_t used = 0;
            try {
                if (whole) {
                    const long long v = std::stoll(item, &used);
                    if (used == item.size()) return v;
                } else {
                    const double v = std::stod(item, &used);
                    if (used == item.size()) return v;
                }
            } catch (const std::exception&) {
            }
            throw std::invalid_argument(where + ": '" + item + "' is not " + (whole ? "a whole number" : "a number"));
        };
        switch (axis->kind) {
        case ValueKind::Integer: out.push_back(number(true)); break;
        case ValueKind::Number: out.push_back(number(false)); break;
        case ValueKind::Radius:
        case ValueKind::NumberOrAuto:
            // Words ("default", "overlap:32", "auto") stay text; anything else must be a number.
            if (std::isalpha(static_cast<unsigned char>(item[0]))) out.push_back(item);
            else out.push_back(number(false));
            break;
        case ValueKind::Text:
        case ValueKind::Boolean: out.push_back(item); break;
        }
    }
    return out;
}

Sweep expandSweep(const json& doc, const json& overrides, const std::vector<std::string>& only) {
    if (!doc.is_object()) throw std::invalid_argument("sweep: the document must be a JSON object");
    for (const char* key : {"name", "description"})
        if (doc.contains(key) && !doc.at(key).is_string())
            throw std::invalid_argument(std::string("sweep: \"") + key + "\" must be a string");
    Sweep sweep;
    sweep.name = doc.value("name", std::string("sweep"));
    sweep.description = doc.value("description", std::string());
    sweep.document = doc;
    const std::string where = "sweep '" + sweep.name + "'";
    requireOnly(doc, {"name", "description", "run", "defaults", "experiments"}, where);
    sweep.run = parseRun(doc.value("run", json()), where);

    std::set<std::string> axisKeys;
    for (const AxisDef& a : axisDefs()) axisKeys.insert(a.info.key);
    const json defaults = doc.value("defaults", json::object());
    if (!defaults.is_object()) throw std::invalid_argument(where + ": \"defaults\" must be an object");
    requireOnly(defaults, axisKeys, where + ", defaults");
    for (const auto& [key, value] : overrides.items())
        if (!findAxis(key)) throw std::invalid_argument("unknown sweep axis '" + key + "' (expected one of: " + axisKeyList() + ")");

    json experiments = doc.value("experiments", json::array());
    if (!experiments.is_array()) throw std::invalid_argument(where + ": \"experiments\" must be a list");
    if (experiments.empty()) experiments.push_back(json{{"name", sweep.name}});

    std::set<std::string> allowed = axisKeys;
    allowed.insert("name");
    allowed.insert("description");
    std::set<std::string> names;
    for (const json& e : experiments) {
        if (!e.is_object() || !e.contains("name") || !e.at("name").is_string())
            throw std::invalid_argument(where + ": every experiment needs a \"name\"");
        const std::string name = e.at("name").get<std::string>();
        if (!names.insert(name).second) throw std::invalid_argument(where + ": two experiments are named '" + name + "'");
        requireOnly(e, allowed, where + ", experiment '" + name + "'");
    }
    for (const std::string& o : only) {
        if (names.count(o)) continue;
        std::string list;
        for (const json& e : experiments) list += (list.empty() ? "" : ", ") + e.at("name").get<std::string>();
        throw std::invalid_argument("--experiment '" + o + "': " + where + " has no such experiment (it has: " + list + ")");
    }

    for (const json& e : experiments) {
        const std::string name = e.at("name").get<std::string>();
        if (!only.empty() && std::find(only.begin(), only.end(), name) == only.end()) continue;
        sweep.experiments.push_back(name);
        const std::string at = where + ", experiment '" + name + "'";

        // Each axis's values: the experiment's, else the defaults', else the command's own default.
        std::vector<std::pair<const AxisDef*, json>> axes;
        for (const AxisDef& a : axisDefs()) {
            json values;
            if (overrides.contains(a.info.key)) values = overrides.at(a.info.key);
            else if (e.contains(a.info.key)) values = e.at(a.info.key);
            else if (defaults.contains(a.info.key)) values = defaults.at(a.info.key);
            else continue;
            values = asList(values);
            if (a.info.key == std::string("camera")) values = expandCameraSets(values);
            if (values.empty()) throw std::invalid_argument(at + ", " + a.info.key + ": empty list");
            axes.emplace_back(&a, values);
        }

        // Odometer over the axes, the last axis turning fastest.
        std::vector<std::size_t> digit(axes.size(), 0);
        // --msaa above 1 where every method stores one sample per pixel is refused, as by
        // `render`; beside naive or forward-plus those methods run at one sample.
        std::string msaaRefused;
        bool msaaTaken = false;
        std::set<std::string> seen;
        for (bool more = true; more;) {
            BenchPoint p;
            p.experiment = name;
            p.frame.method = "deferred";
            p.clustered = p.deferred = p.gbuffered = p.prepassed = true;
            json key = json::object();
            for (std::size_t i = 0; i < axes.size(); ++i) {
                const json& v = axes[i].second[digit[i]];
                try {
                    axes[i].first->set(p, v);
                } catch (const std::invalid_argument& err) {
                    // Name the value where the user wrote it: the flag, or the file's key.
                    const std::string reason = err.what();
                    if (overrides.contains(axes[i].first->info.key))
                        throw std::invalid_argument(reason.rfind("--", 0) == 0 ? reason
                                                    : std::string(axes[i].first->info.flag) + " " + v.dump() + ": " + reason);
                    throw std::invalid_argument(at + ", " + axes[i].first->info.key + " " + v.dump() + ": " + reason);
                }
            }
            // Axes the method does not use go back to their defaults and out of the key.
            if (!p.clustered) {
                const FrameOptions d;
                p.frame.tilesX = d.tilesX, p.frame.slices = d.slices, p.frame.slicing = d.slicing;
                p.frame.workgroup = d.workgroup, p.frame.assign = d.assign, p.frame.activeOnly = d.activeOnly;
                p.frame.cull = d.cull;
                p.capped = false;
            }
            if (!p.capped) p.frame.maxPerCluster = FrameOptions{}.maxPerCluster;
            if (!p.gbuffered || p.capped) p.frame.normalCones = false;
            if (!p.deferred) p.frame.resolve = FrameOptions{}.resolve;
            if (!p.visibility) p.frame.visRaster = FrameOptions{}.visRaster;
            if (!p.gbuffered) p.frame.gbuffer = FrameOptions{}.gbuffer;
            if (!p.prepassed) p.frame.prepass = FrameOptions{}.prepass;
            if (p.frame.msaa > 1 && p.gbuffered)
                msaaRefused = "--msaa " + std::to_string(p.frame.msaa) + ": " + msaaRefusal(parseMethod(p.frame.method));
            if (p.frame.msaa > 1 && !p.gbuffered) msaaTaken = true;
            if (p.gbuffered) p.frame.msaa = FrameOptions{}.msaa;
            for (std::size_t i = 0; i < axes.size(); ++i)
                if (applies(*axes[i].first, p)) key[axes[i].first->info.key] = axes[i].second[digit[i]];
            try {
                validatePoint(p);
            } catch (const std::invalid_argument& err) {
                throw std::invalid_argument(at + ", point " + key.dump() + ": " + err.what());
            }
            if (seen.insert(key.dump()).second) sweep.points.push_back(std::move(p));

            more = false;
            for (std::size_t i = axes.size(); i-- > 0;) {
                if (++digit[i] < axes[i].second.size()) {
                    more = true;
                    break;
                }
                digit[i] = 0;
            }
        }
        if (!msaaRefused.empty() && !msaaTaken) throw std::invalid_argument(at + ": " + msaaRefused);
    }
    if (sweep.points.empty()) throw std::invalid_argument(where + ": the sweep has no points");
    return sweep;
}

}  // namespace ml::app
