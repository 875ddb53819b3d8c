#include "app/frame_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "app/animation_choice.h"
#include "app/camera_spec.h"
#include "app/material_variant_choice.h"
#include "renderer/camera/default_camera.h"
#include "glsl/include/bindings.h"
#include "renderer/lights/light_buffers.h"
#include "renderer/passes/overdraw_pass.h"
#include "renderer/scene/material_features.h"
#include "scenes/animation_pose.h"
#include "scenes/scene_library.h"

namespace ml::app {

namespace {
// Larger than any GL implementation's maximum texture size; the context checks the real limit.
constexpr int kMaxDimension = 16384;
constexpr long long kMaxLights = 16'777'216;

// on/off switches (--specular, --prepass): one line naming the flag and the bad value.
bool parseOnOff(const char* flag, const std::string& text) {
    // true/false too: the words a sweep file's booleans take.
    if (text == "on" || text == "true") return true;
    if (text == "off" || text == "false") return false;
    throw std::invalid_argument(std::string(flag) + " '" + text + "': expected on or off");
}

// --near/--far: a distance > 0, or auto (fitted to the scene), as a sweep's "near"/"far" take it.
std::optional<float> parseClipPlane(const char* flag, const std::string& text) {
    if (text == "auto") return std::nullopt;
    try {
        std::size_t used = 0;
        const float v = std::stof(text, &used);
        if (used == text.size() && std::isfinite(v) && v > 0.0f) return v;
    } catch (const std::exception&) {
    }
    throw std::invalid_argument(std::string(flag) + " '" + text + "': expected a distance > 0, or auto (fitted to the scene)");
}
float aspectOf(const FrameSettings& settings) {
    return static_cast<float>(settings.width) / static_cast<float>(settings.height);
}
}  // namespace

LightModel parseLightModel(const FrameOptions& o) {
    LightModel model;
    model.brdf = parseBrdf(o.brdf);
    if (o.lightCutoff && !(std::isfinite(*o.lightCutoff) && *o.lightCutoff > 0.0f))
        throw std::invalid_argument("--light-cutoff: must be a finite number > 0");
    if (o.lightCutoff && o.lightRadius.kind != RadiusSpec::Kind::SceneDefault)
        throw std::invalid_argument("--light-cutoff with --light-radius: choose one (the cut-off sets every generated light's radius)");
    model.cutoff = o.lightCutoff.value_or(0.0f);
    if (o.cutoff == "hard") {
        model.falloff = o.lightCutoff ? Falloff::Gltf : Falloff::Smooth;
    } else if (o.cutoff == "stochastic") {
        if (!o.lightCutoff) throw std::invalid_argument("--cutoff stochastic: needs --light-cutoff E (the contribution the roulette starts at)");
        model.falloff = Falloff::Stochastic;
    } else if (o.cutoff == "none") {
        model.falloff = Falloff::Untruncated;
    } else {
        throw std::invalid_argument("--cutoff '" + o.cutoff + "': expected hard, stochastic or none");
    }
    return model;
}

void checkCutoffForMethod(const LightModel& model, MethodKind method) {
    if (model.falloff == Falloff::Untruncated && method != MethodKind::Naive)
        throw std::invalid_argument("--cutoff none: needs --method naive (every light reaches every pixel; no cluster can hold that)");
}

SceneLook defaultLook(const std::string& scene, Brdf brdf) {
    if (!isBuiltinScene(scene)) return SceneLook{};
    const float unitless = unitlessLightExposure(brdf);
    return SceneLook{FrameSettings{}.ambient / unitless, std::log2(unitless)};
}

void addFrameOptions(CLI::App& cmd, FrameOptions& o) {
    cmd.add_option("--scene", o.scene, "atrium, plane, boxes, or a .gltf/.glb file")->capture_default_str();
    cmd.add_option("--detail", o.detail, "tessellation scale of procedural scenes")->capture_default_str();
    cmd.add_option("--method", o.method, "shading method: " + [] {
        std::string s;
        for (const auto& n : methodNames()) s += (s.empty() ? "" : ", ") + n;
        return s;
    }())->capture_default_str();
    auto* grid = cmd.add_option_group("clustering", "cluster grid and light assignment (forward-plus, deferred)");
    grid->add_option("--tiles-x", o.tilesX, "tiles across the screen (its longer side); tiles down follow so tiles stay square")->capture_default_str();
    grid->add_option("--slices", o.slices, "depth slices")->capture_default_str();
    grid->add_option("--slicing", o.slicing, "linear, log (near to far plane), or fitted (log over the visible depth range)")->capture_default_str();
    grid->add_option("--workgroup", o.workgroup, "compute workgroup size of the light assignment")->capture_default_str();
    grid->add_option("--assign", o.assign, "exact (count, prefix sum, fill; no cap), capped (fixed lists, the seeds' baseline) per-cluster (one invocation per cluster over all lights; exact) or zbin (depth-sorted lights, z-bin ranges, tile bit masks)")->capture_default_str();
    grid->add_option("--max-per-cluster", o.maxPerCluster, "list size of --assign capped")->capture_default_str();
    grid->add_flag("--active-only", o.activeOnly, "assign lights only to clusters that hold a visible sample");
    grid->add_option("--cull", o.cull, "light-vs-cluster test: aabb (sphere vs the cluster's AABB), sphere (vs its frustum planes), cone (seed 001's spherical-sliced cone)")->capture_default_str();
    grid->add_flag("--normal-cones", o.normalCones, "deferred and visibility: lists per (cluster, view-space normal bin), skipping lights behind every surface of a cluster (Olsson et al. 2012)");
    grid->add_option("--vis-raster", o.visRaster,
                     "visibility's raster: auto (hardware), hardware, compute (by compute shaders; 64-bit atomics where "
                     "the GPU has them), compute-two-pass (32-bit atomics, as without them)")
        ->capture_default_str();
    grid->add_option("--resolve", o.resolve, "deferred lighting pass: compute or fragment")->capture_default_str();
    grid->add_option("--gbuffer", o.gbuffer, "G-buffer of deferred and visibility: exact (3 x RGBA32F with the position, 48 B/px: "
                     "holds the accuracy contract), standard (3 x RGBA16F, 24 B/px), packed (1 x RGBA32UI, 16 B/px), two-component (normal z rebuilt, loses its sign: the documented failure case); "
                     "naive and forward-plus have none and ignore it")->capture_default_str();
    grid->add_option("--prepass", o.prepass, "depth pre-pass of forward-plus and deferred, so each pixel is shaded (forward-plus) "
                     "or written to the G-buffer (deferred) once: on, or off (one LESS pass over every fragment, overdraw "
                     "included; forward-plus: fitted slicing falls back to log, --active-only is refused)")->capture_default_str();
    cmd.add_option("--msaa", o.msaa, "samples per pixel: 1, 2, 4 or 8 (naive and forward-plus; resolved in linear HDR "
                   "before the tonemap; deferred and visibility store one sample per pixel and refuse it)")->capture_default_str();
    cmd.add_option("--view", o.view, "shaded, light-count, slices, clusters, overflow, albedo, normal, depth, overdraw (fragments shaded per pixel, any method)")->capture_default_str();
    cmd.add_option("--lights", o.lights, "number of generated lights, added to the scene file's own (default: 1024, or 0 for a file with lights)");
    cmd.add_option("--spot-share", o.spotShare, "share of the generated lights that are spots, in [0, 1] (random directions)")->capture_default_str();
    cmd.add_option("--spot-angle", o.spotAngle, "generated spots' outer cone angle in degrees, (0, 90] (inner: 0.7 of it); 0: each spot's in [20, 60]")->capture_default_str();
    cmd.add_option("--scene-lights", o.sceneLights, "on: render a glTF file's own lights (KHR_lights_punctual); off: leave them out")->capture_default_str();
    cmd.add_option_function<std::string>(
           "--light-radius", [&o](const std::string& text) { o.lightRadius = parseRadius(text); },
           "light radius: R in scene units, default (a tenth of the scene's diagonal), or overlap:K (the radius at "
           "which about K generated lights reach any point of the light volume)")
        ->type_name("R|default|overlap:K");
    cmd.add_option("--light-intensity", o.lightIntensity, "light intensity multiplier")->capture_default_str();
    cmd.add_option("--seed", o.seed, "seed of the light placement")->capture_default_str();
    cmd.add_option("--light-placement", o.lightPlacement,
                   "where generated lights go: volume (uniform in the scene's bounds) or surfaces (area-weighted points "
                   "on its triangles, a quarter of the radius out along the normal) (default: volume for a built-in "
                   "scene, surfaces for a file)")
        ->type_name("volume|surfaces");
    cmd.add_option("--lights-file", o.lightsFile, "load an exact light set from JSON (replaces the generated and the scene file's lights)");
    cmd.add_option("--save-lights", o.saveLights, "write the light set of the rendered frame (after animation) to JSON");
    cmd.add_option("--size", o.size, "output size WxH")->capture_default_str();
    cmd.add_option("--camera", o.camera, "px,py,pz,tx,ty,tz,fovy_deg; gltf:N for the glTF file's Nth camera (from 0; "
                   "its clip planes unless --near/--far); orbit[:frames=N][,elevation=DEG][,distance=D][,azimuth=DEG]"
                   "[,fovy=DEG], a turntable around the scene's centre that the frames follow; or default: a built-in "
                   "scene's view, a file's first camera, else the file framed from its front (the default)");
    cmd.add_option_function<std::string>(
           "--near", [&o](const std::string& text) { o.nearPlane = parseClipPlane("--near", text); },
           "near clip plane, or auto (the default: fits the scene's bounds)");
    cmd.add_option_function<std::string>(
           "--far", [&o](const std::string& text) { o.farPlane = parseClipPlane("--far", text); },
           "far clip plane, or auto (the default: fits the scene's bounds)");
    cmd.add_option("--frames", o.frames, "advance the light animation this many frames (1/60 s each) first")->capture_default_str();
    cmd.add_option("--animation", o.animation, "the glTF clip a file plays: its name, its index (from 0), or off "
                   "(drawn at rest) (default: the first clip)")->type_name("NAME|INDEX|off");
    cmd.add_option("--scene-time", o.sceneTime, "seconds into the clip at frame 0; each frame adds 1/60 s, as the lights' "
                   "animation does, and the clip loops")->capture_default_str();
    cmd.add_option("--material-variant", o.materialVariant, "a glTF file's KHR_materials_variants variant to draw, by name "
                   "(default: the file's own materials; `info FILE` lists them)");
    cmd.add_option("--exposure", o.exposure, "auto (from the frame's log-average luminance, computed on the GPU), or EV "
                   "stops (the HDR frame times 2^EV before the tonemap) (default: auto for a file; for a built-in scene "
                   "log2(pi) = 1.65 under --brdf ggx, whose Lambert divides by pi, and 0 under blinn-phong: the same look)")
        ->type_name("auto|EV");
    cmd.add_option("--draw", o.draw, "scene submission: direct (a draw call per draw range) or indirect (multi-draw indirect, a call per texture)")->capture_default_str();
    cmd.add_option("--triangle-order", o.triangleOrder, "each draw range's triangles at upload: as-loaded, vertex-cache or overdraw (meshoptimizer; renderer/scene/triangle_order.h)")->capture_default_str();
    cmd.add_option("--backface-culling", o.backfaceCulling, "on: raster passes cull the back faces of single-sided materials (glTF doubleSided false); off: draw both sides of everything")->capture_default_str();
    cmd.add_option("--transparency", o.transparency, "on: draw glTF BLEND surfaces (the atrium's glass) blended over the opaque frame, each pixel's in depth order (with --msaa: back to front per draw range), and KHR_materials_transmission surfaces seeing the opaque frame through them; off: leave them out")->capture_default_str();
    cmd.add_flag("--bloom", o.bloom, "bloom: bright pass, half-resolution Gaussian, added to the HDR image before the tonemap");
    cmd.add_option("--bloom-threshold", o.bloomThreshold, "luminance above which pixels bloom")->capture_default_str();
    cmd.add_option("--bloom-strength", o.bloomStrength, "how much of the blurred bright part is added back")->capture_default_str();
    cmd.add_option("--specular", o.specular, "on: the BRDF's specular term; off: Lambert only (every method and the reference alike)")->capture_default_str();
    cmd.add_option("--brdf", o.brdf, "ggx (glTF's metallic-roughness BRDF, appendix B) or blinn-phong (the seeds' normalized Blinn-Phong, no 1/pi)")->capture_default_str();
    cmd.add_option("--shadows", o.shadows, "off: lights pass through everything; rays: an exact shadow ray for every point and light "
                   "that adds light, in every method (naive traces the same rays; BLEND surfaces cast none); sampled: deferred's "
                   "compute lighting and the visibility buffer sum every light unshadowed and trace a few rays a pixel to lights "
                   "drawn by their light, the visibility ratio reused and filtered (the other methods and glass trace the exact rays)")->capture_default_str();
    cmd.add_option("--shadow-rays-per-pixel", o.shadowRaysPerPixel, "--shadows sampled: rays a pixel, 1, 2 or 4")->capture_default_str();
    cmd.add_option("--shadow-reuse", o.shadowReuse, "--shadows sampled: temporal (each pixel's ratio averaged with its past frames', "
                   "reprojected, where the same surface was there) or none")->capture_default_str();
    cmd.add_option("--shadow-denoise", o.shadowDenoise, "--shadows sampled: on (the ratio filtered over the pixel's neighbours on its "
                   "surface) or off (the raw estimate: unbiased, noisy)")->capture_default_str();
    cmd.add_option("--shadow-bvh-width", o.shadowBvhWidth, "--shadows rays: the BVH's children a node, 2, 4 or 8 (the same answer; "
                   "the default measured fastest on the H100, docs/lights-and-shading.md)")->capture_default_str();
    cmd.add_option("--light-sum", o.lightSum, "how a point adds up its lights, in every method: float (lists sorted by light index, "
                   "so sums run in naive's order), or fixed (64-bit integers, the same bits in any order: the lists go unsorted; "
                   "needs GL_ARB_gpu_shader_int64; pays at millions of lights)")->capture_default_str();
    cmd.add_option("--light-cutoff", o.lightCutoff, "E > 0 in output units: each generated light, and each scene light without a range, reaches as far as its "
                   "inverse square max(colour) / d^2 exceeds E; lights fall off as glTF says (clamp(1 - (d/r)^4, 0, 1) / max(d, 0.01)^2)");
    cmd.add_option("--cutoff", o.cutoff, "hard (glTF's window at each light's radius), stochastic (ranges drawn per frame by Russian roulette, "
                   "unbiased; needs --light-cutoff) or none (every light reaches everywhere, pure inverse square: the physical reference, naive only)")->capture_default_str();
    cmd.add_option("--drift-speed", o.driftSpeed, "mean upward drift of the lights, units per second (0: still)")->capture_default_str();
    cmd.add_option("--backend", o.backend, "offscreen GL: auto (EGL, then OSMesa), egl, osmesa")->capture_default_str();
    cmd.add_flag("--gl-debug", o.glDebug, "debug context; print every KHR_debug message");
    cmd.add_flag("--verbose", o.verbose, "print GL_RENDERER, GL_VERSION and scene details");
    cmd.add_flag("--time", o.time, "print per-pass times (GPU timer queries; wall clock after glFinish on llvmpipe)");
}

long long generatedLightCount(const FrameOptions& o, const Scene& scene) {
    if (o.lights) return *o.lights;
    return !scene.lights.empty() && parseOnOff("--scene-lights", o.sceneLights) ? 0 : 1024;
}

LightPlacement lightPlacementFor(const FrameOptions& o) {
    if (!o.lightPlacement.empty()) return parseLightPlacement(o.lightPlacement);
    return isBuiltinScene(o.scene) ? LightPlacement::Volume : LightPlacement::Surfaces;
}

float lightRadiusFor(const FrameOptions& o, const Scene& scene) {
    return resolveRadius(o.lightRadius, scene.bounds, generatedLightCount(o, scene));
}

std::vector<Light> frameLights(const FrameOptions& o, const Scene& scene) {
    if (!o.lightsFile.empty()) return loadLightsFile(o.lightsFile);
    std::vector<Light> lights;
    if (parseOnOff("--scene-lights", o.sceneLights)) lights = lightsFromScene(scene, o.lightCutoff.value_or(kUnboundedLightThreshold));
    LightGeneration gen;
    gen.count = static_cast<std::uint32_t>(generatedLightCount(o, scene));
    gen.radius = lightRadiusFor(o, scene);
    gen.intensity = o.lightIntensity;
    gen.seed = static_cast<std::uint32_t>(o.seed);
    gen.spotShare = o.spotShare;
    gen.spotAngleDeg = o.spotAngle;
    std::vector<Light> generated = generateLights(scene, gen, lightPlacementFor(o));
    if (o.lightCutoff) applyCutoffRadii(generated, *o.lightCutoff);
    lights.insert(lights.end(), generated.begin(), generated.end());
    return lights;
}

bool isBuiltinScene(const std::string& scene) {
    const auto& names = builtinSceneNames();
    return std::find(names.begin(), names.end(), scene) != names.end();
}

ExposureSpec parseExposure(const std::string& text) {
    if (text == "auto") return ExposureSpec{true, 0.0f};
    try {
        std::size_t used = 0;
        const float stops = std::stof(text, &used);
        if (used == text.size() && std::isfinite(stops) && std::abs(stops) <= 24.0f) return ExposureSpec{false, stops};
    } catch (const std::exception&) {
    }
    throw std::invalid_argument("--exposure '" + text + "': expected auto, or EV stops between -24 and 24 (0: the HDR frame as it is)");
}

void parseSize(const std::string& text, int& width, int& height) {
    const auto x = text.find('x');
    auto parse = [&](const std::string& part) {
        std::size_t used = 0;
        long v = 0;
        try {
            v = std::stol(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != part.size() || part.empty())
            throw std::invalid_argument("--size '" + text + "': expected WxH with whole numbers, e.g. 1280x720");
        if (v <= 0 || v > kMaxDimension)
            throw std::invalid_argument("--size '" + text + "': each side must be between 1 and " + std::to_string(kMaxDimension));
        return static_cast<int>(v);
    };
    if (x == std::string::npos) throw std::invalid_argument("--size '" + text + "': expected WxH, e.g. 1280x720");
    width = parse(text.substr(0, x));
    height = parse(text.substr(x + 1));
}

PreparedFrame prepareFrame(const FrameOptions& o, const Scene* loaded) {
    PreparedFrame f;
    // Flags first: a bad flag is reported before any scene is built or GL touched.
    parseSize(o.size, f.settings.width, f.settings.height);
    f.settings.method.kind = parseMethod(o.method);
    ClusteringSettings& clustering = f.settings.method.clustering;
    clustering.grid = ClusterGridConfig{o.tilesX, o.slices, parseSlicing(o.slicing), o.workgroup};
    validateGridConfig(clustering.grid);
    clustering.assign = parseAssignMode(o.assign);
    if (o.maxPerCluster == 0 || o.maxPerCluster > (1u << 24))
        throw std::invalid_argument("--max-per-cluster " + std::to_string(o.maxPerCluster) + ": must be between 1 and 16777216");
    clustering.maxPerCluster = o.maxPerCluster;
    clustering.activeOnly = o.activeOnly;
    clustering.cull = parseCullMode(o.cull);
    clustering.normalCones = o.normalCones;
    if (o.normalCones && f.settings.method.kind != MethodKind::Deferred && f.settings.method.kind != MethodKind::Visibility)
        throw std::invalid_argument("--normal-cones: needs --method deferred or visibility (" + o.method +
                                    " knows no surface normal before it shades)");
    if (o.normalCones && clustering.assign == AssignMode::Capped)
        throw std::invalid_argument("--normal-cones: needs exact lists (--assign exact or per-cluster), not --assign capped");
    clustering.view = parseDebugView(o.view);
    if (f.settings.method.kind == MethodKind::Naive && clustering.view != DebugView::Shaded && clustering.view != DebugView::Overdraw)
        throw std::invalid_argument("--view " + o.view + ": needs a clustered method (--method forward-plus or deferred)");
    f.settings.method.resolve = parseResolve(o.resolve);
    f.settings.method.visibilityRaster = parseVisibilityRaster(o.visRaster);
    clustering.lightSum = parseLightSum(o.lightSum);
    f.settings.specular = parseOnOff("--specular", o.specular);
    f.settings.lightModel = parseLightModel(o);
    checkCutoffForMethod(f.settings.lightModel, f.settings.method.kind);
    f.settings.method.gbuffer = parseGBufferFormat(o.gbuffer);
    f.settings.method.prepass = parseOnOff("--prepass", o.prepass);
    if (!f.settings.method.prepass && f.settings.method.kind == MethodKind::ForwardPlus) {
        if (clustering.activeOnly)
            throw std::invalid_argument("--active-only needs the depth pre-pass of forward-plus (drop --prepass off)");
        if (clustering.grid.slicing == Slicing::Fitted)
            f.warnings.push_back("--prepass off: no depth exists before the light lists, so fitted slicing falls back to log");
    }
    f.settings.method.msaa = validMsaa(o.msaa);
    if (const char* refusal = msaaRefusal(f.settings.method.kind); refusal && o.msaa > 1)
        throw std::invalid_argument("--msaa " + std::to_string(o.msaa) + ": " + refusal);
    if (clustering.view == DebugView::Overdraw && o.msaa > 1) throw std::invalid_argument(kOverdrawRefusesMsaa);
    if (o.supersample < 1 || o.supersample > 8)
        throw std::invalid_argument("--supersample " + std::to_string(o.supersample) + ": must be between 1 and 8");
    if (o.supersample > 1 && o.msaa > 1)
        throw std::invalid_argument("--supersample with --msaa: choose one (the supersampled reference shades every drawn pixel once)");
    f.settings.supersample = static_cast<int>(o.supersample);
    if (!(std::isfinite(o.bloomThreshold) && o.bloomThreshold >= 0.0f))
        throw std::invalid_argument("--bloom-threshold: must be a finite number >= 0");
    if (!(std::isfinite(o.bloomStrength) && o.bloomStrength >= 0.0f))
        throw std::invalid_argument("--bloom-strength: must be a finite number >= 0");
    f.settings.bloom = BloomSettings{o.bloom, o.bloomThreshold, o.bloomStrength};
    f.context.backend = parseBackend(o.backend);
    f.context.debug = o.glDebug;
    if (o.lights && (*o.lights < 0 || *o.lights > kMaxLights))
        throw std::invalid_argument("--lights " + std::to_string(*o.lights) + ": must be between 0 and " + std::to_string(kMaxLights));
    if (!(o.spotShare >= 0.0f && o.spotShare <= 1.0f)) throw std::invalid_argument("--spot-share: must be in [0, 1]");
    if (!(o.spotAngle >= 0.0f && o.spotAngle <= 90.0f))
        throw std::invalid_argument("--spot-angle: must be in (0, 90] degrees, or 0 for a range of [20, 60]");
    parseOnOff("--scene-lights", o.sceneLights);
    f.settings.shadows = parseShadows(o.shadows);
    if (o.shadowBvhWidth < 0 || !shadowBvhWidthSupported(static_cast<std::uint32_t>(o.shadowBvhWidth)))
        throw std::invalid_argument("--shadow-bvh-width " + std::to_string(o.shadowBvhWidth) + ": must be 2, 4 or 8");
    f.settings.shadowBvhWidth = static_cast<std::uint32_t>(o.shadowBvhWidth);
    f.settings.sampledShadows.raysPerPixel = checkShadowRaysPerPixel(o.shadowRaysPerPixel);
    if (o.shadowReuse != "temporal" && o.shadowReuse != "none")
        throw std::invalid_argument("--shadow-reuse '" + o.shadowReuse + "': expected temporal or none");
    f.settings.sampledShadows.temporal = o.shadowReuse == "temporal";
    f.settings.sampledShadows.denoise = parseOnOff("--shadow-denoise", o.shadowDenoise);
    if (o.seed < 0 || o.seed > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("--seed " + std::to_string(o.seed) + ": must be between 0 and 4294967295");
    if (o.frames < 0 || o.frames > 100'000'000)
        throw std::invalid_argument("--frames " + std::to_string(o.frames) + ": must be between 0 and 100000000");
    if (!(std::isfinite(o.lightIntensity) && o.lightIntensity >= 0.0f))
        throw std::invalid_argument("--light-intensity: must be a finite number >= 0");
    const bool exposureGiven = !o.exposure.empty();
    const SceneLook look = defaultLook(o.scene, f.settings.lightModel.brdf);
    f.settings.ambient = look.ambient;
    const ExposureSpec exposure = exposureGiven ? parseExposure(o.exposure)
                                                : ExposureSpec{!look.exposureStops, look.exposureStops.value_or(0.0f)};
    const LightPlacement placement = lightPlacementFor(o);
    if (!std::isfinite(o.driftSpeed)) throw std::invalid_argument("--drift-speed: must be finite");
    if (!(std::isfinite(o.detail) && o.detail > 0.0f && o.detail <= 16.0f))
        throw std::invalid_argument("--detail: must be in (0, 16]");
    f.frameIndex = static_cast<std::uint32_t>(o.frames);
    f.lightPlacement = placement;

    f.scene = loaded ? *loaded : loadScene(SceneRequest{o.scene, o.detail}, f.warnings);
    if (f.scene.indices.empty()) throw SceneError(o.scene + ": the scene has no triangles");
    applyMaterialVariant(f.scene, parseMaterialVariant(o.materialVariant, f.scene));
    f.settings.sceneAnimation = sceneAnimationFor(o.animation, o.sceneTime, f.scene);
    if (const std::optional<std::size_t> clip = f.settings.sceneAnimation.clip) {
        // The scene as frame 0 shows it (the default camera frames it, lights are placed on it),
        // and bounds that hold it over the whole loop (clip planes, light volume). Not frame
        // --frames K's pose: then `--frames K` and frame K of a sequence would differ.
        applyPose(f.scene, poseAt(*f.scene.animation, sceneClip(f.scene, clip), o.sceneTime));
        f.scene.bounds = sweptBounds(f.scene, clip, o.sceneTime, kSecondsPerFrame);
    }
    const bool gbufferMethod = f.settings.method.kind == MethodKind::Deferred || f.settings.method.kind == MethodKind::Visibility;
    if (gbufferMethod && f.settings.method.gbuffer == GBufferFormat::TwoComponent && (materialFeatures(f.scene) & ML_FEATURE_EMISSIVE))
        f.warnings.push_back("--gbuffer two-component has no room for emissive: the scene's emissive surfaces stay dark "
                             "(standard and packed store it)");
    if (gbufferMethod && f.settings.method.gbuffer != GBufferFormat::Exact &&
        (materialFeatures(f.scene) &
         (ML_FEATURE_SPECULAR | ML_FEATURE_UNLIT | ML_FEATURE_CLEARCOAT | ML_FEATURE_SHEEN | ML_FEATURE_ANISOTROPY |
          ML_FEATURE_IRIDESCENCE)))
        f.warnings.push_back(std::string("--gbuffer ") + gbufferFormatName(f.settings.method.gbuffer) +
                             " has no room for KHR_materials_specular, ior, unlit, clearcoat, sheen, anisotropy or iridescence: those "
                             "surfaces are lit as glTF's default material (exact stores them)");
    // The loader makes tangents for every anisotropic material; a scene built without them cannot
    // stretch the lobe (materialFeatures leaves ML_FEATURE_ANISOTROPY off).
    if (f.scene.tangents.empty() &&
        std::any_of(f.scene.materials.begin(), f.scene.materials.end(), [](const Material& m) { return m.anisotropyModelled(); }))
        f.warnings.push_back("KHR_materials_anisotropy: the scene has no tangents, so its anisotropic materials are lit isotropic");

    if (isOrbitSpec(o.camera)) f.orbit = orbitAround(parseOrbitSpec(o.camera), f.scene, aspectOf(f.settings));
    Camera camera;
    if (f.orbit) {
        camera = f.orbit->at(f.frameIndex);
        fitClipPlanes(camera, f.scene.bounds);
    } else if (namesSceneCamera(o.camera)) {
        const SceneCamera& fileCamera = f.scene.cameras[sceneCameraIndex(o.camera, f.scene.cameras.size())];
        camera = cameraFromSceneCamera(fileCamera);
        fitClipPlanes(camera, f.scene.bounds, fileCamera);
    } else if (o.camera.empty() || o.camera == "default") {
        const DefaultCamera chosen = defaultCamera(f.scene, aspectOf(f.settings));
        camera = chosen.camera;
        if (!chosen.choice.empty()) f.notes.push_back("camera: " + chosen.choice);
    } else {
        camera = parseCamera(o.camera);
        fitClipPlanes(camera, f.scene.bounds);
    }
    if (o.nearPlane) camera.nearPlane = *o.nearPlane;
    if (o.farPlane) camera.farPlane = *o.farPlane;
    if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane && std::isfinite(camera.farPlane)))
        throw std::invalid_argument("--near/--far: need 0 < near < far (got near " + std::to_string(camera.nearPlane) +
                                    ", far " + std::to_string(camera.farPlane) + ")");
    f.settings.camera = camera;
    f.settings.autoExposure = exposure.automatic;
    f.settings.exposure = std::exp2(exposure.stops);
    if (!exposureGiven && exposure.automatic)
        f.notes.push_back("exposure: auto (the frame's log-average luminance to middle grey; --exposure EV for a fixed one)");
    f.settings.draw = parseDrawSubmission(o.draw);
    f.settings.backfaceCulling = parseOnOff("--backface-culling", o.backfaceCulling);
    f.settings.transparency = parseOnOff("--transparency", o.transparency);
    f.settings.triangleOrder = parseTriangleOrder(o.triangleOrder);
    f.settings.timing = o.time;
    const Bounds volume = lightVolume(f.scene.bounds);
    f.settings.animation = verticalDrift(volume, o.driftSpeed);

    f.lights = frameLights(o, f.scene);
    if (o.lightPlacement.empty() && f.lightPlacement == LightPlacement::Surfaces && o.lightsFile.empty())
        if (const long long n = generatedLightCount(o, f.scene); n > 0)
        {
            char radius[32];
            std::snprintf(radius, sizeof radius, "%.3g", lightRadiusFor(o, f.scene));
            f.notes.push_back("lights: " + std::to_string(n) + " generated near the surfaces, radius " + radius +
                              " (--light-placement volume for the uniform rule, --lights 0 for the file's own only)");
        }
    try {
        toGpuSunLights(f.lights);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument((o.lightsFile.empty() ? o.scene : o.lightsFile) + ": " + e.what());
    }
    return f;
}

}  // namespace ml::app
