#include "renderer/lights/light_buffers.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "glsl/include/bindings.h"

namespace ml {

GpuLight toGpuLight(const Light& light) {
    GpuLight g;
    g.positionRadius = glm::vec4(light.position, light.radius);
    // The CPU reference takes the same float cosines (renderer/reference/shading_reference.cpp).
    const float cosInner = light.type == LightType::Spot ? std::cos(light.innerConeAngle) : float(ML_POINT_LIGHT_CONE_COS);
    g.colorCosInner = glm::vec4(light.color, cosInner);
    return g;
}

GpuLightCone toGpuLightCone(const Light& light) {
    if (light.type != LightType::Spot) return {glm::vec4(glm::vec3(0.0f), float(ML_POINT_LIGHT_CONE_COS))};
    return {glm::vec4(glm::normalize(light.direction), std::cos(light.outerConeAngle))};
}

GpuSunLights toGpuSunLights(const std::vector<Light>& lights) {
    GpuSunLights suns{};
    for (const Light& l : lights) {
        if (l.type != LightType::Directional) continue;
        if (suns.count.x == ML_MAX_SUN_LIGHTS)
            throw std::invalid_argument("more than " + std::to_string(ML_MAX_SUN_LIGHTS) +
                                        " directional lights (the renderer's limit, ML_MAX_SUN_LIGHTS)");
        suns.direction[suns.count.x] = glm::vec4(glm::normalize(l.direction), 0.0f);
        suns.color[suns.count.x] = glm::vec4(l.color, 0.0f);
        ++suns.count.x;
    }
    return suns;
}

LightBuffers::LightBuffers(const std::vector<Light>& lights) : given_(lights), drifting_(driftingLights(lights)) {
    std::vector<GpuLight> gpu;
    std::vector<GpuLightCone> cones;
    gpu.reserve(lights.size());
    for (const Light& l : lights) {
        if (l.type == LightType::Directional) continue;
        gpu.push_back(toGpuLight(l));
        cones.push_back(toGpuLightCone(l));
        hasSpots_ = hasSpots_ || l.type == LightType::Spot;
    }
    count_ = static_cast<std::uint32_t>(gpu.size());
    const GpuSunLights suns = toGpuSunLights(lights);
    sunCount_ = suns.count.x;
    base_ = gl::Buffer::fromSpan<GpuLight>("lights.base", gpu, 0);
    animated_ = gl::Buffer::fromSpan<GpuLight>("lights.animated", gpu, 0);
    if (hasSpots_) {
        baseCones_ = gl::Buffer::fromSpan<GpuLightCone>("lights.cones-base", cones, 0);
        animatedCones_ = gl::Buffer::fromSpan<GpuLightCone>("lights.cones-animated", cones, 0);
    }
    suns_ = gl::Buffer("lights.suns", sizeof(GpuSunLights), &suns, 0);
}

void LightBuffers::bindForAnimation() const {
    base_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHTS_BASE);
    animated_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHTS);
    if (hasSpots_) {
        baseCones_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_CONES_BASE);
        animatedCones_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_CONES);
    }
}

void LightBuffers::bindForReading() const {
    animated_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHTS);
    if (hasSpots_) animatedCones_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_CONES);
}

void LightBuffers::bindSuns() const { suns_.bindBase(GL_UNIFORM_BUFFER, ML_UBO_SUN_LIGHTS); }

std::vector<Light> LightBuffers::downloadAnimated() const {
    std::vector<GpuLight> gpu(count_);
    std::vector<GpuLightCone> cones(hasSpots_ ? count_ : 0);
    if (count_ > 0) animated_.download(gpu.data(), gpu.size() * sizeof(GpuLight));
    if (!cones.empty()) animatedCones_.download(cones.data(), cones.size() * sizeof(GpuLightCone));
    std::vector<Light> out = given_;
    std::size_t next = 0;
    for (Light& l : out) {
        if (l.type == LightType::Directional) continue;
        const std::size_t i = next++;
        const GpuLight& g = gpu[i];
        l.position = glm::vec3(g.positionRadius);
        l.radius = g.positionRadius.w;
        l.color = glm::vec3(g.colorCosInner);
        if (l.type == LightType::Spot) l.direction = glm::vec3(cones[i].directionCosOuter);
    }
    return out;
}

std::pair<std::string, std::string> spotLightsDefine(bool spotLights) { return {"ML_SPOT_LIGHTS", spotLights ? "1" : "0"}; }

AnimateLightsPass::AnimateLightsPass(bool spotLights)
    : program_(gl::Program::compute("animate_lights.comp", shaders::Defines{spotLightsDefine(spotLights)})) {}

void AnimateLightsPass::run(const LightBuffers& lights, float time, const LightAnimation& animation, const LightModel& model,
                            std::uint32_t drawSeed) const {
    if (lights.count() == 0) return;
    program_.use();
    program_.set("u_lightCount", lights.count());
    program_.set("u_time", time);
    const LightAnimation fitted = fitDrift(animation, lights.drifting());
    program_.set("u_driftSpeed", fitted.driftSpeed);
    program_.set("u_wrapY", glm::vec2(fitted.wrapMinY, fitted.wrapHeight));
    program_.set("u_firstDrifting", fitted.firstDrifting);
    program_.set("u_stochasticCutoff", model.falloff == Falloff::Stochastic ? model.cutoff : 0.0f);
    program_.set("u_drawSeed", drawSeed);
    lights.bindForAnimation();
    glDispatchCompute(gl::groupsFor(lights.count(), ML_ANIMATE_WORKGROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace ml
