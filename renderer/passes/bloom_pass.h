// Bloom (--bloom), after shading and before the tonemap, the same for every method:
//
//   hdr (W x H) ──bloom.bright-pass──> half (W/2 x H/2): mean of each 2x2 block of
//                                      max(luminance - threshold, 0) / luminance * colour
//               ──bloom.blur-h, bloom.blur-v──> separable Gaussian, ML_BLOOM_RADIUS taps each side
//               ──bloom.composite──> hdr += strength * bilinear(half) at each pixel centre
//
// All compute; the bilinear upsample is done by hand (texel fetches, float weights) so the CPU
// reference (renderer/reference/bloom_reference.h) can follow it exactly.
#pragma once

#include <array>

#include "renderer/frame_targets.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/pass_timer.h"
#include "glsl/include/bindings.h"

namespace ml {

struct BloomSettings {
    bool enabled = false;
    float threshold = 1.0f;  // linear luminance above which a pixel blooms (before exposure)
    float strength = 0.5f;   // how much of the blurred bright part is added back
};

// Gaussian weights, centre first (w[0..ML_BLOOM_RADIUS]); the whole kernel sums to 1.
std::array<float, ML_BLOOM_RADIUS + 1> bloomKernel();

class BloomPass {
public:
    BloomPass();
    // Adds the bloom of targets.hdr() into it. Does nothing unless settings.enabled.
    void run(const FrameTargets& targets, const BloomSettings& settings, PassTimer& timer);
    // Bytes of the two half-resolution RGBA32F images (0 until bloom first runs).
    std::size_t bytes() const;

private:
    void prepare(int width, int height);

    gl::Program bright_, blur_, composite_;
    int width_ = 0, height_ = 0;
    gl::Texture2D half_[2];
};

}  // namespace ml
