// glsl/tonemap.comp: linear HDR -> 8-bit sRGB, the image written to PNG and shown in the window.
#pragma once

#include "renderer/frame_targets.h"
#include "renderer/gl/program.h"
#include "renderer/passes/auto_exposure_pass.h"

namespace ml {

class TonemapPass {
public:
    TonemapPass();
    // displayColors: the HDR target holds a debug view's colours, shown without the curve.
    // autoExposure: the exposure that pass measured, times `exposure` (null: `exposure` alone).
    void run(const FrameTargets& targets, float exposure, bool displayColors = false,
             const AutoExposurePass* autoExposure = nullptr);

private:
    gl::Program program_;
    gl::Program autoExposureProgram_;  // built on first use: most built-in frames never need it
};

}  // namespace ml
