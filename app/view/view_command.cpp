#include "app/view/view_command.h"

#include <cstdio>
#include <memory>

#include "app/camera_track.h"
#include "app/view/render_scale.h"
#include "app/report.h"
#include "app/view/view_session.h"

namespace ml::app {

namespace {

int runView(const ViewOptions& o) {
    // Flags and files first: a bad one is reported before a window opens.
    if (o.renderScale) validateRenderScale(*o.renderScale);
    std::optional<CameraPath> path = CameraTrack::loadPath(o.frame, o.cameraPath);
    PreparedFrame frame = prepareFrame(o.frame);
    for (const std::string& w : frame.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    printNotes(frame);
    if (o.frame.verbose) printSceneSummary(frame);

    std::unique_ptr<ViewSession> session;
    try {
        session = std::make_unique<ViewSession>(o, std::move(frame), std::move(path));
    } catch (const ContextError& e) {
        // One line: what is missing, and what to run instead.
        std::fprintf(stderr,
                     "manylights view: cannot open a window: %s; use `manylights render` instead (same flags, writes "
                     "the frame to a PNG)\n",
                     e.what());
        return 1;
    }
    return session->run();
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<ViewOptions>();
    CLI::App* cmd = app.add_subcommand("view", "show the scene in a window with live controls, statistics and debug views");
    addFrameOptions(*cmd, options->frame);
    cmd->get_option("--size")->description("window size WxH");
    cmd->get_option("--frames")->description(
        "scripted: render animation frames 1..N in the window, write the screenshots of frame N (the frame "
        "`render --frames N` writes) and exit");
    cmd->get_option("--backend")->description("unused by view (it draws into a GLFW window)");
    cmd->get_option("--time")->description("scripted: print the mean per-pass times at exit (the panel always shows them)");
    cmd->add_option("--screenshot", options->screenshot,
                    "scripted: write the renderer's image of the last frame (no panel; comparable with `render --out`)");
    cmd->add_option("--screenshot-window", options->screenshotWindow,
                    "scripted: write the window as shown, panel included");
    cmd->add_option("--camera-path", options->cameraPath,
                    "follow a JSON camera path: {\"keyframes\": [{\"frame\": 0, \"eye\": [x,y,z], \"target\": [x,y,z], "
                    "\"fovy\": deg}, ...]}, linear between keyframes")
        ->check(CLI::ExistingFile);
    cmd->add_option("--drop", options->drop,
                    "scripted: hand this file to the window's drop callback before frame 1, as if dropped on it "
                    "(the scene is replaced by it, with its own default camera, lights and exposure)");
    cmd->add_option("--panel", options->panel,
                    "scripted: set panel controls before frame 1, as if changed there: brdf=ggx|blinn-phong, "
                    "cutoff=radius|hard|stochastic|none, light-cutoff=E, light-sum=float|fixed, material-variant=NAME "
                    "(comma-separated)");
    cmd->add_option("--run-for", options->runFor,
                    "measure: run the live loop (vsync off, statistics as shown interactively) for this many seconds, "
                    "print the mean frame rate of the last 60 frames and exit")
        ->check(CLI::Range(0.1, 3600.0));
    cmd->add_flag("--no-vsync", options->noVsync, "start with vsync off");
    cmd->add_option("--render-scale", options->renderScale,
                    "draw at this fraction of the window's size, scaled up to fill it, 0.1 to 1 (default: 1, or a "
                    "scale that keeps a software GL renderer such as llvmpipe under 320x180 pixels, with 8 tiles across unless "
                    "--tiles-x is given)");
    cmd->add_flag("--hide-panel", options->hidePanel, "start with the panel hidden (F1 or H shows it)");
    cmd->callback([options, cmd, &exitCode] {
        options->tilesGiven = cmd->count("--tiles-x") > 0;
        exitCode = runView(*options);
    });
}

}  // namespace ml::app
