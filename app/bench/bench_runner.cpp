#include "app/bench/bench_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "app/camera_track.h"
#include "app/bench/sample_spread.h"
#include "app/bench/sm_clock.h"
#include "renderer/methods/visibility_buffer.h"
#include "renderer/clustering/clustered_lighting.h"
#include "renderer/clustering/cull_accuracy.h"
#include "renderer/context/gl_context.h"
#include "renderer/gl/debug_output.h"
#include "renderer/gl/gl_api.h"
#include "renderer/frame_accumulation.h"
#include "renderer/image/image_compare.h"
#include "renderer/lights/light_set.h"
#include "renderer/reference/tonemap_reference.h"
#include "scenes/scene_library.h"

namespace ml::app {

namespace {

// Enough for a handful of 2560x1440 references (59 MB each); points are ordered so that the
// ones sharing a reference run one after another, so the cache rarely needs more than one.
constexpr std::size_t kReferenceCacheBytes = std::size_t{1} << 30;
constexpr double kPhysicalBudgetScale = 10.0;
constexpr std::size_t kSupersampledReferenceBytes = std::size_t{4} << 30;  // two 2560x1440 references at K = 4
// --shadows sampled's accuracy frame is reached through this many frames, its history theirs.
constexpr std::uint32_t kSampledHistoryFrames = 16;

std::string scientific(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// Everything that makes two points render the same frame with the same lights: the renderer
// (scene upload, light buffers, targets) and the naive reference are shared under this key.
std::string frameKeyOf(const FrameOptions& o, double radius) {
    nlohmann::json k;
    k["scene"] = o.scene;
    k["detail"] = o.detail;
    k["camera"] = o.camera;
    k["near"] = o.nearPlane ? nlohmann::json(*o.nearPlane) : nlohmann::json();
    k["far"] = o.farPlane ? nlohmann::json(*o.farPlane) : nlohmann::json();
    k["size"] = o.size;
    k["lights"] = o.lights ? nlohmann::json(*o.lights) : nlohmann::json();
    k["spot_share"] = o.spotShare;
    k["spot_angle"] = o.spotAngle;
    k["scene_lights"] = o.sceneLights;
    k["radius"] = radius;
    k["seed"] = o.seed;
    k["light_placement"] = o.lightPlacement;
    k["intensity"] = o.lightIntensity;
    k["drift"] = o.driftSpeed;
    k["exposure"] = o.exposure;
    k["specular"] = o.specular;  // the naive reference must shade with the same model
    k["brdf"] = o.brdf;
    k["material_variant"] = o.materialVariant;  // the materials drawn
    k["shadows"] = o.shadows;  // naive traces the same rays
    // The renderer builds its occluders and programs for these (naive's frame is the same for all).
    k["shadow_bvh_width"] = o.shadowBvhWidth;
    k["shadow_rays_per_pixel"] = o.shadowRaysPerPixel;
    k["shadow_reuse"] = o.shadowReuse;
    k["shadow_denoise"] = o.shadowDenoise;
    k["light_sum"] = o.lightSum;
    k["light_cutoff"] = o.lightCutoff ? nlohmann::json(*o.lightCutoff) : nlohmann::json();
    k["cutoff"] = o.cutoff;
    k["bloom"] = o.bloom;        // and get the same post-process
    k["bloom_threshold"] = o.bloomThreshold;
    k["bloom_strength"] = o.bloomStrength;
    k["backface_culling"] = o.backfaceCulling;  // and raster the same surfaces
    k["transparency"] = o.transparency;          // and blend the same ones
    k["triangle_order"] = o.triangleOrder;      // the scene's upload
    return k.dump();
}

nlohmann::json finiteOr(double v, const char* otherwise) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(otherwise);
}

void addNote(BenchRow& row, const std::string& note) {
    const std::string old = row.contains("note") && row["note"].is_string() ? row["note"].get<std::string>() : "";
    row["note"] = old.empty() ? note : old + "; " + note;
}

// The point's settings as columns; axes its method does not use stay empty.
BenchRow configColumns(const BenchPoint& p, int index, std::uint32_t frame, const RunSettings& run, TimingClock clock,
                       const GlInfo& info) {
    const FrameOptions& o = p.frame;
    BenchRow row;
    row["experiment"] = p.experiment;
    row["point"] = index;
    row["scene"] = o.scene;
    row["material_variant"] = o.materialVariant;
    row["method"] = o.method;
    row["lights"] = o.lights ? nlohmann::json(*o.lights) : nlohmann::json();
    row["spot_share"] = o.spotShare;
    row["radius"] = nullptr;  // resolved against the scene when measured
    row["radius_rule"] = p.frame.lightRadius.text();
    row["seed"] = o.seed;
    row["intensity"] = o.lightIntensity;
    row["drift_speed"] = o.driftSpeed;
    row["specular"] = o.specular;
    row["brdf"] = o.brdf;
    row["shadows"] = o.shadows;
    row["shadow_bvh_width"] = o.shadows == "off" ? nlohmann::json() : nlohmann::json(o.shadowBvhWidth);
    const bool sampled = o.shadows == "sampled";
    row["shadow_rays_per_pixel"] = sampled ? nlohmann::json(o.shadowRaysPerPixel) : nlohmann::json();
    row["shadow_reuse"] = sampled ? nlohmann::json(o.shadowReuse) : nlohmann::json();
    row["shadow_denoise"] = sampled ? nlohmann::json(o.shadowDenoise) : nlohmann::json();
    row["light_sum"] = o.lightSum;
    row["light_cutoff"] = o.lightCutoff ? nlohmann::ordered_json(*o.lightCutoff) : nlohmann::ordered_json();
    row["cutoff"] = o.cutoff;
    row["accumulate"] = p.accumulate;
    row["bloom"] = o.bloom;
    int w = 0, h = 0;
    parseSize(o.size, w, h);
    row["width"] = w;
    row["height"] = h;
    row["camera"] = o.camera.empty() ? "default" : o.camera;
    row["near"] = o.nearPlane ? nlohmann::json(*o.nearPlane) : nlohmann::json();
    row["far"] = o.farPlane ? nlohmann::json(*o.farPlane) : nlohmann::json();
    auto clustered = [&](auto v) { return p.clustered ? nlohmann::ordered_json(v) : nlohmann::ordered_json(); };
    row["tiles_x"] = clustered(o.tilesX);
    row["tiles_y"] = nullptr;
    row["slices"] = clustered(o.slices);
    row["slicing"] = clustered(o.slicing);
    row["assign"] = clustered(o.assign);
    row["max_per_cluster"] = p.capped ? nlohmann::ordered_json(o.maxPerCluster) : nlohmann::ordered_json();
    row["active_only"] = clustered(o.activeOnly);
    row["cull"] = clustered(o.cull);
    row["normal_cones"] = p.gbuffered && !p.capped ? nlohmann::ordered_json(o.normalCones) : nlohmann::ordered_json();
    row["gbuffer"] = p.gbuffered ? nlohmann::ordered_json(o.gbuffer) : nlohmann::ordered_json();
    row["prepass"] = p.prepassed ? nlohmann::ordered_json(o.prepass) : nlohmann::ordered_json();
    row["msaa"] = p.gbuffered ? nlohmann::ordered_json() : nlohmann::ordered_json(o.msaa);
    row["resolve"] = p.deferred ? nlohmann::ordered_json(o.resolve) : nlohmann::ordered_json();
    // As asked; the point's run replaces it with what ran (auto resolved for this GPU).
    row["vis_raster"] = p.visibility ? nlohmann::ordered_json(o.visRaster) : nlohmann::ordered_json();
    row["draw"] = o.draw;
    row["backface_culling"] = o.backfaceCulling;
    row["transparency"] = o.transparency;
    row["triangle_order"] = o.triangleOrder;
    row["workgroup"] = clustered(o.workgroup);
    row["frame_index"] = frame;
    row["warmup_frames"] = run.warmupFrames;
    row["timed_frames"] = run.timedFrames;
    row["clock"] = clockColumnValue(clock);
    row["sm_clock_mhz"] = nullptr;  // measured with the timed frames
    row["sm_clock_mhz_min"] = nullptr;
    row["renderer"] = info.renderer;
    return row;
}

}  // namespace

BenchRunner::BenchRunner(const RunSettings& run, const GlInfo& info)
    : run_(run),
      info_(info),
      clock_(info.software ? TimingClock::WallClockAfterFinish : TimingClock::GpuQueries),
      naiveBudget_(run.naiveBudget.value_or(info.software ? kNaiveBudgetSoftware : kNaiveBudgetGpu)),
      references_(kReferenceCacheBytes),
      supersampledReferences_(kSupersampledReferenceBytes),
      physicalReferences_(kReferenceCacheBytes) {
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize_);
}

const Scene& BenchRunner::sceneFor(const FrameOptions& o) {
    const std::string key = o.scene + "@" + std::to_string(o.detail);
    if (scene_ && key == sceneKey_) return *scene_;
    renderer_.reset();  // its GPU copy belongs to the old scene
    frameKey_.clear();
    scene_.reset();
    std::vector<std::string> warnings;
    scene_ = std::make_unique<Scene>(loadScene(SceneRequest{o.scene, o.detail}, warnings));
    for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    if (scene_->indices.empty()) throw SceneError(o.scene + ": the scene has no triangles");
    sceneKey_ = key;
    return *scene_;
}

BenchRow BenchRunner::measure(const BenchPoint& point, int index) {
    BenchRow row = configColumns(point, index, run_.firstFrame, run_, clock_, info_);
    const int errorsBefore = gl::debugErrorCount();
    try {
        measureInto(row, point);
    } catch (const GpuResetError&) {
        throw;  // the context is lost: no later point can be measured
    } catch (const std::exception& e) {
        addNote(row, std::string("error: ") + e.what());
        renderer_.reset();  // its state is unknown now; the next point builds a fresh one
        frameKey_.clear();
        ++failed_;
        return row;
    }
    if (gl::debugErrorCount() > errorsBefore) {
        addNote(row, "error: GL error: " + gl::lastDebugError());
        renderer_.reset();
        frameKey_.clear();
        ++failed_;
    }
    return row;
}

void BenchRunner::measureInto(BenchRow& row, const BenchPoint& point) {
    const std::uint32_t first = run_.firstFrame;
    FrameOptions o = point.frame;
    o.time = true;
    o.frames = first;
    const Scene& scene = sceneFor(o);
    PreparedFrame f = prepareFrame(o, &scene);
    f.settings.clock = clock_;
    const double radius = lightRadiusFor(o, scene);
    row["radius"] = o.lightCutoff ? nlohmann::ordered_json() : nlohmann::ordered_json(radius);  // a cut-off: one per light
    row["near"] = f.settings.camera.nearPlane;
    row["far"] = f.settings.camera.farPlane;

    const int w = f.settings.width, h = f.settings.height;
    if (w > maxTextureSize_ || h > maxTextureSize_)
        throw std::runtime_error("size " + o.size + " is larger than this GPU's maximum texture size " +
                                 std::to_string(maxTextureSize_));
    const double pixelLights = static_cast<double>(w) * h * static_cast<double>(f.lights.size());
    const std::string overBudget = o.size + " x " + std::to_string(f.lights.size()) + " lights = " +
                                   scientific(pixelLights) + " pixel-lights > naive budget " + scientific(naiveBudget_);
    const bool naive = f.settings.method.kind == MethodKind::Naive;
    if (naive && pixelLights > naiveBudget_) {
        addNote(row, "naive skipped: " + overBudget);
        return;
    }

    const std::string key = frameKeyOf(o, radius);
    if (!renderer_ || key != frameKey_) {
        renderer_.reset();
        renderer_ = std::make_unique<FrameRenderer>(f.scene, f.lights, f.settings);
        frameKey_ = key;
    }
    // An orbit or --camera-path moves the camera with the frame index, as in `render`; the
    // reference and the accuracy frame are taken at the first timed frame's pose. (A reused
    // renderer holds the last camera of the previous point's track.)
    const CameraTrack track = CameraTrack::fromOptions(o, f, run_.cameraPath);
    renderer_->setCamera(track.at(first));

    // The reference: naive forward on the same frame (same lights, same animation step), with
    // the point's MSAA, so the accuracy columns keep measuring the method against naive alone.
    // The exposure the tonemap applied to the frame just drawn: the fixed one, or the measured one.
    auto appliedExposure = [&] {
        const std::optional<AutoExposureReading> measured = renderer_->autoExposure();
        return measured ? measured->exposure : f.settings.exposure;
    };
    const std::string referenceKey = key + "@frame" + std::to_string(first) + "@msaa" + std::to_string(o.msaa);
    const ReferenceImages* reference = references_.find(referenceKey);
    bool referenceIsSelf = false;
    if (!naive && !reference && pixelLights <= naiveBudget_) {
        MethodSettings naiveSettings;
        naiveSettings.kind = MethodKind::Naive;
        naiveSettings.msaa = f.settings.method.msaa;
        naiveSettings.clustering.lightSum = f.settings.method.clustering.lightSum;
        renderer_->setMethod(naiveSettings);
        renderer_->render(first);
        reference = &references_.insert(referenceKey, ReferenceImages{renderer_->readHdr(), renderer_->readLdr(), appliedExposure()});
    }
    renderer_->setMethod(f.settings.method);
    // Not part of the frame key (the reference does not depend on it): set for every point.
    renderer_->setDrawSubmission(f.settings.draw);
    renderer_->render(first);  // applies it, so the scene reports its draw calls
    row["draw_calls"] = renderer_->scene().drawCallsPerPass();
    if (const auto* visibility = dynamic_cast<const VisibilityBuffer*>(&renderer_->method()))
        row["vis_raster"] = visibilityRasterName(visibility->raster());

    auto renderFrame = [&](std::uint32_t frame) {
        renderer_->setCamera(track.at(frame));
        return renderer_->render(frame);
    };

    // Warm-up: shader compilation (llvmpipe compiles on first draw) and first-use allocation.
    for (int i = 0; i < run_.warmupFrames; ++i) renderFrame(first + static_cast<std::uint32_t>(i));

    // The SM clock, read while the timed frames run (median and lowest read). Not on llvmpipe:
    // no NVIDIA clock there.
    SmClockSampler smClockSampler;
    if (!info_.software) smClockSampler.start();

    // Timed frames, the lights moving on by one animation step each.
    std::vector<double> totals, walls;
    std::vector<std::pair<std::string, std::vector<double>>> passes;
    for (int i = 0; i < run_.timedFrames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const std::vector<PassTime> times = renderFrame(first + static_cast<std::uint32_t>(i));
        glFinish();
        walls.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        totals.push_back(totalMilliseconds(times));
        for (const PassTime& t : times) {
            auto it = std::find_if(passes.begin(), passes.end(), [&](const auto& p) { return p.first == t.name; });
            if (it == passes.end()) {
                passes.emplace_back(t.name, std::vector<double>(static_cast<std::size_t>(i), 0.0));
                it = passes.end() - 1;
            }
            it->second.push_back(t.milliseconds);
        }
        for (auto& p : passes) p.second.resize(static_cast<std::size_t>(i) + 1, 0.0);  // a pass this frame skipped
    }
    checkNoGpuReset("the timed frames");
    // A pass the GPU clock gave no interval for (PassTimer: NaN) leaves the frame to the wall clock.
    const auto unknown = [](const std::vector<double>& v) { return std::any_of(v.begin(), v.end(), [](double x) { return std::isnan(x); }); };
    if (unknown(totals)) {
        totals = walls;
        addNote(row, "the GPU timer queries gave no interval for some pass (seconds long): frame_ms is the wall clock");
    }
    const std::optional<SmClockReading> smClock = smClockSampler.stop();  // nullopt where never started
    row["sm_clock_mhz"] = smClock ? nlohmann::ordered_json(smClock->medianMhz) : nlohmann::ordered_json();
    row["sm_clock_mhz_min"] = smClock ? nlohmann::ordered_json(smClock->lowestMhz) : nlohmann::ordered_json();
    const SampleSpread frame = spreadOf(totals);
    row["frame_ms"] = frame.median;
    row["frame_ms_p10"] = frame.p10;
    row["frame_ms_p90"] = frame.p90;
    row["wall_ms"] = spreadOf(walls).median;
    for (const auto& [name, samples] : passes) {
        const std::string column = passColumn(name);
        passNames_[column] = name;
        if (unknown(samples)) continue;  // left empty
        const SampleSpread s = spreadOf(samples);
        row[column] = s.median;
        row[column + "_p10"] = s.p10;
        row[column + "_p90"] = s.p90;
    }

    // Accuracy on the first timed frame, rendered again now that the timing is done. --shadows
    // sampled reuses the frames before it: its history is rebuilt from kSampledHistoryFrames
    // frames before, as a sequence that reached the frame would have it.
    const bool sampledShadows = f.settings.shadows == Shadows::Sampled;
    if (sampledShadows) {
        renderer_->resetShadowHistory();
        for (std::uint32_t frame = first > kSampledHistoryFrames ? first - kSampledHistoryFrames : 0; frame < first; ++frame) renderFrame(frame);
    }
    renderFrame(first);
    FloatImage hdr = renderer_->readHdr();
    RgbaImage ldr = renderer_->readLdr();
    if (naive && !reference) {
        reference = &references_.insert(referenceKey, ReferenceImages{std::move(hdr), std::move(ldr), appliedExposure()});
        referenceIsSelf = true;
    }
    if (reference) {
        const FloatImage& test = referenceIsSelf ? reference->hdr : hdr;
        const RgbaImage& testLdr = referenceIsSelf ? reference->ldr : ldr;
        const ImageDifference d = compareImages(test, reference->hdr);
        // With --exposure auto each frame measures its own exposure, so the 8-bit frames are
        // compared under the reference's: a hair's difference in the measurement, scaled over
        // the whole frame, is not the method's error.
        const ImageDifference d8 = f.settings.autoExposure && !referenceIsSelf
                                       ? compareImages(tonemapImage(test, reference->exposure),
                                                       tonemapImage(reference->hdr, reference->exposure))
                                       : compareImages(testLdr, reference->ldr);
        row["max_abs_err"] = d.maxAbs;
        row["rmse"] = d.rmse;
        row["psnr_db"] = finiteOr(d.psnrDb, "inf");
        row["bad_pixel_share"] = d.badPixelShare;
        row["ldr_max_abs_err"] = d8.maxAbs;
        row["ldr_psnr_db"] = finiteOr(d8.psnrDb, "inf");
        row["ldr_bad_pixel_share"] = d8.badPixelShare;
        row["reference"] = referenceIsSelf ? "self" : "naive";
    } else {
        addNote(row, "no naive reference: " + overBudget);
    }

    if (sampledShadows && !naive) compareWithExactShadows(row, scene, hdr, ldr, renderFrame);

    // What the light assignment built on that frame.
    row["dropped_lights"] = 0;
    if (const ClusteredLighting* clustering = renderer_->method().clustering()) {
        const ClusterStatistics s = clustering->statistics();
        row["tiles_y"] = s.tilesY;
        row["clusters"] = s.clusters;
        row["empty_share"] = s.emptyShare;
        row["mean_lights_per_cluster"] = s.meanLightsPerCluster;
        row["mean_lights_per_nonempty_cluster"] = s.meanLightsPerNonEmptyCluster;
        row["max_lights_per_cluster"] = s.maxLightsPerCluster;
        row["list_entries"] = s.listEntries;
        // Sampled to 200,000 references: a CPU pass, outside the timed frames.
        const CullAccuracy cull = measureCullAccuracy(*clustering, renderer_->lights().downloadAnimated(), renderer_->uniforms(), 200'000);
        row["false_positive_share"] = cull.references ? double(cull.falsePositives) / double(cull.references) : 0.0;
        row["normal_cone_pairs_removed"] = s.listsPerCluster > 1 ? nlohmann::ordered_json(s.normalConePairs - s.normalConePairsKept)
                                                                 : nlohmann::ordered_json();
        row["overflow_clusters"] = s.overflowClusters;
        row["dropped_lights"] = s.droppedReferences;
        row["active_clusters"] = s.activeOnly ? nlohmann::ordered_json(s.activeClusters) : nlohmann::ordered_json();
        row["list_bytes"] = s.listBytes;
        row["grid_bytes"] = s.gridBytes;
        if (s.zbin) {
            row["zbin_mask_bytes"] = s.zbinStats.maskBytes;
            row["zbin_lights_walked"] = s.zbinStats.meanWalkedPerPixel;
            row["zbin_lights_shaded"] = s.zbinStats.meanPassedPerPixel;
        }
    }
    // The shadow rays of that frame, counted by one more, untimed rendering, and the rate the
    // median frame implies: every pass's time counted against the rays, a floor on the traversal's.
    if (const std::optional<std::uint64_t> rays = renderer_->countShadowRays(first)) {
        row["shadow_rays"] = *rays;
        row["shadow_grays_per_s"] = frame.median > 0.0 ? nlohmann::ordered_json(double(*rays) / (frame.median * 1e6)) : nlohmann::ordered_json();
    }
    const FloatImage& pointHdr = referenceIsSelf ? reference->hdr : hdr;
    if (run_.physicalReference) {
        // The accumulated mean first, with the point's renderer; the reference has a renderer of its own.
        const FloatImage mean = point.accumulate > 1 ? renderAccumulated(*renderer_, first, static_cast<std::uint32_t>(point.accumulate))
                                                     : FloatImage{};
        compareWithPhysical(row, f, o, point.accumulate > 1 ? mean : pointHdr);
    }
    // Last: it renders with a renderer of its own.
    if (run_.supersampledReference > 0) compareWithSupersampled(row, f, key, pointHdr);
    row["gbuffer_bytes"] = renderer_->method().extraTargetBytes();
    row["target_bytes"] = renderer_->targets().bytes();
    row["light_bytes"] = renderer_->lights().bytes();
}

void BenchRunner::compareWithExactShadows(BenchRow& row, const Scene& scene, const FloatImage& hdr, const RgbaImage& ldr,
                                          const std::function<std::vector<PassTime>(std::uint32_t)>& renderFrame) {
    const std::uint32_t first = run_.firstFrame;
    // Frame to frame: the next frame, its history this one's (noise alone where the lights and camera are still).
    renderFrame(first + 1);
    const ImageDifference next = compareImages(renderer_->readHdr(), hdr), next8 = compareImages(renderer_->readLdr(), ldr);
    row["shadow_flicker_psnr_db"] = finiteOr(next.psnrDb, "inf");
    row["shadow_flicker_ldr_share"] = next8.badPixelShare;
    // The exact shadows of the same frame: the same renderer tracing a ray per pixel and light.
    renderer_->setShadows(Shadows::Rays, scene);
    renderFrame(first);
    const FloatImage exactHdr = renderer_->readHdr();
    const RgbaImage exactLdr = renderer_->readLdr();
    renderer_->setShadows(Shadows::Sampled, scene);
    renderFrame(first);  // the rebuilt method's buffers exist once it has drawn (the statistics read them)
    const ImageDifference d = compareImages(hdr, exactHdr), d8 = compareImages(ldr, exactLdr);
    row["shadow_max_abs_err"] = d.maxAbs;
    row["shadow_rmse"] = d.rmse;
    row["shadow_psnr_db"] = finiteOr(d.psnrDb, "inf");
    row["shadow_ldr_max_abs_err"] = d8.maxAbs;
    row["shadow_ldr_bad_pixel_share"] = d8.badPixelShare;
}

void BenchRunner::compareWithSupersampled(BenchRow& row, const PreparedFrame& f, const std::string& frameKey,
                                          const FloatImage& hdr) {
    const int k = run_.supersampledReference;
    row["aa_reference"] = referenceSettingName(k);
    const double pixelLights = static_cast<double>(f.settings.width) * f.settings.height * k * k * static_cast<double>(f.lights.size());
    if (pixelLights > naiveBudget_) {
        addNote(row, "no supersampled reference: " + scientific(pixelLights) + " pixel-lights > naive budget " + scientific(naiveBudget_));
        return;
    }
    const std::string key = frameKey + "@frame" + std::to_string(run_.firstFrame) + "@supersampled" + std::to_string(k);
    const ReferenceImages* reference = supersampledReferences_.find(key);
    if (!reference) {
        // A renderer of its own: the targets are K x K times the frame's, needed for one frame.
        FrameSettings settings = f.settings;
        settings.method = MethodSettings{};
        settings.supersample = k;
        settings.timing = false;
        try {
            FrameRenderer supersampled(f.scene, f.lights, settings);
            supersampled.render(run_.firstFrame);
            reference = &supersampledReferences_.insert(key, ReferenceImages{supersampled.readHdr(), supersampled.readLdr()});
        } catch (const std::invalid_argument& e) {  // a size past the GPU's texture limit
            addNote(row, std::string("no supersampled reference: ") + e.what());
            return;
        }
    }
    const ImageDifference d = compareImages(hdr, reference->hdr);
    row["aa_rmse"] = d.rmse;
    row["aa_psnr_db"] = finiteOr(d.psnrDb, "inf");
}

void BenchRunner::compareWithPhysical(BenchRow& row, const PreparedFrame& f, const FrameOptions& o, const FloatImage& hdr) {
    // Rendered once per frame for every cut-off and drawn in bands (naive_forward.h), so it may
    // cost kPhysicalBudgetScale naive frames.
    const double pixelLights = static_cast<double>(f.settings.width) * f.settings.height * static_cast<double>(f.lights.size());
    const double budget = kPhysicalBudgetScale * naiveBudget_;
    if (pixelLights > budget) {
        addNote(row, "no physical reference: " + scientific(pixelLights) + " pixel-lights > " + scientific(budget) +
                         " (10 x the naive budget)");
        return;
    }
    // Radii and cut-offs do not matter to it: every light reaches everywhere.
    FrameOptions untruncated = o;
    untruncated.lightCutoff.reset();
    untruncated.cutoff = "none";
    const std::string key = frameKeyOf(untruncated, 0.0) + "@frame" + std::to_string(run_.firstFrame) + "@physical";
    const ReferenceImages* reference = physicalReferences_.find(key);
    if (!reference) {
        FrameSettings settings = f.settings;
        settings.method = MethodSettings{};
        settings.supersample = 1;
        settings.timing = false;
        settings.lightModel.falloff = Falloff::Untruncated;
        FrameRenderer physical(f.scene, f.lights, settings);
        physical.render(run_.firstFrame);
        checkNoGpuReset("the physical reference");
        FloatImage referenceHdr = physical.readHdr();
        RgbaImage referenceLdr = tonemapImage(referenceHdr, settings.exposure);
        reference = &physicalReferences_.insert(key, ReferenceImages{std::move(referenceHdr), std::move(referenceLdr)});
    }
    const ImageDifference d = compareImages(hdr, reference->hdr);
    const ImageDifference d8 = compareImages(tonemapImage(hdr, f.settings.exposure), reference->ldr);
    row["physical_max_abs_err"] = d.maxAbs;
    row["physical_rmse"] = d.rmse;
    row["physical_psnr_db"] = finiteOr(d.psnrDb, "inf");
    row["physical_ldr_max_abs_err"] = d8.maxAbs;
    row["physical_ldr_psnr_db"] = finiteOr(d8.psnrDb, "inf");
    row["physical_ldr_bad_pixel_share"] = d8.badPixelShare;
    if (f.settings.bloom.enabled) addNote(row, "physical_ldr_* compare without bloom (the CPU tonemap has none)");
}

std::string describeResult(const BenchRow& row) {
    std::string s;
    char buf[160];
    if (row.contains("frame_ms") && row.at("frame_ms").is_number()) {
        std::snprintf(buf, sizeof buf, "%.3f ms (p10 %.3f, p90 %.3f)", row.at("frame_ms").get<double>(),
                      row.at("frame_ms_p10").get<double>(), row.at("frame_ms_p90").get<double>());
        s += buf;
        if (row.contains("psnr_db") && row.at("psnr_db").is_number()) {
            std::snprintf(buf, sizeof buf, ", PSNR %.1f dB", row.at("psnr_db").get<double>());
            s += buf;
        } else if (row.contains("psnr_db") && row.at("psnr_db").is_string()) {
            s += ", identical to the reference";
        }
        if (row.contains("dropped_lights") && row.at("dropped_lights").is_number() && row.at("dropped_lights").get<double>() > 0)
            s += ", " + row.at("dropped_lights").dump() + " light references dropped";
    }
    if (row.contains("note") && row.at("note").is_string()) s += (s.empty() ? "" : " ") + ("[" + row.at("note").get<std::string>() + "]");
    return s;
}

}  // namespace ml::app
