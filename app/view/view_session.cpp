#include "app/view/view_session.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "renderer/gl/extensions.h"
#include "renderer/gl/gl_api.h"  // before glfw3.h, which must not include GL/gl.h itself

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/material_variant_choice.h"
#include "app/view/render_scale.h"
#include "app/report.h"
#include "app/view/window_capture.h"
#include "renderer/camera/default_camera.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/gl/debug_output.h"
#include "renderer/lights/light_sum.h"

namespace ml::app {

namespace {

// GL_NVX_gpu_memory_info (NVIDIA, some Mesa drivers): sizes in KiB. glad is generated for the
// core profile only, so the two enums are spelled out here.
constexpr GLenum kGpuMemoryTotalNvx = 0x9048;
constexpr GLenum kGpuMemoryAvailableNvx = 0x9049;


// Statistics read back (a GPU sync) this often while interactive, not every frame.
constexpr double kStatisticsInterval = 0.25;
// Automatic exposure moves 63 % of the way (in stops) to the frame's own in this time.
constexpr double kExposureSettleSeconds = 0.4;
// A longer gap (a stall, a window drag) counts as this much: the camera does not leap.
constexpr double kMaxFrameSeconds = 0.5;

float diagonal(const Bounds& b) { return b.empty() ? 1.0f : glm::length(b.size()); }

}  // namespace

ViewSession::ViewSession(const ViewOptions& options, PreparedFrame frame, std::optional<CameraPath> path)
    : options_(options),
      frame_(std::move(frame)),
      track_(path || frame_.orbit ? std::optional(CameraTrack::fromOptions(options.frame, frame_, std::move(path)))
                                  : std::nullopt),
      followPath_(track_.has_value()),
      window_("manylights view", frame_.settings.width, frame_.settings.height, frame_.context),
      input_(window_.handle()),
      controller_(frame_.settings.camera, diagonal(frame_.scene.bounds)) {
    gl::enableDebugOutput(options.frame.glDebug ? gl::DebugVerbosity::All : gl::DebugVerbosity::ErrorsOnly);
    info_ = queryGlInfo();
    nvxMemoryInfo_ = gl::hasExtension("GL_NVX_gpu_memory_info");
    if (options.frame.verbose)
        std::printf("GL_RENDERER: %s\nGL_VERSION: %s\nplatform: %s\n", info_.renderer.c_str(), info_.version.c_str(),
                    window_.platform().c_str());
    imgui_ = std::make_unique<ImGuiLayer>(window_.handle());

    // The window may be given another size than asked for (a tiling window manager, HiDPI):
    // the renderer follows the framebuffer.
    int w = 0, h = 0;
    window_.framebufferSize(w, h);
    if (w > 0 && h > 0) {
        if (options.scripted() && (w != frame_.settings.width || h != frame_.settings.height))
            std::fprintf(stderr, "warning: the window is %dx%d, not the --size %dx%d asked for\n", w, h,
                         frame_.settings.width, frame_.settings.height);
        frame_.settings.width = w;
        frame_.settings.height = h;
    }
    chooseRenderScale();
    frame_.settings.width = scaledSide(frame_.settings.width, settings_.renderScale);
    frame_.settings.height = scaledSide(frame_.settings.height, settings_.renderScale);
    frame_.settings.timing = true;
    frame_.settings.clock = info_.software ? TimingClock::WallClockAfterFinish : TimingClock::GpuQueries;
    frame_.settings.readback = TimingReadback::Latest;
    settings_.method = frame_.settings.method;
    workingMethod_ = settings_.method;
    frame_.settings.method = effectiveMethod(settings_.method);
    renderer_ = std::make_unique<FrameRenderer>(frame_.scene, frame_.lights, frame_.settings);

    adoptSceneSettings();
    settings_.draw = parseDrawSubmission(options.frame.draw);
    settings_.backfaceCulling = frame_.settings.backfaceCulling;
    settings_.transparency = frame_.settings.transparency;
    settings_.specular = frame_.settings.specular;
    settings_.bloom = frame_.settings.bloom;
    settings_.vsync = !options.noVsync && !(options.runFor > 0.0);
    showPanel_ = !options.hidePanel;

    stats_.glRenderer = info_.renderer;
    stats_.glVersion = info_.version;
    stats_.clock = frame_.settings.clock;
    if (namesSceneCamera(options.frame.camera))  // checked when the frame was prepared
        settings_.sceneCamera = static_cast<int>(sceneCameraIndex(options.frame.camera, frame_.scene.cameras.size()));
}

void ViewSession::adoptSceneSettings() {
    const FrameOptions& o = options_.frame;
    const std::size_t generated =
        o.lightsFile.empty() ? static_cast<std::size_t>(generatedLightCount(o, frame_.scene)) : frame_.lights.size();
    settings_.lightCount = static_cast<int>(std::min<std::size_t>(generated, kMaxViewLights));
    settings_.spotShare = o.spotShare;
    settings_.spotAngle = o.spotAngle;
    settings_.sceneLights = o.sceneLights == "on";
    settings_.lightRadius = lightRadiusFor(o, frame_.scene);
    const LightModel& model = frame_.settings.lightModel;
    settings_.brdf = model.brdf;
    settings_.falloff = model.falloff;
    if (model.cutoff > 0.0f) settings_.lightCutoff = model.cutoff;
    settings_.exposureStops = std::log2(frame_.settings.exposure);
    settings_.autoExposure = frame_.settings.autoExposure;
    settings_.sceneCamera = -1;
    // prepareFrame has applied --material-variant, which it checked.
    const std::optional<std::size_t> variant = parseMaterialVariant(o.materialVariant, frame_.scene);
    settings_.materialVariant = variant ? static_cast<int>(*variant) + 1 : 0;
    stats_.materialVariants.clear();
    if (!frame_.scene.materialVariants.empty()) {
        stats_.materialVariants.push_back("default");
        for (const std::string& name : frame_.scene.materialVariants.names) stats_.materialVariants.push_back(name);
    }
    stats_.sceneLights = frame_.scene.lights.size();
    stats_.transparentRanges = renderer_ ? renderer_->scene().transparentRangeCount() : 0;
    stats_.lightsFromFile = !o.lightsFile.empty();
    stats_.sceneSize = diagonal(frame_.scene.bounds);
    stats_.sceneCameras.clear();
    for (std::size_t i = 0; i < frame_.scene.cameras.size(); ++i) {
        const std::string& name = frame_.scene.cameras[i].name;
        stats_.sceneCameras.push_back("gltf:" + std::to_string(i) + (name.empty() ? "" : " " + name));
    }
}

void ViewSession::openScene(const std::string& path) {
    // The file's own defaults (camera, lights, exposure), the rest of the flags and the panel's
    // method kept.
    FrameOptions o = options_.frame;
    o.scene = path;
    o.camera.clear();
    o.lightsFile.clear();
    o.lightPlacement.clear();
    o.exposure.clear();
    o.materialVariant.clear();  // another file's variants are its own
    try {
        PreparedFrame next = prepareFrame(o);
        for (const std::string& w : next.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
        std::printf("opened %s\n", path.c_str());
        printNotes(next);
        FrameSettings settings = renderer_->settings();
        settings.camera = next.settings.camera;
        settings.exposure = next.settings.exposure;
        settings.autoExposure = next.settings.autoExposure;
        settings.ambient = next.settings.ambient;
        settings.lightModel = next.settings.lightModel;
        settings.animation = next.settings.animation;
        auto renderer = std::make_unique<FrameRenderer>(next.scene, next.lights, settings);
        renderer_ = std::move(renderer);  // the old scene's GL objects go only once the new one is built
        next.settings = settings;
        frame_ = std::move(next);
        options_.frame = o;
    } catch (const std::exception& e) {
        stats_.error = "could not open " + path + ": " + e.what();
        std::fprintf(stderr, "error: %s\n", stats_.error.c_str());
        return;
    }
    track_.reset();
    followPath_ = false;
    controller_ = CameraController(frame_.settings.camera, diagonal(frame_.scene.bounds));
    controller_.setMode(settings_.cameraMode);
    adoptSceneSettings();
    stats_.error.clear();
    stats_.clusters.reset();
    lastStatistics_ = -1.0;
}

ViewSession::~ViewSession() {
    // GL objects go while the context is still current.
    renderer_.reset();
    imgui_.reset();
}

void ViewSession::chooseRenderScale() {
    if (options_.renderScale) {
        settings_.renderScale = *options_.renderScale;
        return;
    }
    // --screenshot promises render's pixels at --size: a scripted screenshot keeps full size.
    if (!info_.software || !options_.screenshot.empty()) return;
    const int w = frame_.settings.width, h = frame_.settings.height;
    settings_.renderScale = softwareRenderScale(w, h);
    if (settings_.renderScale >= 1.0f) return;
    std::string tiles;
    ClusterGridConfig& grid = frame_.settings.method.clustering.grid;
    if (!options_.tilesGiven && grid.tilesX > kSoftwareTilesX) {
        grid.tilesX = kSoftwareTilesX;
        tiles = ", " + std::to_string(kSoftwareTilesX) + " tiles across";
    }
    char note[256];
    std::snprintf(note, sizeof note, "software GL renderer: drawn at %.2f scale (%dx%d%s), scaled up to the window",
                  settings_.renderScale, scaledSide(w, settings_.renderScale), scaledSide(h, settings_.renderScale),
                  tiles.c_str());
    stats_.renderScaleNote = note;
    std::fprintf(stderr, "notice: %s (%s); --render-scale 1 for full resolution\n", note, info_.renderer.c_str());
}

Camera ViewSession::fitted(Camera camera) const {
    fitClipPlanes(camera, frame_.scene.bounds);
    if (options_.frame.nearPlane) camera.nearPlane = *options_.frame.nearPlane;
    if (options_.frame.farPlane) camera.farPlane = *options_.frame.farPlane;
    return camera;
}

Camera ViewSession::interactiveCamera(double now) {
    if (followPath_) {
        const auto frame = static_cast<std::uint32_t>((now - startTime_) / kSecondsPerFrame);
        return track_->at(frame + frame_.frameIndex);
    }
    return fitted(controller_.camera());
}

void ViewSession::toggleShadows() {
    const Shadows now = renderer_->settings().shadows;
    const Shadows next = now == Shadows::Off ? Shadows::Rays : now == Shadows::Rays ? Shadows::Sampled : Shadows::Off;
    try {
        renderer_->setShadows(next, frame_.scene);
        options_.frame.shadows = shadowsName(next);
        std::printf("shadows: %s\n", shadowsName(next));
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "shadows: %s\n", e.what());
    }
}

void ViewSession::handleKeys(const std::vector<int>& keys) {
    for (int key : keys) {
        switch (key) {
        case GLFW_KEY_1:
        case GLFW_KEY_2:
        case GLFW_KEY_3:
        case GLFW_KEY_4:
        case GLFW_KEY_5: {
            // The methods in the order the panel lists them: 1 naive, 2 Forward+, 3 deferred, ...
            const auto index = static_cast<std::size_t>(key - GLFW_KEY_1);
            if (index >= methodNames().size()) break;
            settings_.method.kind = parseMethod(methodNames()[index]);
            setMethodOrExplain(settings_.method);
            break;
        }
        case GLFW_KEY_F1:
        case GLFW_KEY_H: showPanel_ = !showPanel_; break;
        case GLFW_KEY_F12: screenshotRequested_ = true; break;
        case GLFW_KEY_R:
            followPath_ = false;
            controller_.reset();
            break;
        case GLFW_KEY_F: frameScene(); break;
        case GLFW_KEY_O: toggleShadows(); break;
        // Pauses and resumes time: the lights' drift and the file's animation clip alike.
        case GLFW_KEY_P: settings_.animate = !settings_.animate; break;
        case GLFW_KEY_C:
            settings_.cameraMode = settings_.cameraMode == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
            controller_.setMode(settings_.cameraMode);
            break;
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window_.handle(), GLFW_TRUE); break;
        default: break;
        }
    }
}

void ViewSession::frameScene() {
    // The front framing of a file without cameras (defaultCamera), whatever the scene.
    followPath_ = false;
    settings_.sceneCamera = -1;
    const float aspect = static_cast<float>(renderer_->settings().width) / static_cast<float>(renderer_->settings().height);
    controller_.jumpTo(frontFramingCamera(framedSurface(frame_.scene).sphere, aspect));
}

void ViewSession::setMethodOrExplain(const MethodSettings& method) {
    try {
        validateGridConfig(method.clustering.grid);
        checkCutoffForMethod(renderer_->settings().lightModel, method.kind);
        renderer_->setMethod(effectiveMethod(method));
        workingMethod_ = method;
        stats_.error.clear();
        stats_.clusters.reset();
        lastStatistics_ = -1.0;
    } catch (const std::exception& e) {
        stats_.error = e.what();
        settings_.method = workingMethod_;
        renderer_->setMethod(effectiveMethod(workingMethod_));
    }
}

void ViewSession::applyLights() {
    FrameOptions o = options_.frame;
    o.lightsFile.clear();
    o.lights = std::clamp(settings_.lightCount, 0, kMaxViewLights);
    o.spotShare = settings_.spotShare;
    o.spotAngle = settings_.spotAngle;
    o.sceneLights = settings_.sceneLights ? "on" : "off";
    const bool cutoff = settings_.falloff == Falloff::Gltf || settings_.falloff == Falloff::Stochastic;
    o.cutoff = settings_.falloff == Falloff::Stochastic ? "stochastic" : settings_.falloff == Falloff::Untruncated ? "none" : "hard";
    o.lightCutoff = cutoff ? std::optional(settings_.lightCutoff) : std::nullopt;
    o.lightRadius = cutoff ? RadiusSpec{} : RadiusSpec{RadiusSpec::Kind::Fixed, settings_.lightRadius};
    try {
        const LightModel model = parseLightModel(o);
        checkCutoffForMethod(model, settings_.method.kind);
        frame_.lights = frameLights(o, frame_.scene);
        toGpuSunLights(frame_.lights);
        LightModel working = renderer_->settings().lightModel;  // the BRDF is applyBrdf's
        working.falloff = model.falloff;
        working.cutoff = model.cutoff;
        renderer_->setLightModel(working);
        renderer_->setLights(frame_.lights);
        // Opening another file keeps the panel's light model.
        options_.frame.cutoff = o.cutoff;
        options_.frame.lightCutoff = o.lightCutoff;
        if (cutoff) options_.frame.lightRadius = RadiusSpec{};
        stats_.error.clear();
    } catch (const std::exception& e) {
        stats_.error = e.what();
        const LightModel& working = renderer_->settings().lightModel;
        settings_.falloff = working.falloff;
        if (working.cutoff > 0.0f) settings_.lightCutoff = working.cutoff;
        return;
    }
    stats_.lightsFromFile = false;
    lastStatistics_ = -1.0;
}

void ViewSession::applyMaterialVariant() {
    const int chosen = settings_.materialVariant;
    const std::vector<std::string>& names = frame_.scene.materialVariants.names;
    if (chosen < 0 || static_cast<std::size_t>(chosen) > names.size()) return;
    const std::optional<std::size_t> variant = chosen == 0 ? std::nullopt : std::optional<std::size_t>(chosen - 1);
    try {
        Scene scene = frame_.scene;
        ml::applyMaterialVariant(scene, variant);
        // The materials drawn decide the shaders' features, the transparent ranges and the
        // shadow casters: a new renderer on the same settings, built before the old one goes.
        renderer_ = std::make_unique<FrameRenderer>(scene, frame_.lights, renderer_->settings());
        frame_.scene = std::move(scene);
        options_.frame.materialVariant = variant ? names[*variant] : "";
        stats_.error.clear();
    } catch (const std::exception& e) {
        stats_.error = std::string("material variant: ") + e.what();
        return;
    }
    std::printf("material variant: %s\n", variant ? names[*variant].c_str() : "default");
    stats_.transparentRanges = renderer_->scene().transparentRangeCount();
    stats_.clusters.reset();
    lastStatistics_ = -1.0;
}

void ViewSession::applyBrdf() {
    LightModel model = renderer_->settings().lightModel;
    const Brdf previous = model.brdf;
    model.brdf = settings_.brdf;
    renderer_->setLightModel(model);
    renderer_->setAmbient(defaultLook(options_.frame.scene, settings_.brdf).ambient);
    // GGX's Lambert divides by pi: a fixed exposure moves with it, as a built-in scene's default does.
    if (!settings_.autoExposure)
        settings_.exposureStops += std::log2(unitlessLightExposure(settings_.brdf) / unitlessLightExposure(previous));
    options_.frame.brdf = brdfName(settings_.brdf);
}

void ViewSession::applyPanelScript(const std::string& script) {
    PanelEdits edits;
    std::size_t start = 0;
    while (start < script.size()) {
        const std::size_t comma = std::min(script.find(',', start), script.size());
        const std::string item = script.substr(start, comma - start);
        start = comma + 1;
        const std::size_t eq = item.find('=');
        const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
        if (key == "brdf") {
            settings_.brdf = parseBrdf(value);
            edits.brdf = true;
        } else if (key == "cutoff" && (value == "radius" || value == "hard" || value == "stochastic" || value == "none")) {
            settings_.falloff = value == "radius" ? Falloff::Smooth : value == "hard" ? Falloff::Gltf
                                : value == "stochastic" ? Falloff::Stochastic : Falloff::Untruncated;
            edits.lights = true;
        } else if (key == "light-cutoff") {
            FrameOptions check;
            check.lightCutoff = std::strtof(value.c_str(), nullptr);
            try {
                (void)parseLightModel(check);  // one rule for E: finite and > 0
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("--panel '" + item + "': " + e.what());
            }
            settings_.lightCutoff = *check.lightCutoff;
            edits.lights = true;
        } else if (key == "light-sum") {
            try {
                settings_.method.clustering.lightSum = parseLightSum(value);
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("--panel '" + item + "': " + e.what());
            }
            edits.method = true;
        } else if (key == "material-variant") {
            try {
                const std::optional<std::size_t> variant = parseMaterialVariant(value, frame_.scene);
                settings_.materialVariant = variant ? static_cast<int>(*variant) + 1 : 0;
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("--panel '" + item + "': " + e.what());
            }
            edits.materialVariant = true;
        } else {
            throw std::invalid_argument("--panel '" + item + "': expected brdf=ggx|blinn-phong, "
                                        "cutoff=radius|hard|stochastic|none, light-cutoff=E, light-sum=float|fixed "
                                        "or material-variant=NAME");
        }
    }
    applyEdits(edits);
    if (!stats_.error.empty()) throw std::invalid_argument("--panel " + script + ": " + stats_.error);
}

void ViewSession::applyEdits(const PanelEdits& edits) {
    if (edits.method) setMethodOrExplain(settings_.method);
    if (edits.brdf) applyBrdf();
    if (edits.lights) applyLights();
    if (edits.materialVariant) applyMaterialVariant();
    if (edits.vsync) window_.setVsync(settings_.vsync);
    if (edits.renderScale) stats_.renderScaleNote.clear();  // the user's choice now, not ours
    if (edits.cameraMode) controller_.setMode(settings_.cameraMode);
    if (edits.frameScene) frameScene();
    if (edits.openFile) openScene(settings_.openPath.data());
    if (edits.resetCamera) {
        followPath_ = false;
        controller_.reset();
        settings_.sceneCamera = -1;
    }
    // A file camera is where the free camera starts from: moving on from it is flying as usual.
    if (edits.sceneCamera && settings_.sceneCamera >= 0) {
        followPath_ = false;
        controller_.jumpTo(cameraFromSceneCamera(frame_.scene.cameras[static_cast<std::size_t>(settings_.sceneCamera)]));
    }
    if (edits.screenshot) screenshotRequested_ = true;
    renderer_->setExposure(std::exp2(settings_.exposureStops));
    renderer_->setDrawSubmission(settings_.draw);
    renderer_->setBackfaceCulling(settings_.backfaceCulling);
    renderer_->setTransparency(settings_.transparency);
    renderer_->setSpecular(settings_.specular);
    renderer_->setBloom(settings_.bloom);
}

namespace {

// "shadows: sampled, 2 rays a pixel traced in 1.20 ms, reuse and filter 0.87 ms (9.1 % of the
// frame)", from the recent frames' mean pass times (shadows.trace, then shadows.temporal and
// shadows.denoise).
std::string shadowsLine(const FrameSettings& s, const std::vector<PassTime>& passes) {
    if (s.shadows == Shadows::Off) return "";  // no line: the panel keeps its height
    std::string line = std::string("shadows: ") + shadowsName(s.shadows);
    if (s.shadows != Shadows::Sampled) return line;
    double trace = 0.0, filter = 0.0;
    for (const PassTime& p : passes) {
        if (p.name == "shadows.trace") trace += p.milliseconds;
        if (p.name == "shadows.temporal" || p.name == "shadows.denoise") filter += p.milliseconds;
    }
    const double total = totalMilliseconds(passes);
    char text[200];
    std::snprintf(text, sizeof text, ", %u rays a pixel traced in %.2f ms, reuse and filter %.2f ms (%.1f %% of the frame)",
                  s.sampledShadows.raysPerPixel, trace, filter, total > 0.0 ? 100.0 * filter / total : 0.0);
    return line + text;
}

}  // namespace

void ViewSession::refreshStatistics(bool now, bool rendered) {
    const double t = glfwGetTime();
    stats_.frameMilliseconds = history_.meanFrameMilliseconds();
    stats_.frameGraph = history_.frameGraph();
    stats_.passes = history_.meanPasses();
    stats_.shadows = shadowsLine(renderer_->settings(), stats_.passes);
    stats_.width = renderer_->settings().width;
    stats_.height = renderer_->settings().height;
    stats_.lights = renderer_->lights().count();
    stats_.flySpeed = controller_.flySpeed();
    stats_.glErrors = gl::debugErrorCount();
    // A method that has not built its lists yet has no statistics to read.
    if (!rendered || (!now && lastStatistics_ >= 0.0 && t - lastStatistics_ < kStatisticsInterval)) return;
    lastStatistics_ = t;
    if (const auto exposure = renderer_->autoExposure()) stats_.autoExposureStops = std::log2(exposure->exposure);
    else stats_.autoExposureStops.reset();
    const ClusteredLighting* clustering = renderer_->method().clustering();
    if (clustering) stats_.clusters = clustering->statistics();
    else stats_.clusters.reset();
    const MethodSettings& method = renderer_->settings().method;
    if (method.kind == MethodKind::Deferred || method.kind == MethodKind::Visibility) {
        stats_.gbuffer = method.gbuffer;
        stats_.gbufferPixelBytes = gbufferBytesPerPixel(method.gbuffer, renderer_->scene().materialFeatures());
    } else {
        stats_.gbuffer.reset();
    }
    std::size_t bytes = renderer_->scene().bytes() + renderer_->lights().bytes() + renderer_->targets().bytes() +
                        renderer_->method().extraTargetBytes() + renderer_->bloom().bytes();
    if (stats_.clusters) bytes += stats_.clusters->listBytes + stats_.clusters->gridBytes;
    stats_.rendererBytes = bytes;
    if (nvxMemoryInfo_) {
        GLint totalKiB = 0, availableKiB = 0;
        glGetIntegerv(kGpuMemoryTotalNvx, &totalKiB);
        glGetIntegerv(kGpuMemoryAvailableNvx, &availableKiB);
        stats_.gpuUsedBytes = static_cast<std::size_t>(std::max(0, totalKiB - availableKiB)) * 1024;
    }
}

void ViewSession::writeWindowScreenshot(const std::string& path, int width, int height) {
    writePng(path, readWindowPixels(width, height));
    std::printf("wrote %s (window %dx%d%s)\n", std::filesystem::absolute(path).string().c_str(), width, height,
                showPanel_ ? ", panel shown" : "");
    std::fflush(stdout);
}

int ViewSession::run() {
    const bool scripted = options_.scripted();
    // Scripted: animation frames 1..N, so the last is frame N, the frame `render --frames N` writes.
    const std::uint32_t lastFrame = frame_.frameIndex;
    std::uint32_t frameIndex = lastFrame > 0 ? 1 : 0;
    double animationTime = frame_.frameIndex * static_cast<double>(kSecondsPerFrame);
    window_.setVsync(!scripted && settings_.vsync);
    if (!options_.drop.empty()) {
        // --drop: through GLFW's drop callback, as a file dropped on the window arrives.
        const char* paths[] = {options_.drop.c_str()};
        ViewInput::onDrop(window_.handle(), 1, paths);
    }
    if (!options_.panel.empty()) applyPanelScript(options_.panel);
    startTime_ = glfwGetTime();
    double previous = startTime_;
    std::size_t framesShown = 0;

    while (!window_.shouldClose()) {
        glfwPollEvents();
        int width = 0, height = 0;
        window_.framebufferSize(width, height);
        const bool iconified = glfwGetWindowAttrib(window_.handle(), GLFW_ICONIFIED) == GLFW_TRUE;
        if (width == 0 || height == 0 || (iconified && !scripted)) {
            // Minimised (0 x 0 on some platforms, iconified on X11): nothing to show; sleep until
            // the window changes.
            glfwWaitEvents();
            previous = glfwGetTime();
            continue;
        }
        const double now = glfwGetTime();
        if (options_.runFor > 0.0 && now - startTime_ >= options_.runFor) {
            const double ms = history_.meanFrameMilliseconds();
            std::printf("view: %.1f fps (mean frame interval %.3f ms over the last %zu frames, %zu frames in %.1f s), %dx%d, %s, "
                        "%u lights\n",
                        1000.0 / ms, ms, std::min(framesShown, TimingHistory::kWindow), framesShown, now - startTime_, width,
                        height, methodName(renderer_->settings().method.kind).c_str(), renderer_->lights().count());
            if (options_.frame.time) printPassTimes(history_.meanPasses(), frame_.settings.clock);
            return 0;
        }
        // The statistics show the real interval; the camera and the animation step by at most
        // kMaxFrameSeconds.
        const double elapsed = now - previous;
        const double seconds = std::min(elapsed, kMaxFrameSeconds);
        previous = now;
        if (framesShown > 0) history_.addFrame(elapsed * 1000.0);
        const int renderWidth = scaledSide(width, settings_.renderScale);
        const int renderHeight = scaledSide(height, settings_.renderScale);
        if (renderWidth != renderer_->settings().width || renderHeight != renderer_->settings().height)
            renderer_->resize(renderWidth, renderHeight);

        const bool panelHasFocus = showPanel_ && !scripted;
        FrameInput input = input_.collect(controller_.mode(), panelHasFocus && imgui_->wantsMouse(),
                                          panelHasFocus && imgui_->wantsKeyboard());
        for (const std::string& path : input.droppedPaths) openScene(path);
        Camera camera;
        if (scripted) {
            camera = track_ ? track_->at(frameIndex) : frame_.settings.camera;
        } else {
            handleKeys(input.pressedKeys);
            if (followPath_ && !input.camera.idle()) {
                // The user takes over from wherever the path had got to.
                controller_.jumpTo(interactiveCamera(now));
                followPath_ = false;
            }
            controller_.update(input.camera, static_cast<float>(seconds));
            if (settings_.animate) animationTime += seconds * settings_.animationSpeed;
            camera = interactiveCamera(now);
        }
        renderer_->setCamera(camera);
        // Scripted frames expose as `render` does (at once); live ones settle smoothly.
        renderer_->setAutoExposure(settings_.autoExposure,
                                   scripted ? 1.0f : static_cast<float>(1.0 - std::exp(-seconds / kExposureSettleSeconds)));

        bool rendered = true;
        try {
            history_.addPasses(scripted ? renderer_->render(frameIndex)
                                        : renderer_->renderAt(static_cast<float>(animationTime)));
        } catch (const std::exception& e) {
            if (scripted) throw;
            // A setting the GPU cannot hold (e.g. capped lists over the storage limit): go back
            // to the last method that worked. The panel is still drawn (over the last good
            // frame), so a light count that is the cause can be lowered there.
            stats_.error = std::string("reverted: ") + e.what();
            settings_.method = workingMethod_;
            renderer_->setMethod(effectiveMethod(workingMethod_));
            rendered = false;
        }
        const bool lastScripted = scripted && frameIndex >= lastFrame;
        refreshStatistics(scripted, rendered);

        // The renderer's image fills the window; the panel is drawn over it.
        const int drawnWidth = renderer_->settings().width, drawnHeight = renderer_->settings().height;
        const bool scaled = drawnWidth != width || drawnHeight != height;
        glBlitNamedFramebuffer(renderer_->targets().ldrFramebuffer().id(), 0, 0, 0, drawnWidth, drawnHeight, 0, 0, width,
                               height, GL_COLOR_BUFFER_BIT, scaled ? GL_LINEAR : GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        // ImGui's backend saves and restores the current program and vertex array; after a
        // failed frame they can be a replaced method's deleted objects, which it cannot restore.
        glUseProgram(0);
        glBindVertexArray(0);
        PanelEdits edits;
        if (framesShown == 0 && showPanel_) {
            ViewSettings scratch = settings_;
            imgui_->beginFrame();
            drawViewPanel(scratch, stats_);
            imgui_->discardFrame();
        }
        imgui_->beginFrame();
        if (showPanel_) edits = drawViewPanel(settings_, stats_);
        imgui_->endFrame();

        if (screenshotRequested_ && !scripted) {
            screenshotRequested_ = false;
            try {
                writeWindowScreenshot(freeScreenshotPath(std::filesystem::current_path()).string(), width, height);
            } catch (const std::exception& e) {
                stats_.error = e.what();
            }
        }
        if (lastScripted && !options_.screenshotWindow.empty()) writeWindowScreenshot(options_.screenshotWindow, width, height);
        window_.swapBuffers();
        ++framesShown;

        if (scripted) {
            if (lastScripted) return finishScript();
            ++frameIndex;
        } else {
            applyEdits(edits);
        }
    }
    return 0;
}

int ViewSession::finishScript() {
    if (!options_.screenshot.empty()) {
        writePng(options_.screenshot, renderer_->readLdr());
        std::printf("wrote %s (%dx%d, %s, %s, %u lights, frame %u)\n", options_.screenshot.c_str(),
                    renderer_->settings().width, renderer_->settings().height, frame_.scene.name.c_str(),
                    methodName(renderer_->settings().method.kind).c_str(), renderer_->lights().count(), frame_.frameIndex);
    }
    if (!options_.frame.saveLights.empty()) saveLightsFile(options_.frame.saveLights, renderer_->lights().downloadAnimated());
    if (options_.frame.time) printPassTimes(history_.meanPasses(), frame_.settings.clock);
    if (gl::debugErrorCount() > 0) {
        std::fprintf(stderr, "error: %d GL error(s); last: %s\n", gl::debugErrorCount(), gl::lastDebugError().c_str());
        return 1;
    }
    return 0;
}

}  // namespace ml::app
