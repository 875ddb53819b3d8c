// One run of `manylights view`: the window, the renderer, the camera, the panel, and the frame
// loop that ties them together, interactively or scripted (--frames/--screenshot).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "app/camera_track.h"
#include "app/frame_options.h"
#include "app/view/gui_layer.h"
#include "app/view/timing_history.h"
#include "app/view/view_input.h"
#include "app/view/view_panel.h"
#include "renderer/camera/camera_controller.h"
#include "renderer/camera/camera_path.h"
#include "renderer/context/glfw_window.h"
#include "renderer/frame_renderer.h"

namespace ml::app {

struct ViewOptions {
    FrameOptions frame;
    std::string screenshot;        // the renderer's image of the last frame (as `render --out` writes it)
    std::string screenshotWindow;  // the window as shown, panel included
    std::string cameraPath;
    std::string drop;              // scripted: a file delivered through the window's drop callback before frame 1
    std::string panel;             // scripted: panel controls set before frame 1 (applyPanelScript)
    double runFor = 0.0;           // > 0: the live loop, vsync off, for this many seconds; then the frame rate, and exit
    bool noVsync = false;
    bool hidePanel = false;
    std::optional<float> renderScale;  // unset: automatic (render_scale.h)
    bool tilesGiven = false;           // --tiles-x on the command line: the automatic scale keeps it

    // Scripted: render frames up to --frames, write the screenshots, exit; user input is ignored.
    bool scripted() const { return frame.frames > 0 || !screenshot.empty() || !screenshotWindow.empty(); }
};

class ViewSession {
public:
    // Opens the window (throws ContextError when there is no display or no GL 4.5 core) and
    // builds the renderer.
    ViewSession(const ViewOptions& options, PreparedFrame frame, std::optional<CameraPath> path);
    ~ViewSession();
    ViewSession(const ViewSession&) = delete;
    ViewSession& operator=(const ViewSession&) = delete;

    // Runs until the window closes (or the script ends); returns the exit status.
    int run();

private:
    // O: --shadows off -> rays -> sampled -> off (the occluders are built the first time; the
    // statistics show the sampled passes' times: shadows.trace, shadows.temporal, shadows.denoise).
    void toggleShadows();
    void handleKeys(const std::vector<int>& keys);
    // Jumps the free camera to the scene's front framing (F, the panel's "frame").
    void frameScene();
    // Replaces the scene with a file (dropped on the window, or the panel's path field) with its
    // own default camera, lights and exposure; a file that fails leaves the scene as it was.
    void openScene(const std::string& path);
    // The panel's per-scene settings and statistics from frame_ and options_.frame.
    void adoptSceneSettings();
    Camera fitted(Camera camera) const;
    Camera interactiveCamera(double now);
    // Frame and pass times every frame; the read-backs (a GPU sync) every kStatisticsInterval,
    // or at once with `now`.
    void refreshStatistics(bool now, bool rendered);
    void drawPanel();
    void applyEdits(const PanelEdits& edits);
    // The panel's lights and light model (count, radius, spots, the file's lights, falloff, cut-off
    // E) through the frame's own rule (frameLights, parseLightModel), re-uploaded; a combination
    // that is refused leaves the lights as they were and says why.
    void applyLights();
    // The panel's BRDF; a fixed exposure and a built-in scene's ambient follow it (defaultLook),
    // so the picture keeps its brightness and only the BRDF's shape changes.
    void applyBrdf();
    // The panel's material variant (KHR_materials_variants): the draw ranges take its materials
    // and the renderer is rebuilt on the scene, whose shaders follow the materials drawn.
    void applyMaterialVariant();
    // --panel brdf=ggx|blinn-phong,cutoff=radius|hard|stochastic|none,light-cutoff=E,
    // material-variant=NAME: as if set in
    // the panel before frame 1 (scripted frames take no input). Throws std::invalid_argument.
    void applyPanelScript(const std::string& script);
    void setMethodOrExplain(const MethodSettings& method);
    // Chooses the starting render scale and says why; needs info_.
    void chooseRenderScale();
    void writeWindowScreenshot(const std::string& path, int width, int height);
    int finishScript();

    ViewOptions options_;  // a copy: opening another file changes its scene
    PreparedFrame frame_;
    // --camera-path or --camera orbit:..., followed until the user takes the camera over.
    std::optional<CameraTrack> track_;
    bool followPath_ = false;
    GlfwWindow window_;  // before everything that holds GL objects, so it is destroyed last
    GlInfo info_;
    bool nvxMemoryInfo_ = false;
    ViewInput input_;
    std::unique_ptr<ImGuiLayer> imgui_;
    std::unique_ptr<FrameRenderer> renderer_;
    CameraController controller_;

    ViewSettings settings_;
    MethodSettings workingMethod_;  // the last method that rendered; restored when a change fails
    bool showPanel_ = true;
    bool screenshotRequested_ = false;
    TimingHistory history_;
    ViewStatistics stats_;
    double lastStatistics_ = -1.0;
    double startTime_ = 0.0;
};

}  // namespace ml::app
