#include "renderer/light_buffers.h"

#include "glsl/include/bindings.h"
#include "renderer/gpu_types.h"

namespace ml {

namespace {
std::vector<GpuLight> toGpu(const std::vector<PointLight>& lights) {
    std::vector<GpuLight> out(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        out[i].positionRadius = glm::vec4(lights[i].position, lights[i].radius);
        out[i].color = glm::vec4(lights[i].color, 0.0f);
    }
    return out;
}
}  // namespace

LightBuffers::LightBuffers(const std::vector<PointLight>& lights) : count_(static_cast<std::uint32_t>(lights.size())) {
    const std::vector<GpuLight> gpu = toGpu(lights);
    base_ = gl::Buffer::fromSpan<GpuLight>("lights.base", gpu, 0);
    animated_ = gl::Buffer::fromSpan<GpuLight>("lights.animated", gpu, 0);
}

std::vector<PointLight> LightBuffers::downloadAnimated() const {
    std::vector<GpuLight> gpu(count_);
    animated_.download(gpu.data(), gpu.size() * sizeof(GpuLight));
    std::vector<PointLight> out(count_);
    for (std::size_t i = 0; i < gpu.size(); ++i) {
        out[i].position = glm::vec3(gpu[i].positionRadius);
        out[i].radius = gpu[i].positionRadius.w;
        out[i].color = glm::vec3(gpu[i].color);
    }
    return out;
}

AnimateLightsPass::AnimateLightsPass() : program_(gl::Program::compute("animate_lights.comp")) {}

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
