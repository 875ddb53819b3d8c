// The flags that describe a frame (scene, lights, camera, method, size, context), shared by
// the subcommands, and their validation into typed settings before any GL work is done.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/light_radius.h"

#include "renderer/camera/camera_orbit.h"
#include "renderer/context/gl_context.h"
#include "renderer/frame_renderer.h"
#include "renderer/lights/light_set.h"
#include "renderer/lights/surface_placement.h"
#include "scenes/scene.h"

namespace ml::app {

struct FrameOptions {
    std::string scene = "atrium";
    float detail = 1.0f;
    std::string method = "deferred";
    // Clustering
    unsigned tilesX = ClusterGridConfig{}.tilesX;
    unsigned slices = ClusterGridConfig{}.slices;
    std::string slicing = "fitted";
    unsigned workgroup = 64;
    std::string assign = "exact";
    unsigned maxPerCluster = 2048;
    bool activeOnly = false;
    std::string cull = "aabb";
    bool normalCones = false;
    std::string resolve = "compute";
    std::string visRaster = "auto";
    std::string gbuffer = "exact";
    std::string prepass = "on";
    long long msaa = 1;        // --msaa: naive and forward-plus
    long long supersample = 1; // --supersample (render only): drawn at K times the size, box-filtered down
    std::string view = "shaded";
    std::optional<long long> lights;  // generated lights; default 1024, or 0 when the scene file has lights
    float spotShare = 0.0f;           // share of generated lights that are spots
    float spotAngle = 0.0f;           // generated spots' outer cone angle in degrees; 0: each in [20, 60]
    std::string sceneLights = "on";   // the scene file's own lights (KHR_lights_punctual)
    RadiusSpec lightRadius;           // --light-radius R|default|overlap:K (app/light_radius.h)
    float lightIntensity = 1.0f;
    long long seed = 1;
    std::string lightPlacement;       // volume or surfaces; empty: volume for a built-in scene, surfaces for a file
    std::string lightsFile;
    std::string saveLights;
    std::string size = "1280x720";
    std::string camera;
    std::optional<float> nearPlane;
    std::optional<float> farPlane;
    long long frames = 0;
    std::string animation;   // --animation NAME|INDEX|off; empty: the first clip (app/animation_choice.h)
    double sceneTime = 0.0;  // --scene-time: seconds into the clip at frame 0
    std::string materialVariant;  // --material-variant NAME (KHR_materials_variants); empty: the file's own materials
    // --exposure: auto, or EV stops (2^EV before the tonemap); empty: defaultLook (auto for a file;
    // for a built-in scene log2(pi) under GGX, 0 under Blinn-Phong).
    std::string exposure;
    std::string draw = "direct";
    std::string backfaceCulling = "on";
    std::string transparency = "on";
    std::string triangleOrder = "overdraw";
    std::string specular = "on";
    std::string brdf = "ggx";
    std::string shadows = "off";
    int shadowBvhWidth = static_cast<int>(kDefaultShadowBvhWidth);  // --shadow-bvh-width: 2, 4 or 8
    int shadowRaysPerPixel = 2;          // --shadow-rays-per-pixel (--shadows sampled): 1, 2 or 4
    std::string shadowReuse = "temporal";  // --shadow-reuse temporal|none
    std::string shadowDenoise = "on";      // --shadow-denoise on|off
    std::string lightSum = "float";
    std::optional<float> lightCutoff;  // --light-cutoff E: radii where max(colour) / d^2 falls to E, glTF's falloff
    std::string cutoff = "hard";       // --cutoff hard|stochastic|none
    bool bloom = false;
    float bloomThreshold = BloomSettings{}.threshold;
    float bloomStrength = BloomSettings{}.strength;
    float driftSpeed = 0.5f;
    std::string backend = "auto";
    bool glDebug = false;
    bool verbose = false;
    bool time = false;
};

void addFrameOptions(CLI::App& command, FrameOptions& options);

// --brdf, --light-cutoff and --cutoff, validated (std::invalid_argument, one line naming the flag).
LightModel parseLightModel(const FrameOptions& options);
// Refuses --cutoff none with a clustered method (std::invalid_argument): render, bench and the view's panel.
void checkCutoffForMethod(const LightModel& model, MethodKind method);

// What a frame of `scene` looks like by default under `brdf`: a built-in scene's lights are the
// seeds' unitless ones, so under GGX, whose Lambert divides by pi, its fixed exposure is pi and
// its ambient fill (no 1/pi under either BRDF) a pi-th, and it looks as it did under Blinn-Phong
// (unitlessLightExposure). A file's lights have units: the ambient as it is, automatic exposure.
struct SceneLook {
    float ambient = FrameSettings{}.ambient;
    std::optional<float> exposureStops;  // fixed EV; none: automatic
};
SceneLook defaultLook(const std::string& scene, Brdf brdf);

// --lights as given, else its default for a scene: 0 where the scene brings lights of its own
// (and --scene-lights is on), 1024 otherwise.
long long generatedLightCount(const FrameOptions& options, const Scene& scene);
// --light-radius resolved for the scene and the generated light count.
float lightRadiusFor(const FrameOptions& options, const Scene& scene);
// --light-placement as given, else its default for the scene.
LightPlacement lightPlacementFor(const FrameOptions& options);
// The scene's own lights followed by the generated ones, or a --lights-file's set alone.
std::vector<Light> frameLights(const FrameOptions& options, const Scene& scene);

// Everything a frame needs, validated. Built on the CPU only.
struct PreparedFrame {
    Scene scene;
    std::vector<Light> lights;
    FrameSettings settings;
    std::uint32_t frameIndex = 0;
    LightPlacement lightPlacement = LightPlacement::Volume;  // of the generated lights, as chosen
    std::optional<CameraOrbit> orbit;  // --camera orbit:...; settings.camera is its pose at frameIndex
    // The defaults chosen for a scene file (camera, light placement, exposure), one line each,
    // printed by render and view so a first try says what it did.
    std::vector<std::string> notes;
    ContextOptions context;
    std::vector<std::string> warnings;
};

// Throws std::invalid_argument or SceneError with one line naming the culprit. `loaded`, when
// given, is options.scene already loaded (bench reuses one scene across many frames).
PreparedFrame prepareFrame(const FrameOptions& options, const Scene* loaded = nullptr);

// True for atrium, plane, boxes: scenes whose defaults (view, light placement, exposure) are their own.
bool isBuiltinScene(const std::string& scene);

struct ExposureSpec {
    bool automatic = false;
    float stops = 0.0f;  // fixed: EV; automatic: a compensation on top of the measured exposure (0)
};
// "auto" or a number of stops in [-24, 24]; throws std::invalid_argument naming --exposure.
ExposureSpec parseExposure(const std::string& text);

// Parses "WxH"; throws std::invalid_argument.
void parseSize(const std::string& text, int& width, int& height);

}  // namespace ml::app
