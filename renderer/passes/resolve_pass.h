// glsl/resolve_samples.comp: the methods' multisampled (--msaa) or supersampled (--supersample)
// colour averaged into FrameTargets::outputHdr(), in linear HDR, before bloom and the tonemap.
#pragma once

#include <optional>

#include "renderer/frame_targets.h"
#include "renderer/gl/program.h"

namespace ml {

class ResolvePass {
public:
    // Its row in the timing list: "msaa.resolve" or "supersample.resolve".
    static const char* passName(const TargetSampling& sampling);
    // Does nothing unless targets.sampling().resolves(). Compiles the variant on first use.
    void run(const FrameTargets& targets);

private:
    std::optional<gl::Program> program_;
    TargetSampling compiledFor_;
};

}  // namespace ml
