// The light set on the GPU: the clustered lights (points and spots) at time 0, the animated copy
// every method shades with, and the directional lights in a small uniform block.
#pragma once

#include <vector>

#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/gpu_types.h"
#include "renderer/lights/light_model.h"
#include "renderer/lights/light_set.h"

namespace ml {

// A light as the shaders read it: a spot's direction normalised, its angles as cosines; a point
// light's cosines are ML_POINT_LIGHT_CONE_COS. Not for directional lights.
GpuLight toGpuLight(const Light& light);
GpuLightCone toGpuLightCone(const Light& light);
// The directional lights of a set (at most ML_MAX_SUN_LIGHTS, else std::invalid_argument).
GpuSunLights toGpuSunLights(const std::vector<Light>& lights);

class LightBuffers {
public:
    explicit LightBuffers(const std::vector<Light>& lights);

    // Clustered lights (points and spots): what the light buffers and light lists index.
    std::uint32_t count() const { return count_; }
    std::uint32_t sunCount() const { return sunCount_; }
    // Whether any clustered light is a spot (ClusteringSettings::spotLights).
    bool hasSpots() const { return hasSpots_; }
    // Which lights drift and over what heights (the animation pass fits the drift to them).
    const DriftingLights& drifting() const { return drifting_; }
    // The animated lights (and their cones, where any light is a spot) at ML_SSBO_LIGHTS and
    // ML_SSBO_LIGHT_CONES, for every pass that reads lights.
    void bindForReading() const;
    // The lights at time 0 and the animated ones, for the animation pass.
    void bindForAnimation() const;
    // Binds the directional lights' uniform block (ML_UBO_SUN_LIGHTS).
    void bindSuns() const;
    // 32 bytes per clustered light in each of the two buffers, 16 more each where the set has
    // spots, and the suns' block.
    std::size_t bytes() const { return base_.size() + animated_.size() + baseCones_.size() + animatedCones_.size() + suns_.size(); }

    // Reads back the lights as drawn, in the order they were given (for --save-lights and the
    // tests' CPU references): clustered ones animated, directional ones as given.
    std::vector<Light> downloadAnimated() const;

private:
    std::uint32_t count_ = 0;
    std::uint32_t sunCount_ = 0;
    bool hasSpots_ = false;
    std::vector<Light> given_;
    DriftingLights drifting_;
    gl::Buffer base_;
    gl::Buffer animated_;
    gl::Buffer baseCones_, animatedCones_;  // only where a light is a spot
    gl::Buffer suns_;
};

// {"ML_SPOT_LIGHTS", "0" or "1"} for the programs that read lights: without spots in the set,
// their spot paths compile out (glsl/include/lights.glsl).
std::pair<std::string, std::string> spotLightsDefine(bool spotLights);

// glsl/animate_lights.comp: writes the animated lights for a point in time and, under
// Falloff::Stochastic, their ranges drawn with `drawSeed`.
class AnimateLightsPass {
public:
    explicit AnimateLightsPass(bool spotLights);
    void run(const LightBuffers& lights, float time, const LightAnimation& animation, const LightModel& model = {},
             std::uint32_t drawSeed = 0) const;

private:
    gl::Program program_;
};

}  // namespace ml
