#include "app/render_command.h"

#include <cstdio>
#include <memory>

#include "app/frame_options.h"
#include "app/offscreen_session.h"
#include "app/report.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/frame_renderer.h"
#include "renderer/gl/debug_output.h"
#include "renderer/image.h"

namespace ml::app {

namespace {

struct RenderOptions {
    FrameOptions frame;
    std::string out = "manylights.png";
    std::string outFloat;
    bool stats = false;
    std::string dumpClusters;
};

int runRender(const RenderOptions& o) {
    PreparedFrame frame = prepareFrame(o.frame);
    for (const std::string& w : frame.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    OffscreenSession session = openOffscreen(o.frame, frame);
    if (o.frame.verbose) printSceneSummary(frame);

    FrameRenderer renderer(frame.scene, frame.lights, frame.settings);
    // With --time, one untimed frame first: shader compilation and first-use allocation
    // (llvmpipe compiles shaders on their first draw) would otherwise count as pass time.
    if (o.frame.time) renderer.render(frame.frameIndex);
    const std::vector<PassTime> times = renderer.render(frame.frameIndex);
    if (o.frame.time) printPassTimes(times, frame.settings.clock);
    const ClusteredLighting* clustering = renderer.method().clustering();
    if (o.stats) {
        std::printf("scene submission: %s, %zu draw calls per textured raster pass (%zu draw ranges)\n",
                    drawSubmissionName(renderer.scene().submission()), renderer.scene().drawCallsPerPass(),
                    renderer.scene().drawRangeCount());
        printShadingOptions(frame.settings);
        if (clustering) {
            const ClusterStatistics stats = clustering->statistics();
            printClusterStatistics(stats);
            printCullAccuracy(stats, measureCullAccuracy(*clustering, renderer.lights().downloadAnimated(), renderer.uniforms()));
        }
        else std::printf("stats: naive shading builds no light lists (every fragment loops over all %zu lights)\n",
                         frame.lights.size());
    }
    if (!o.dumpClusters.empty()) {
        if (!clustering) throw std::invalid_argument("--dump-clusters: needs --method forward-plus or deferred");
        writeJsonFile(o.dumpClusters, clustering->dump(renderer.uniforms()));
    }

    if (!o.out.empty()) writePng(o.out, renderer.readLdr());
    if (!o.outFloat.empty()) writePfm(o.outFloat, renderer.readHdr());
    if (!o.frame.saveLights.empty()) saveLightsFile(o.frame.saveLights, renderer.lights().downloadAnimated());
    if (gl::debugErrorCount() > 0) {
        std::fprintf(stderr, "error: %d GL error(s); last: %s\n", gl::debugErrorCount(), gl::lastDebugError().c_str());
        return 1;
    }
    std::printf("wrote %s (%dx%d, %s, %s, %zu lights, frame %u)\n", o.out.empty() ? o.outFloat.c_str() : o.out.c_str(),
                frame.settings.width, frame.settings.height, frame.scene.name.c_str(),
                methodName(frame.settings.method.kind).c_str(), frame.lights.size(), frame.frameIndex);
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "render one frame offscreen to a PNG (EGL, or OSMesa)");
    addFrameOptions(*cmd, options->frame);
    cmd->add_option("--out", options->out, "tonemapped 8-bit sRGB PNG")->capture_default_str();
    cmd->add_option("--out-float", options->outFloat, "linear HDR before the tonemap, as PFM");
    cmd->add_flag("--stats", options->stats, "print cluster statistics (empty share, lights per cluster, overflow, memory)");
    cmd->add_option("--dump-clusters", options->dumpClusters, "write the grid and every non-empty cluster's light indices to JSON");
    cmd->callback([options, &exitCode] { exitCode = runRender(*options); });
}

}  // namespace ml::app
