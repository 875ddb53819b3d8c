#include "app/bench/raster_floors_command.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <memory>

#include "app/bench/camera_sets.h"
#include "app/frame_options.h"
#include "app/offscreen_session.h"
#include "app/bench/sample_spread.h"
#include "app/bench/sm_clock.h"
#include "renderer/frame_renderer.h"
#include "renderer/gl/debug_output.h"
#include "renderer/passes/overdraw_pass.h"
#include "renderer/passes/raster_floors.h"

namespace ml::app {

namespace {

struct RasterFloorsOptions {
    FrameOptions frame;
    int warmup = 5;
    int timedFrames = 30;
    std::string out;  // CSV; empty: stdout
};

// --camera's ';'-separated list, named sets expanded.
std::vector<std::string> cameraList(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find(';', start);
        if (end == std::string::npos) end = text.size();
        const std::string item = text.substr(start, end - start);
        start = end + 1;
        if (const auto set = namedCameraSet(item)) out.insert(out.end(), set->begin(), set->end());
        else out.push_back(item);
    }
    for (std::string& camera : out)
        if (camera == "default") camera.clear();  // FrameOptions' spelling of the scene's view
    return out;
}

int runRasterFloors(const RasterFloorsOptions& o) {
    const std::vector<std::string> cameras = cameraList(o.frame.camera);
    FrameOptions first = o.frame;
    first.camera = cameras.front();
    PreparedFrame frame = prepareFrame(first);
    OffscreenSession session = openOffscreen(first, frame);
    std::FILE* out = o.out.empty() ? stdout : std::fopen(o.out.c_str(), "w");
    if (!out) throw std::runtime_error(o.out + ": cannot write");
    std::fprintf(out, "scene,detail,triangle_order,camera,width,height,triangles,draw_calls,covered_pixels,fragments_per_covered_pixel,probe,ms,ms_p10,ms_p90,"
                      "sm_clock_mhz,renderer\n");

    FrameSettings settings = frame.settings;
    settings.method.kind = MethodKind::Visibility;
    FrameRenderer renderer(frame.scene, frame.lights, settings);
    RasterFloors floors(renderer.scene().materialFeatures());
    OverdrawPass overdraw(renderer.scene().materialFeatures());
    for (const std::string& camera : cameras) {
        FrameOptions options = o.frame;
        options.camera = camera;
        const PreparedFrame posed = prepareFrame(options, &frame.scene);
        renderer.setCamera(posed.settings.camera);
        renderer.render(options.frames);  // uploads the camera's frame uniforms, which stay bound
        PassTimer noTimer;
        overdraw.run(renderer.scene(), renderer.targets(), noTimer);
        const OverdrawStatistics od = overdrawStatistics(overdraw.readCounts());

        PassTimer timer(true, session.info.software ? TimingClock::WallClockAfterFinish : TimingClock::GpuQueries);
        const FrameContext ctx = renderer.frameContext(timer);
        std::map<std::string, std::vector<double>> samples;
        SmClockSampler clockSampler;  // read while the timed frames run (app/bench/sm_clock.h)
        for (int i = 0; i < o.warmup + o.timedFrames; ++i) {
            if (i == o.warmup && !session.info.software) clockSampler.start();
            timer.beginFrame();
            for (const RasterFloors::Probe probe : RasterFloors::probes()) {
                if (!floors.supports(probe)) continue;
                auto pass = timer.pass(RasterFloors::name(probe));
                floors.run(probe, ctx);
            }
            const std::vector<PassTime> times = timer.endFrame();
            if (i >= o.warmup)
                for (const PassTime& t : times) samples[t.name].push_back(t.milliseconds);
        }
        const std::optional<SmClockReading> reading = clockSampler.stop();  // nullopt where never started
        const std::string clock = reading ? std::to_string(reading->medianMhz) : "";
        // Each probe, then the compute raster's own steps (timed inside it) as scene-compute.STEP.
        std::vector<std::pair<std::string, std::string>> rows;  // (probe column, sample name)
        for (const RasterFloors::Probe probe : RasterFloors::probes())
            if (floors.supports(probe)) rows.emplace_back(RasterFloors::name(probe), RasterFloors::name(probe));
        const std::string stepPrefix = "visibility.raster-";
        for (const auto& [name, times] : samples)
            if (name.starts_with(stepPrefix)) rows.emplace_back(std::string("scene-compute.") + name.substr(stepPrefix.size()), name);
        for (const auto& [probe, sampleName] : rows) {
            const SampleSpread s = spreadOf(samples[sampleName]);
            std::fprintf(out, "%s,%g,%s,\"%s\",%d,%d,%zu,%zu,%zu,%.4f,%s,%.4f,%.4f,%.4f,%s,\"%s\"\n", frame.scene.name.c_str(),
                         o.frame.detail, triangleOrderName(settings.triangleOrder),
                         camera.empty() ? "default" : camera.c_str(), settings.width, settings.height,
                         renderer.scene().triangleCount(), renderer.scene().drawCallsPerPass(), od.coveredPixels,
                         od.meanPerCoveredPixel(), probe.c_str(), s.median, s.p10, s.p90,
                         clock.c_str(), session.info.renderer.c_str());
        }
        std::fflush(out);
    }
    if (out != stdout) std::fclose(out);
    if (gl::debugErrorCount() > 0) {
        std::fprintf(stderr, "error: %d GL error(s); last: %s\n", gl::debugErrorCount(), gl::lastDebugError().c_str());
        return 1;
    }
    return 0;
}

}  // namespace

void addRasterFloorsCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RasterFloorsOptions>();
    options->frame.size = "2560x1440";
    CLI::App* cmd = app.add_subcommand("raster-floors",
                                       "time the visibility raster's floors (clears, a full-screen triangle, the scene with depth "
                                       "alone and without rasterization, the compute raster and its steps) and count its overdraw, "
                                       "per camera, as CSV");
    addFrameOptions(*cmd, options->frame);
    cmd->get_option("--camera")->description("cameras separated by ';' (px,py,pz,tx,ty,tz,fovy_deg or default), or a named "
                                             "set: " + cameraSetNames());
    cmd->add_option("--warmup", options->warmup, "untimed rounds of every probe per camera")->capture_default_str();
    cmd->add_option("--timed-frames", options->timedFrames, "timed rounds per camera (median, p10, p90)")->capture_default_str();
    cmd->add_option("--csv", options->out, "write the CSV here instead of stdout");
    cmd->callback([options, &exitCode] { exitCode = runRasterFloors(*options); });
}

}  // namespace ml::app
