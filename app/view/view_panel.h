// The view's Dear ImGui panel: the controls, which edit a ViewSettings, and the statistics block
// (frame time and its graph, per-pass GPU times, cluster statistics, memory, GL renderer).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "renderer/passes/bloom_pass.h"
#include "renderer/camera/camera_controller.h"
#include "renderer/clustering/cluster_statistics.h"
#include "renderer/lights/light_model.h"
#include "renderer/methods/shading_method.h"
#include "renderer/pass_timer.h"

namespace ml::app {

// What the user can change while the view runs. Starts from the command line's flags.
struct ViewSettings {
    // As chosen: a debug view stays selected while naive (which has none) is shown.
    MethodSettings method;
    int lightCount = 1024;        // generated lights
    float lightRadius = 1.0f;
    float spotShare = 0.0f;       // share of generated lights that are spots
    float spotAngle = 0.0f;       // their outer cone angle in degrees; 0: each in [20, 60]
    bool sceneLights = true;      // the scene file's own lights
    // The light model (--brdf, --cutoff, --light-cutoff). Falloff::Smooth: radii from the radius
    // slider; Gltf (hard) and Stochastic: every radius from the cut-off E; Untruncated: naive only.
    Brdf brdf = Brdf::Ggx;
    Falloff falloff = Falloff::Smooth;
    float lightCutoff = 0.01f;    // E, kept while the falloff does not use it
    bool animate = true;
    float animationSpeed = 1.0f;  // times real time
    float exposureStops = 0.0f;   // EV: fixed, or on top of the automatic exposure
    bool autoExposure = false;    // from the frame's log-average luminance, settling over about a second
    DrawSubmission draw = DrawSubmission::Direct;
    bool backfaceCulling = true;
    bool transparency = true;     // draw the scene's BLEND surfaces
    bool specular = true;
    BloomSettings bloom;
    bool vsync = true;
    float renderScale = 1.0f;  // the renderer's size over the window's (app/view/render_scale.h)
    CameraMode cameraMode = CameraMode::Fly;
    int sceneCamera = -1;  // the scene file's camera last chosen (Scene::cameras), -1: free camera
    int materialVariant = 0;  // 0: the file's own materials, i + 1: its KHR_materials_variants variant i
    std::array<char, 1024> openPath{};  // the panel's path field: a .gltf/.glb to open
};

// The largest light count the slider offers.
inline constexpr int kMaxViewLights = 1'000'000;

// What the statistics block shows; gathered by the view each frame.
struct ViewStatistics {
    double frameMilliseconds = 0.0;          // mean wall-clock time between frames
    std::vector<float> frameGraph;           // recent frame times, oldest first
    std::vector<PassTime> passes;            // mean per pass over recent frames
    TimingClock clock = TimingClock::GpuQueries;
    std::optional<ClusterStatistics> clusters;  // clustered methods; refreshed a few times a second
    std::size_t rendererBytes = 0;           // the renderer's buffers and targets
    std::optional<GBufferFormat> gbuffer;    // the layout, where the method has a G-buffer
    std::size_t gbufferPixelBytes = 0;       // what it stores a pixel for this scene's materials
    std::optional<std::size_t> gpuUsedBytes; // the whole GPU, where GL_NVX_gpu_memory_info says
    std::string glRenderer, glVersion;
    int width = 0, height = 0;                // the renderer's (the window's times the render scale)
    std::string renderScaleNote;             // why the scale is what it is, when chosen automatically
    std::string shadows;                     // --shadows rays or sampled (with its rays a pixel and the passes' share); empty when off
    std::size_t lights = 0;
    bool lightsFromFile = false;
    std::size_t sceneLights = 0;             // lights the scene file brings (KHR_lights_punctual)
    std::size_t transparentRanges = 0;       // the scene's BLEND draw ranges
    float sceneSize = 1.0f;                  // bounds' diagonal: the radius slider's scale
    float flySpeed = 0.0f;
    std::vector<std::string> sceneCameras;   // the scene file's cameras as the panel lists them
    std::vector<std::string> materialVariants;  // "default", then the file's variants; empty: it has none
    std::optional<float> autoExposureStops;  // the measured exposure in EV, while automatic
    int glErrors = 0;
    std::string error;                       // the last change that failed, and why
};

struct PanelEdits {
    bool method = false;      // method, grid, assignment, resolve or debug view
    bool lights = false;      // count, radius, falloff or cut-off E (sliders applied when let go)
    bool brdf = false;
    bool vsync = false;
    bool renderScale = false;  // applied when the slider is let go
    bool cameraMode = false;
    bool resetCamera = false;
    bool frameScene = false;   // the whole scene in view, from its front (F)
    bool openFile = false;     // open ViewSettings::openPath
    bool sceneCamera = false;  // a camera of the scene file was chosen
    bool materialVariant = false;  // another material variant was chosen
    bool screenshot = false;
};

PanelEdits drawViewPanel(ViewSettings& settings, const ViewStatistics& stats);

// The settings a FrameRenderer gets: naive shows no debug view (the tonemap would otherwise
// treat its shaded colour as a debug colour); deferred and visibility draw without MSAA.
MethodSettings effectiveMethod(const MethodSettings& chosen);

}  // namespace ml::app
