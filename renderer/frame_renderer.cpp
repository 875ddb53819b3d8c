#include "renderer/frame_renderer.h"

#include <cstring>
#include <stdexcept>

#include "glsl/include/bindings.h"
#include "renderer/context/gl_context.h"

namespace ml {

FrameRenderer::FrameRenderer(const Scene& scene, const std::vector<Light>& lights, const FrameSettings& settings)
    : settings_(settings),
      scene_(scene, settings.triangleOrder),
      vertexAnimation_(sceneClip(scene, settings.sceneAnimation.clip)
                           ? std::make_unique<VertexAnimationPass>(scene, *settings.sceneAnimation.clip, scene_.hasTangentStream())
                           : nullptr),
      lights_(lights),
      // An animated scene's structure follows its pose (ShadowRays::refit, each frame).
      shadowRays_(settings.shadows != Shadows::Off
                      ? std::make_unique<ShadowRays>(scene, settings.shadowBvhWidth, vertexAnimation_ != nullptr)
                      : nullptr),
      sampledShadows_(settings.shadows == Shadows::Sampled ? std::make_unique<SampledShadowPass>(settings.sampledShadows) : nullptr),
      // Sampled as asked from the start, so a size the GPU cannot hold is refused before allocation.
      targets_(settings.width, settings.height, false, TargetSampling{settings.method.msaa, settings.supersample}),
      frameUniformBuffer_("frame.uniforms", sizeof(FrameUniforms)),
      animate_(lights_.hasSpots()),
      method_(createMethod(forFrame(settings.method), scene_.materialFeatures())),
      timer_(settings.timing, settings.clock, settings.readback) {
    settings_.method = forFrame(settings_.method);
    configureTargets();
}

void FrameRenderer::configureTargets() {
    targets_.configure(method_->needsStencil(), TargetSampling{settings_.method.msaa, settings_.supersample});
}

void FrameRenderer::resize(int width, int height) {
    settings_.width = width;
    settings_.height = height;
    targets_.resize(width, height);
}

MethodSettings FrameRenderer::forFrame(MethodSettings method) const {
    method.clustering.spotLights = lights_.hasSpots();
    const ShadowRays* shadows = activeShadowRays();
    method.clustering.shading = ShadingSwitches{settings_.lightModel.brdf, settings_.specular, settings_.lightModel.falloff, shadows != nullptr,
                                                activeSampledShadows() ? settings_.sampledShadows.raysPerPixel : 0u,
                                                countingShadowRays_ && shadows != nullptr, shadows ? shadows->width() : kDefaultShadowBvhWidth};
    return method;
}

std::optional<std::uint64_t> FrameRenderer::countShadowRays(std::uint32_t frame) {
    if (activeShadowRays() == nullptr) return std::nullopt;
    countingShadowRays_ = true;
    setMethod(settings_.method);
    shadowRays_->resetRayCount();
    render(frame);
    const std::uint64_t rays = shadowRays_->rayCount();
    countingShadowRays_ = false;
    setMethod(settings_.method);
    return rays;
}

const ShadowRays* FrameRenderer::activeShadowRays() const {
    return settings_.shadows != Shadows::Off && shadowRays_ && !shadowRays_->empty() ? shadowRays_.get() : nullptr;
}

SampledShadowPass* FrameRenderer::activeSampledShadows() const {
    return settings_.shadows == Shadows::Sampled && activeShadowRays() ? sampledShadows_.get() : nullptr;
}

void FrameRenderer::setShadows(Shadows shadows, const Scene& scene) {
    settings_.shadows = shadows;
    if (shadows != Shadows::Off && !shadowRays_) shadowRays_ = std::make_unique<ShadowRays>(scene, settings_.shadowBvhWidth, vertexAnimation_ != nullptr);
    if (shadows == Shadows::Sampled && !sampledShadows_) sampledShadows_ = std::make_unique<SampledShadowPass>(settings_.sampledShadows);
    if (sampledShadows_) sampledShadows_->resetHistory();
    rebuildForShadingSwitches();
}

void FrameRenderer::setSpecular(bool on) {
    settings_.specular = on;
    rebuildForShadingSwitches();
}

void FrameRenderer::setLightModel(const LightModel& model) {
    settings_.lightModel = model;
    rebuildForShadingSwitches();
}

void FrameRenderer::rebuildForShadingSwitches() {
    if (forFrame(settings_.method).clustering.shading != settings_.method.clustering.shading) setMethod(settings_.method);
}

void FrameRenderer::setMethod(const MethodSettings& method) {
    settings_.method = forFrame(method);
    method_ = createMethod(settings_.method, scene_.materialFeatures());
    configureTargets();
}

void FrameRenderer::setLights(const std::vector<Light>& lights) {
    const bool hadSpots = lights_.hasSpots();
    lights_ = LightBuffers(lights);
    if (lights_.hasSpots() == hadSpots) return;
    // The programs that read lights are compiled for spots or for points only.
    animate_ = AnimateLightsPass(lights_.hasSpots());
    setMethod(settings_.method);
}

void FrameRenderer::updateUniforms(float time, std::uint32_t drawSeed) {
    const Camera& c = settings_.camera;
    // The size the method draws at (times --supersample); the aspect ratio is the output's.
    const float w = static_cast<float>(targets_.width()), h = static_cast<float>(targets_.height());
    uniforms_.view = c.view();
    uniforms_.proj = c.projection(w / h);
    uniforms_.viewProj = uniforms_.proj * uniforms_.view;
    uniforms_.invProj = glm::inverse(uniforms_.proj);
    uniforms_.invView = glm::inverse(uniforms_.view);
    uniforms_.cameraPos = glm::vec4(c.eye, 1.0f);
    uniforms_.viewport = glm::vec4(w, h, 1.0f / w, 1.0f / h);
    uniforms_.depthRange = glm::vec4(c.nearPlane, c.farPlane, time, settings_.ambient);
    const LightModel& model = settings_.lightModel;
    const std::uint32_t switches = (settings_.specular ? ML_SHADING_SPECULAR : 0u) | (model.brdf == Brdf::Ggx ? ML_SHADING_GGX : 0u);
    uniforms_.counts = glm::uvec4(lights_.count(), switches, static_cast<std::uint32_t>(model.falloff), drawSeed);
    const ShadowRays* shadows = activeShadowRays();
    uniforms_.lightModel = glm::vec4(model.cutoff, shadows ? shadows->directionalReach() : 0.0f, 0.0f, 0.0f);
    uniforms_.shadows = shadows ? shadows->uniforms() : glm::uvec4(0u);
    frameUniformBuffer_.upload(&uniforms_, sizeof(uniforms_));
    frameUniformBuffer_.bindBase(GL_UNIFORM_BUFFER, ML_UBO_FRAME);
    lights_.bindSuns();
}

std::vector<PassTime> FrameRenderer::render(std::uint32_t frameIndex, std::uint32_t draw) {
    return renderAt(static_cast<float>(frameIndex) * kSecondsPerFrame, stochasticDrawSeed(frameIndex, draw));
}

std::vector<PassTime> FrameRenderer::renderAt(float time, std::uint32_t drawSeed) {
    timer_.beginFrame();
    updateUniforms(time, drawSeed);
    if (vertexAnimation_) {
        auto pass = timer_.pass("scene.animate");
        vertexAnimation_->run(scene_, settings_.sceneAnimation.startSeconds + static_cast<double>(time));
        // Transparent ranges blend back to front by their boxes, which move with them.
        if (scene_.transparentRangeCount() > 0)
            scene_.refitTransparentBounds([&](std::uint32_t v, const glm::vec3& loaded) { return vertexAnimation_->posedPosition(v, loaded); });
    }
    if (const ShadowRays* shadows = activeShadowRays(); shadows && shadows->followsPose()) {
        auto pass = timer_.pass("shadows.refit");
        shadows->refit(scene_);
    }
    {
        auto pass = timer_.pass("lights.animate");
        animate_.run(lights_, time, settings_.animation, settings_.lightModel, drawSeed);
    }
    scene_.setSubmission(settings_.draw);
    scene_.setBackfaceCulling(settings_.backfaceCulling);
    scene_.setTransparency(settings_.transparency);
    if (settings_.method.clustering.view == DebugView::Overdraw) {
        // The raster work itself, whatever the method: the view replaces the method's frame.
        if (settings_.method.msaa > 1) throw std::invalid_argument(kOverdrawRefusesMsaa);
        if (!overdraw_) overdraw_ = std::make_unique<OverdrawPass>(scene_.materialFeatures());
        overdraw_->run(scene_, targets_, timer_);
    } else {
        targets_.setComputedDepth(nullptr);
        method_->render(FrameContext{scene_, lights_, frameUniformBuffer_, uniforms_, targets_, timer_, activeShadowRays(), activeSampledShadows()});
    }
    // After the method and anything it drew last (a transparent pass lands in the samples too).
    if (targets_.sampling().resolves()) {
        auto pass = timer_.pass(ResolvePass::passName(targets_.sampling()));
        resolve_.run(targets_);
    }
    const bool debugView = settings_.method.clustering.view != DebugView::Shaded;
    // After shading, so every method gets the same bloom; debug views' colours get none.
    if (!debugView) bloom_.run(targets_, settings_.bloom, timer_);
    const bool autoExposure = settings_.autoExposure && !debugView;
    if (autoExposure) autoExposure_.run(targets_, settings_.exposureAdaptation, timer_);
    {
        auto pass = timer_.pass("tonemap");
        tonemap_.run(targets_, settings_.exposure, debugView, autoExposure ? &autoExposure_ : nullptr);
    }
    return timer_.endFrame();
}

std::optional<AutoExposureReading> FrameRenderer::autoExposure() const {
    if (!settings_.autoExposure) return std::nullopt;
    return autoExposure_.read();
}

RgbaImage FrameRenderer::readLdr() const {
    RgbaImage image{targets_.outputWidth(), targets_.outputHeight(), {}};
    const std::size_t row = static_cast<std::size_t>(image.width) * 4;
    std::vector<std::uint8_t> bottomUp(row * image.height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(targets_.ldr().id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bottomUp.size()), bottomUp.data());
    checkNoGpuReset("the frame");  // the read-back waited for it
    image.pixels.resize(bottomUp.size());
    // GL's first row is the bottom one; images are stored top row first.
    for (int y = 0; y < image.height; ++y)
        std::memcpy(&image.pixels[y * row], &bottomUp[(image.height - 1 - y) * row], row);
    return image;
}

FloatImage FrameRenderer::readHdr() const {
    FloatImage image{targets_.outputWidth(), targets_.outputHeight(), {}};
    const std::size_t row = static_cast<std::size_t>(image.width) * 3;
    std::vector<float> bottomUp(row * image.height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(targets_.outputHdr().id(), 0, GL_RGB, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)),
                      bottomUp.data());
    checkNoGpuReset("the frame");
    image.pixels.resize(bottomUp.size());
    for (int y = 0; y < image.height; ++y)
        std::memcpy(&image.pixels[y * row], &bottomUp[(image.height - 1 - y) * row], row * sizeof(float));
    return image;
}

}  // namespace ml
