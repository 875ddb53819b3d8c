// The light set on the GPU: the lights at time 0, and the animated copy every method shades with.
#pragma once

#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/light_set.h"

namespace ml {

class LightBuffers {
public:
    explicit LightBuffers(const std::vector<PointLight>& lights);

    std::uint32_t count() const { return count_; }
    const gl::Buffer& base() const { return base_; }
    const gl::Buffer& animated() const { return animated_; }
    // 32 bytes per light in each of the two buffers.
    std::size_t bytes() const { return base_.size() + animated_.size(); }

    // Reads back the animated lights (for --save-lights and the tests' CPU references).
    std::vector<PointLight> downloadAnimated() const;

private:
    std::uint32_t count_ = 0;
    gl::Buffer base_;
    gl::Buffer animated_;
};

// glsl/animate_lights.comp: writes LightBuffers::animated() for a point in time.
class AnimateLightsPass {
public:
    AnimateLightsPass();
    void run(const LightBuffers& lights, float time, const LightAnimation& animation) const;

private:
    gl::Program program_;
};

}  // namespace ml
