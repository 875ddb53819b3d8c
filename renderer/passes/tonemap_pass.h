// glsl/tonemap.comp: linear HDR -> 8-bit sRGB, the image written to PNG and shown in the window.
#pragma once

#include "renderer/frame_targets.h"
#include "renderer/gl/program.h"

namespace ml {

class TonemapPass {
public:
    TonemapPass();
    // displayColors: the HDR target holds a debug view's colours, shown without the curve.
    void run(const FrameTargets& targets, float exposure, bool displayColors = false) const;

private:
    gl::Program program_;
};

}  // namespace ml
