#include "app/render/render_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/camera_track.h"
#include "app/frame_options.h"
#include "app/render/frame_pattern.h"
#include "app/render/frame_range.h"
#include "app/offscreen_session.h"
#include "app/report.h"
#include "app/render/sequence_progress.h"
#include "app/render/sequence_timing.h"
#include "app/render/video_encoder.h"
#include "renderer/methods/visibility_buffer.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/frame_accumulation.h"
#include "renderer/frame_renderer.h"
#include "renderer/gl/debug_output.h"
#include "renderer/gl/gl_api.h"
#include "renderer/image/image.h"
#include "renderer/lights/surface_reach.h"
#include "renderer/reference/tonemap_reference.h"
#include "renderer/passes/glass_fragments.h"

namespace ml::app {

namespace {

struct RenderOptions {
    FrameOptions frame;
    std::string frames = "0";  // K or A..B (frame_range.h); replaces FrameOptions' numeric --frames
    std::string out = "manylights.png";
    bool outGiven = false;     // a sequence writes PNGs only when asked to
    std::string outFloat;
    bool overwrite = false;
    std::string cameraPath;
    std::string video;
    double videoFps = 30.0;
    int videoCrf = 23;
    std::string timingCsv;
    bool stats = false;
    std::string dumpClusters;
    long long accumulate = 1;  // --accumulate K: each frame is the mean of K stochastic draws
};

// The files a run writes, checked before the scene is built.
struct RenderOutputs {
    std::optional<FramePattern> png;
    std::optional<FramePattern> pfm;
};

RenderOutputs checkOutputs(const RenderOptions& o, const FrameRange& range) {
    RenderOutputs out;
    // A single frame keeps the default PNG unless a video is all that was asked for.
    const bool wantPng = o.outGiven || (!range.several() && o.video.empty());
    if (wantPng && !o.out.empty()) out.png = FramePattern::parse("--out", o.out, range.several());
    if (!o.outFloat.empty()) out.pfm = FramePattern::parse("--out-float", o.outFloat, range.several());
    if (!out.png && !out.pfm && o.video.empty() && o.timingCsv.empty())
        throw std::invalid_argument("--frames " + o.frames + ": nothing to write; give --out frame_%04d.png, --out-float, "
                                    "--video or --timing-csv");

    // Existing files: a single frame's image is replaced as it always was; a sequence, a video
    // and a timing CSV are not overwritten without --overwrite (a rerun with another range or
    // a typo would otherwise silently replace a finished clip).
    if (!o.overwrite) {
        std::vector<std::string> existing;
        auto check = [&](const std::string& path) {
            if (std::filesystem::exists(path)) existing.push_back(path);
        };
        for (const auto* pattern : {&out.png, &out.pfm})
            if (*pattern && range.several())
                for (std::uint32_t k = range.first; k <= range.last; ++k) check((*pattern)->path(k));
        if (!o.video.empty()) check(o.video);
        if (!o.timingCsv.empty()) check(o.timingCsv);
        if (!existing.empty())
            throw std::invalid_argument(existing.front() + " exists" +
                                        (existing.size() > 1 ? " (and " + std::to_string(existing.size() - 1) + " more outputs)"
                                                             : std::string()) +
                                        "; add --overwrite to replace, or write elsewhere");
    }
    if (out.png) out.png->prepareDirectory();
    if (out.pfm) out.pfm->prepareDirectory();
    if (!o.video.empty()) prepareDirectoryOf("--video " + o.video, o.video);
    if (!o.timingCsv.empty()) prepareDirectoryOf("--timing-csv " + o.timingCsv, o.timingCsv);
    return out;
}

int runRender(RenderOptions o) {
    // Flags, files and outputs first: a bad one is reported before any scene is built or GL touched.
    const FrameRange range = parseFrameRange(o.frames);
    o.frame.frames = range.first;
    const RenderOutputs outputs = checkOutputs(o, range);
    std::optional<CameraPath> path = CameraTrack::loadPath(o.frame, o.cameraPath);
    VideoSettings videoSettings{o.video, 0, 0, o.videoFps, o.videoCrf};
    if (!o.video.empty()) validateVideo(videoSettings);

    if (o.accumulate < 1 || o.accumulate > 65536)
        throw std::invalid_argument("--accumulate " + std::to_string(o.accumulate) + ": must be between 1 and 65536");
    if (o.accumulate > 1 && o.frame.bloom)
        throw std::invalid_argument("--accumulate with --bloom: the mean is tonemapped on the CPU, which has no bloom; drop one");
    PreparedFrame frame = prepareFrame(o.frame);
    for (const std::string& w : frame.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    printNotes(frame);
    const bool timing = o.frame.time || !o.timingCsv.empty();
    frame.settings.timing = timing;
    OffscreenSession session = openOffscreen(o.frame, frame);
    if (o.frame.verbose) printSceneSummary(frame);
    const CameraTrack track = CameraTrack::fromOptions(o.frame, frame, std::move(path));

    FrameRenderer renderer(frame.scene, frame.lights, frame.settings);
    // When timing, one untimed frame first: shader compilation and first-use allocation
    // (llvmpipe compiles shaders on their first draw) would otherwise count as pass time.
    if (timing) {
        renderer.setCamera(track.at(range.first));
        renderer.render(range.first);
    }
    std::unique_ptr<VideoEncoder> video;
    if (!o.video.empty()) {
        videoSettings.width = frame.settings.width;
        videoSettings.height = frame.settings.height;
        video = std::make_unique<VideoEncoder>(videoSettings);
    }
    SequenceTiming timings(frame.settings.clock);
    SequenceProgress progress(range.count());
    std::vector<PassTime> lastTimes;
    for (std::uint32_t k = range.first;; ++k) {
        const Camera camera = track.at(k);
        renderer.setCamera(camera);
        const auto start = std::chrono::steady_clock::now();
        lastTimes = renderer.render(k);
        std::optional<FloatImage> mean;
        if (o.accumulate > 1) mean = renderAccumulated(renderer, k, static_cast<std::uint32_t>(o.accumulate));
        if (timing) {
            glFinish();
            timings.add(k, camera, lastTimes,
                        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        if (outputs.png || video) {
            const RgbaImage ldr = mean ? tonemapImage(*mean, frame.settings.exposure) : renderer.readLdr();
            if (outputs.png) writePng(outputs.png->path(k), ldr);
            if (video) video->addFrame(ldr);
        }
        if (outputs.pfm) writePfm(outputs.pfm->path(k), mean ? *mean : renderer.readHdr());
        progress.frameDone(k, k - range.first + 1);
        if (k == range.last) break;
    }
    progress.done();
    if (video) video->finish();
    if (!o.timingCsv.empty()) timings.writeCsv(o.timingCsv);
    if (o.frame.time) printPassTimes(range.several() ? timings.meanPasses() : lastTimes, frame.settings.clock);

    // Statistics, cluster dumps and the light set are those of the last frame.
    const ClusteredLighting* clustering = renderer.method().clustering();
    if (o.stats) {
        std::printf("scene submission: %s, %zu draw calls per textured raster pass (%zu draw ranges)\n",
                    drawSubmissionName(renderer.scene().submission()), renderer.scene().drawCallsPerPass(),
                    renderer.scene().drawRangeCount());
        printShadingOptions(frame.settings, renderer.scene().materialFeatures());
        printShadowStructure(frame.settings.shadows, renderer.shadowRays());
        // Lights that touch no surface light nothing, yet are culled and assigned all the same.
        const SurfaceReach reach = measureSurfaceReach(frame.scene, frame.lights);
        if (reach.lights > 0)
            std::printf("lights reaching a surface: %.1f %% (%zu of %zu point and spot lights; placement %s)\n",
                        100.0 * reach.share(), reach.reaching, reach.lights, lightPlacementName(frame.lightPlacement));
        if (const auto exposure = renderer.autoExposure())
            std::printf("auto exposure: EV %+.2f (log-average luminance %.4g over %.1f %% of the pixels, to %.2f)\n",
                        std::log2(exposure->exposure), std::exp2(exposure->logAverage), 100.0 * exposure->litShare,
                        kAutoExposureKey);
        if (const GlassFragments* glass = renderer.method().transparentCapture(); glass && renderer.scene().hasTransparent())
            std::printf("transparency: %llu fragments captured at %dx%d (%zu B each, %zu B per pixel%s), %.1f MiB\n",
                        static_cast<unsigned long long>(glass->fragmentCount()), renderer.targets().width(), renderer.targets().height(),
                        GlassFragments::kBytesPerFragment, GlassFragments::kBytesPerPixel,
                        glass->hasDeepTileList() ? "; the deep tiles' split: their colours and list" : "",
                        double(glass->bytes()) / (1 << 20));
        if (const auto* visibility = dynamic_cast<const VisibilityBuffer*>(&renderer.method())) {
            if (const ComputeRaster* raster = visibility->computeRaster()) {
                const ComputeRaster::Work w = raster->lastWork();
                std::printf("compute raster (%s): %u opaque triangles; %u large (%u binned by their setup) and %u as homogeneous planes to the tile pass over %u tiles (%u of them 8x8), %u to the hardware\n",
                            visibilityRasterName(visibility->raster()), w.opaqueTriangles, w.large, w.setupBinned, w.clipped, w.tiles, w.fineTiles, w.hardware);
                if (w.alphaTested > 0)
                    std::printf("compute raster: %u alpha-tested triangles; %u large to their tile pass over %u tiles (%u of them 8x8), %u to the hardware\n",
                                w.alphaTested, w.alphaLarge, w.alphaTiles, w.alphaFineTiles, w.alphaHardware);
            } else {
                std::printf("visibility raster: hardware\n");
            }
        }
        if (const OverdrawPass* overdraw = renderer.overdraw()) {
            // The view replaced the method's frame, so no light lists were built.
            const OverdrawStatistics s = overdrawStatistics(overdraw->readCounts());
            std::printf("overdraw: %zu pixels covered, %llu fragments shaded (%.3f per covered pixel), at most %u on one pixel\n",
                        s.coveredPixels, static_cast<unsigned long long>(s.fragments), s.meanPerCoveredPixel(), s.maxPerPixel);
        } else if (clustering) {
            const ClusterStatistics stats = clustering->statistics();
            printClusterStatistics(stats);
            printCullAccuracy(stats, measureCullAccuracy(*clustering, renderer.lights().downloadAnimated(), renderer.uniforms()));
        } else {
            std::printf("stats: naive shading builds no light lists (every fragment loops over all %zu lights)\n",
                        frame.lights.size());
        }
    }
    if (!o.dumpClusters.empty()) {
        if (!clustering) throw std::invalid_argument("--dump-clusters: needs --method forward-plus or deferred");
        writeJsonFile(o.dumpClusters, clustering->dump(renderer.uniforms()));
    }
    if (!o.frame.saveLights.empty()) saveLightsFile(o.frame.saveLights, renderer.lights().downloadAnimated());
    // Last: counting renders the frame again with programs of its own, replacing the method that
    // `clustering` points into.
    if (o.stats) {
        if (const std::optional<std::uint64_t> rays = renderer.countShadowRays(range.last))
            std::printf("shadow rays: %llu in frame %u (%.2f a pixel)\n", static_cast<unsigned long long>(*rays), range.last,
                        double(*rays) / (double(frame.settings.width) * frame.settings.height));
    }
    if (gl::debugErrorCount() > 0) {
        std::fprintf(stderr, "error: %d GL error(s); last: %s\n", gl::debugErrorCount(), gl::lastDebugError().c_str());
        return 1;
    }

    const std::string what = std::to_string(frame.settings.width) + "x" + std::to_string(frame.settings.height) + ", " +
                             frame.scene.name + ", " + methodName(frame.settings.method.kind) + ", " +
                             std::to_string(frame.lights.size()) + " lights";
    for (const auto* pattern : {&outputs.png, &outputs.pfm}) {
        if (!*pattern) continue;
        if (range.several())
            std::printf("wrote %s .. %s (%s, frames %u..%u)\n", (*pattern)->path(range.first).c_str(),
                        (*pattern)->path(range.last).c_str(), what.c_str(), range.first, range.last);
        else
            std::printf("wrote %s (%s, frame %u)\n", (*pattern)->path(range.first).c_str(), what.c_str(), range.first);
    }
    if (video)
        std::printf("wrote %s (%s, frames %u..%u, %u frames at %g fps)\n", o.video.c_str(), what.c_str(), range.first,
                    range.last, range.count(), o.videoFps);
    if (!o.timingCsv.empty()) std::printf("wrote %s (%u frames, %s)\n", o.timingCsv.c_str(), range.count(),
                                          timingClockName(frame.settings.clock));
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "render a frame, or a sequence of frames, offscreen to PNG (EGL, or OSMesa)");
    addFrameOptions(*cmd, options->frame);
    // render's --frames also takes a range; the other commands keep the plain count.
    cmd->remove_option(cmd->get_option("--frames"));
    cmd->add_option("--frames", options->frames,
                    "K: animation frame K (the lights advanced K frames of 1/60 s); A..B: the sequence of frames A to B, "
                    "one file each, scene and renderer built once")
        ->capture_default_str();
    cmd->add_option("--out", options->out,
                    "tonemapped 8-bit sRGB PNG; a sequence needs a frame-number field, e.g. shots/frame_%04d.png")
        ->capture_default_str();
    cmd->add_option("--supersample", options->frame.supersample,
                    "draw at K times the size (K = 1..8) and box-filter down in linear HDR before the tonemap: with naive, "
                    "the anti-aliased reference")->capture_default_str();
    cmd->add_option("--out-float", options->outFloat, "linear HDR before the tonemap, as PFM (the same pattern rule as --out)");
    cmd->add_flag("--overwrite", options->overwrite, "replace existing files of a sequence, --video or --timing-csv");
    cmd->add_option("--camera-path", options->cameraPath,
                    "the camera follows the keyframes of a JSON camera path (the format of `view --camera-path`)");
    cmd->add_option("--video", options->video, "also encode the frames with ffmpeg: .mp4, .mkv, .mov (H.264), .webm (VP9), "
                                               ".webp (animated WebP) or .gif");
    cmd->add_option("--video-fps", options->videoFps, "frame rate of --video")->capture_default_str();
    cmd->add_option("--video-crf", options->videoCrf, "quality of --video, 0 (best, largest) to 51; WebP quality is 100 - 2 x this")
        ->capture_default_str();
    cmd->add_option("--timing-csv", options->timingCsv,
                    "per-frame camera and pass times to CSV (the bench's column names; implies timing as --time)");
    cmd->add_option("--accumulate", options->accumulate,
                    "K: each frame is the mean of K draws of --cutoff stochastic's ranges, lights and camera held still "
                    "(deterministic per --seed and frame; tonemapped on the CPU, no bloom)")->capture_default_str();
    cmd->add_flag("--stats", options->stats, "print cluster statistics (empty share, lights per cluster, overflow, memory) of the last frame");
    cmd->add_option("--dump-clusters", options->dumpClusters, "write the grid and every non-empty cluster's light indices to JSON");
    cmd->callback([options, cmd, &exitCode] {
        options->outGiven = cmd->count("--out") > 0;
        exitCode = runRender(*options);
    });
}

}  // namespace ml::app
