#include "renderer/light_buffers.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "glsl/include/bindings.h"

namespace ml {

GpuLight toGpuLight(const Light& light) {
    GpuLight g;
    g.positionRadius = glm::vec4(light.position, light.radius);
    if (light.type == LightType::Spot) {
        // The CPU reference takes the same float cosines (renderer/shading_reference.cpp).
        g.colorCosInner = glm::vec4(light.color, std::cos(light.innerConeAngle));
        g.directionCosOuter = glm::vec4(glm::normalize(light.direction), std::cos(light.outerConeAngle));
    } else {
        g.colorCosInner = glm::vec4(light.color, float(ML_POINT_LIGHT_CONE_COS));
        g.directionCosOuter = glm::vec4(glm::vec3(0.0f), float(ML_POINT_LIGHT_CONE_COS));
    }
    return g;
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

LightBuffers::LightBuffers(const std::vector<Light>& lights) : given_(lights) {
    std::vector<GpuLight> gpu;
    gpu.reserve(lights.size());
    for (const Light& l : lights) {
        if (l.type != LightType::Directional) gpu.push_back(toGpuLight(l));
        hasSpots_ = hasSpots_ || l.type == LightType::Spot;
    }
    count_ = static_cast<std::uint32_t>(gpu.size());
    const GpuSunLights suns = toGpuSunLights(lights);
    sunCount_ = suns.count.x;
    base_ = gl::Buffer::fromSpan<GpuLight>("lights.base", gpu, 0);
    animated_ = gl::Buffer::fromSpan<GpuLight>("lights.animated", gpu, 0);
    suns_ = gl::Buffer("lights.suns", sizeof(GpuSunLights), &suns, 0);
}

void LightBuffers::bindSuns() const { suns_.bindBase(GL_UNIFORM_BUFFER, ML_UBO_SUN_LIGHTS); }

std::vector<Light> LightBuffers::downloadAnimated() const {
    std::vector<GpuLight> gpu(count_);
    if (count_ > 0) animated_.download(gpu.data(), gpu.size() * sizeof(GpuLight));
    std::vector<Light> out = given_;
    std::size_t next = 0;
    for (Light& l : out) {
        if (l.type == LightType::Directional) continue;
        const GpuLight& g = gpu[next++];
        l.position = glm::vec3(g.positionRadius);
        l.radius = g.positionRadius.w;
        l.color = glm::vec3(g.colorCosInner);
        if (l.type == LightType::Spot) l.direction = glm::vec3(g.directionCosOuter);
    }
    return out;
}

std::pair<std::string, std::string> spotLightsDefine(bool spotLights) { return {"ML_SPOT_LIGHTS", spotLights ? "1" : "0"}; }

AnimateLightsPass::AnimateLightsPass(bool spotLights)
    : program_(gl::Program::compute("animate_lights.comp", shaders::Defines{spotLightsDefine(spotLights)})) {}

void AnimateLightsPass::run(const LightBuffers& lights, float time, const LightAnimation& animation) const {
    if (lights.count() == 0) return;
    program_.use();
    program_.set("u_lightCount", lights.count());
    program_.set("u_time", time);
    program_.set("u_driftSpeed", animation.driftSpeed);
    program_.set("u_wrapY", glm::vec2(animation.wrapMinY, animation.wrapHeight));
    lights.base().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHTS_BASE);
    lights.animated().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHTS);
    glDispatchCompute(gl::groupsFor(lights.count(), ML_ANIMATE_WORKGROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace ml
