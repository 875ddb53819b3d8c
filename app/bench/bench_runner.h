// Measures the points of a sweep on one GL context: per point, warm-up frames, timed frames
// with the lights animating, one frame compared against the naive reference of the same
// frame, and the cluster statistics. The scene, the renderer and the references are reused
// between points that share them (a scene load or a naive frame can cost seconds).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "app/bench/bench_sweep.h"
#include "app/bench/bench_table.h"
#include "app/bench/reference_cache.h"
#include "renderer/frame_renderer.h"
#include "renderer/pass_timer.h"

namespace ml::app {

// Pixels x lights a naive frame may cost before it is skipped (--naive-budget): about 2 s a
// frame either way. On an H200 a full-screen fragment loop over 2560x1440 x 4096 lights took
// 333 ms (design.md); on llvmpipe with two cores, naive in the atrium (overdraw included) ran
// 320x180 x 256 lights in 3.3 s. A timed naive point costs warm-up + timed + 1 such frames.
inline constexpr double kNaiveBudgetGpu = 1e11;
inline constexpr double kNaiveBudgetSoftware = 1e7;

class BenchRunner {
public:
    // Needs a current context; `info` tells software renderers (wall-clock timing, smaller
    // naive budget) from GPUs.
    BenchRunner(const RunSettings& run, const GlInfo& info);

    // Measures one point. A failure of the point itself (a list that does not fit the GPU, a
    // GL error) does not throw: the row's note says what happened and failed() counts it.
    BenchRow measure(const BenchPoint& point, int index);

    double naiveBudget() const { return naiveBudget_; }
    TimingClock clock() const { return clock_; }
    int failed() const { return failed_; }
    // Pass column stem -> the pass's own name ("pass_forward_plus_shade_ms" -> "forward+.shade").
    const nlohmann::ordered_json& passNames() const { return passNames_; }

private:
    const Scene& sceneFor(const FrameOptions& options);
    void measureInto(BenchRow& row, const BenchPoint& point);
    // aa_rmse, aa_psnr_db: the point's HDR frame against naive at K x K samples per pixel
    // (RunSettings::supersampledReference), cached per frame as the naive reference is.
    // --shadows sampled: the frame `hdr`/`ldr` (the first timed one) against the same frame with
    // the exact shadows (--shadows rays), and against the next frame (the shadow_* columns).
    void compareWithExactShadows(BenchRow& row, const Scene& scene, const FloatImage& hdr, const RgbaImage& ldr,
                                 const std::function<std::vector<PassTime>(std::uint32_t)>& renderFrame);
    void compareWithSupersampled(BenchRow& row, const PreparedFrame& frame, const std::string& frameKey, const FloatImage& hdr);
    // physical_*: `hdr` (the point's frame, or the mean of its accumulated draws) against naive with
    // no cut-off (RunSettings::physicalReference), and the same after the CPU tonemap.
    void compareWithPhysical(BenchRow& row, const PreparedFrame& frame, const FrameOptions& options, const FloatImage& hdr);

    RunSettings run_;
    GlInfo info_;
    TimingClock clock_;
    double naiveBudget_;
    int maxTextureSize_ = 0;
    int failed_ = 0;
    nlohmann::ordered_json passNames_ = nlohmann::ordered_json::object();

    std::string sceneKey_;
    std::unique_ptr<Scene> scene_;
    std::string frameKey_;  // what renderer_ was built for
    std::unique_ptr<FrameRenderer> renderer_;
    ReferenceCache references_;
    // Supersampled references apart: 16 times a naive reference's size at K = 4, so sharing one
    // budget would evict the naive reference a comparison still holds (and themselves each point).
    ReferenceCache supersampledReferences_;
    ReferenceCache physicalReferences_;  // keyed without radius or cut-off: one per frame serves every cut-off
};

// "12.345 ms (p10 12.1, p90 13.0), PSNR 87.3 dB [note]": a measured row, for the progress output.
std::string describeResult(const BenchRow& row);

}  // namespace ml::app
