// Automatic exposure (--exposure auto), between the method's HDR frame and the tonemap:
//
//   hdr (W x H) ──exposure.reduce──> per 64x64 tile: (sum of log2 luminance, lit pixels);
//                                    its last workgroup: exposure = key / 2^(mean log2
//                                    luminance), blended with the previous frame's by
//                                    `adaptation` (1 in render: at once)
//
// The log-average, as engines expose (Reinhard et al. 2002's key): a frame whose lit pixels
// average to middle grey is left alone, a dim interior is brightened, a washed-out one darkened.
// Unlit pixels (the background) are left out. One compute dispatch; the exposure stays on the
// GPU (the tonemap reads it from ML_SSBO_EXPOSURE), and is read back only when asked for.
// The HDR frame, and every accuracy number measured on it, comes before exposure.
#pragma once

#include "renderer/frame_targets.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/pass_timer.h"

namespace ml {

// Middle grey: what the frame's log-average luminance is mapped to.
inline constexpr float kAutoExposureKey = 0.18f;
// The exposure stays within 2^-16 .. 2^16 (a frame of nearly nothing is not blown up without bound).
inline constexpr float kAutoExposureMaxStops = 16.0f;

struct AutoExposureReading {
    float exposure = 1.0f;    // the multiplier the tonemap applied
    float logAverage = 0.0f;  // mean log2 luminance of the lit pixels
    float litShare = 0.0f;    // lit pixels over all pixels
};

class AutoExposurePass {
public:
    AutoExposurePass();
    // Measures targets.outputHdr() and updates the exposure buffer. adaptation in (0, 1].
    void run(const FrameTargets& targets, float adaptation, PassTimer& timer);
    // Binds the exposure for the tonemap.
    void bind() const;
    // Starts over: the next frame sets the exposure at once (a new scene, a cut).
    void reset();
    // A GPU sync: for reports and tests, not every frame.
    AutoExposureReading read() const;

private:
    gl::Program reduce_;
    gl::GrowableBuffer partials_{"exposure.partials"};
    gl::Buffer exposure_;
};

}  // namespace ml
