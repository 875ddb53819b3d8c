// --view overdraw: how many fragments per pixel the scene's raster passes shade. The scene is
// drawn as the visibility raster and the depth pre-pass draw it (the same ranges, order,
// back-face culling and alpha test; LESS with depth writes), and each fragment that passes the
// depth test at its turn adds 1 to its pixel (additive blending into an R32F target). Opaque
// ranges keep early depth testing, so the count is the fragment-shader work those passes pay;
// 1 on every covered pixel is the floor a perfect front-to-back order would reach.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/frame_targets.h"
#include "renderer/frame_targets_stamp.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/pass_timer.h"
#include "renderer/scene/raster_program.h"
#include "renderer/scene/scene_gpu.h"

namespace ml {

// The view counts each pixel's fragments into a one-sample target over the frame's depth, which
// --msaa makes multisampled: refused by name rather than left to an incomplete framebuffer.
inline constexpr const char* kOverdrawRefusesMsaa = "--view overdraw counts fragments per pixel, not per sample: drop --msaa";

// What a count image says: pixels covered, fragments shaded over them, the most on one pixel.
struct OverdrawStatistics {
    std::size_t coveredPixels = 0;
    std::uint64_t fragments = 0;
    std::uint32_t maxPerPixel = 0;
    double meanPerCoveredPixel() const { return coveredPixels ? double(fragments) / double(coveredPixels) : 0.0; }
};
OverdrawStatistics overdrawStatistics(const std::vector<std::uint32_t>& counts);

class OverdrawPass {
public:
    explicit OverdrawPass(std::uint32_t materialFeatures);

    // Counts into its own target (the frame's depth is overwritten), then writes the counts'
    // colours into targets.hdr (a debug view's colours: tonemap them as such).
    void run(const SceneGpu& scene, const FrameTargets& targets, PassTimer& timer);

    // The last run's fragment counts, top row first (width x height of the targets).
    std::vector<std::uint32_t> readCounts() const;

private:
    void prepareTargets(const FrameTargets& targets);

    RasterProgram countProgram_;
    gl::Program colorProgram_;
    gl::Texture2D counts_;  // R32F: exact up to 2^24 fragments a pixel
    gl::Framebuffer fbo_;
    FrameTargetsStamp stamp_;
};

}  // namespace ml
