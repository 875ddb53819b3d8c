// One frame, end to end: animate the lights, run the chosen shading method into the HDR
// target, tonemap. The same object serves `render`, `view`, `bench` and the tests.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/passes/auto_exposure_pass.h"
#include "renderer/passes/bloom_pass.h"
#include "renderer/camera/camera.h"
#include "renderer/frame_targets.h"
#include "renderer/gl/buffer.h"
#include "renderer/image/image.h"
#include "renderer/lights/light_buffers.h"
#include "renderer/methods/shading_method.h"
#include "renderer/passes/overdraw_pass.h"
#include "renderer/pass_timer.h"
#include "renderer/passes/resolve_pass.h"
#include "renderer/scene/scene_gpu.h"
#include "renderer/scene/vertex_animation.h"
#include "renderer/passes/tonemap_pass.h"
#include "renderer/raytracing/shadow_bvh_layout.h"
#include "renderer/raytracing/shadow_mode.h"
#include "renderer/raytracing/shadow_rays.h"

namespace ml {

// The animation advances this much per frame index, whatever the real frame rate.
inline constexpr float kSecondsPerFrame = 1.0f / 60.0f;

// --animation and --scene-time: the glTF clip a file plays (none: off, drawn at rest) and the
// time it starts from; a frame at animation time T shows the clip at startSeconds + T.
struct SceneAnimationSettings {
    std::optional<std::size_t> clip = 0;  // the first clip, where the scene has one
    double startSeconds = 0.0;
};

struct FrameSettings {
    int width = 1280;
    int height = 720;
    Camera camera;
    MethodSettings method;
    // --supersample K: the method draws at K*width x K*height, box-filtered down in linear HDR
    // before bloom and the tonemap (the anti-aliased reference, with naive).
    int supersample = 1;
    float exposure = 1.0f;
    // --exposure auto: the exposure measured from the frame (renderer/passes/auto_exposure_pass.h),
    // times `exposure`; each frame moves `exposureAdaptation` of the way (in stops) to it.
    bool autoExposure = false;
    float exposureAdaptation = 1.0f;
    float ambient = 0.03f;
    DrawSubmission draw = DrawSubmission::Direct;  // --draw: how raster passes submit the scene
    bool backfaceCulling = true;                   // --backface-culling (SceneGpu::setBackfaceCulling)
    bool transparency = true;                      // --transparency: draw glTF BLEND surfaces (SceneGpu::setTransparency)
    TriangleOrder triangleOrder = TriangleOrder::Overdraw;  // --triangle-order, applied at upload
    bool specular = true;  // the BRDF's specular term (--specular), compiled in (ShadingSwitches)
    LightModel lightModel;  // --brdf, --cutoff compiled in (ShadingSwitches); --light-cutoff a frame uniform
    Shadows shadows = Shadows::Off;  // --shadows, compiled in (ShadingSwitches) where something casts one
    std::uint32_t shadowBvhWidth = kDefaultShadowBvhWidth;  // --shadow-bvh-width (shadow_bvh.h)
    SampledShadowSettings sampledShadows;  // --shadow-rays-per-pixel, --shadow-reuse, --shadow-denoise (--shadows sampled)
    BloomSettings bloom;
    LightAnimation animation;
    SceneAnimationSettings sceneAnimation;
    bool timing = false;
    TimingClock clock = TimingClock::GpuQueries;
    TimingReadback readback = TimingReadback::Wait;
};

class FrameRenderer {
public:
    FrameRenderer(const Scene& scene, const std::vector<Light>& lights, const FrameSettings& settings);

    // Renders the frame at animation time frameIndex * kSecondsPerFrame. Returns the pass times
    // (empty unless settings.timing). `draw` numbers the stochastic cut-off's draws of one frame
    // (render --accumulate): the lights and camera stay, the drawn ranges change.
    std::vector<PassTime> render(std::uint32_t frameIndex, std::uint32_t draw = 0);
    // The same at any animation time (the live view's clock runs at the real frame rate), the
    // stochastic ranges drawn with `drawSeed`.
    std::vector<PassTime> renderAt(float seconds, std::uint32_t drawSeed = 0);
    // The last frame's context (its scene, lights, uniforms and targets) timed by `timer`: for
    // passes run outside a frame (`raster-floors`).
    FrameContext frameContext(PassTimer& timer) {
        return FrameContext{scene_, lights_, frameUniformBuffer_, uniforms_, targets_, timer, activeShadowRays(), activeSampledShadows()};
    }

    RgbaImage readLdr() const;
    FloatImage readHdr() const;

    void resize(int width, int height);
    void setCamera(const Camera& camera) { settings_.camera = camera; }
    void setMethod(const MethodSettings& method);
    // Replaces the light set (count or radius changed); the GPU buffers are re-created.
    void setLights(const std::vector<Light>& lights);
    void setExposure(float exposure) { settings_.exposure = exposure; }
    void setAutoExposure(bool on, float adaptation) {
        settings_.autoExposure = on;
        settings_.exposureAdaptation = adaptation;
    }
    // The automatic exposure of the last frame (a GPU sync); nothing when it is off.
    std::optional<AutoExposureReading> autoExposure() const;
    void setDrawSubmission(DrawSubmission draw) { settings_.draw = draw; }
    void setBackfaceCulling(bool on) { settings_.backfaceCulling = on; }
    void setTransparency(bool on) { settings_.transparency = on; }
    // Both rebuild the method's programs when a compiled-in switch changes (ShadingSwitches).
    void setSpecular(bool on);
    void setAmbient(float ambient) { settings_.ambient = ambient; }
    void setLightModel(const LightModel& model);
    // --shadows; `scene` (the one this renderer was built from) gives the occluders the first
    // time shadow rays are asked for.
    void setShadows(Shadows shadows, const Scene& scene);
    // Forgets --shadows sampled's reused history (a cut: the next frame reuses nothing).
    void resetShadowHistory() {
        if (sampledShadows_) sampledShadows_->resetHistory();
    }
    // The occluders' structure, once --shadows rays has built it (else null).
    const ShadowRays* shadowRays() const { return shadowRays_.get(); }
    // The shadow rays one more rendering of `frame` traces, counted by programs compiled for it
    // (ML_COUNT_SHADOW_RAYS) and rebuilt as they were after: for rays per second beside timed
    // frames, never inside them. nullopt where the frame traces none (--shadows off, no occluder).
    std::optional<std::uint64_t> countShadowRays(std::uint32_t frame);
    void setBloom(const BloomSettings& bloom) { settings_.bloom = bloom; }
    const BloomPass& bloom() const { return bloom_; }
    const ShadingMethod& method() const { return *method_; }
    const FrameSettings& settings() const { return settings_; }
    const LightBuffers& lights() const { return lights_; }
    const FrameTargets& targets() const { return targets_; }
    const FrameUniforms& uniforms() const { return uniforms_; }
    const SceneGpu& scene() const { return scene_; }
    // --view overdraw's pass, once a frame has been rendered with that view (else null).
    const OverdrawPass* overdraw() const { return overdraw_.get(); }
    // The vertex animation pre-pass: null for a static scene or with --animation off.
    const VertexAnimationPass* vertexAnimation() const { return vertexAnimation_.get(); }

private:
    void updateUniforms(float time, std::uint32_t drawSeed);
    // The occluders the frame traces: null with --shadows off or where nothing casts a shadow.
    const ShadowRays* activeShadowRays() const;
    // --shadows sampled's passes where the frame traces rays; else null.
    SampledShadowPass* activeSampledShadows() const;
    // The targets' stencil and sampling as the method needs them.
    void configureTargets();
    // The method's settings with what the frame decides: ClusteringSettings::spotLights from the
    // current lights, ClusteringSettings::shading from --brdf, --specular and --cutoff.
    MethodSettings forFrame(MethodSettings method) const;
    // Rebuilds the method where the frame's shading switches no longer match its programs'.
    void rebuildForShadingSwitches();

    FrameSettings settings_;
    SceneGpu scene_;
    std::unique_ptr<VertexAnimationPass> vertexAnimation_;  // only where a clip plays
    LightBuffers lights_;
    std::unique_ptr<ShadowRays> shadowRays_;  // built on the first frame settings with --shadows rays or sampled
    std::unique_ptr<SampledShadowPass> sampledShadows_;  // --shadows sampled, built with its settings
    bool countingShadowRays_ = false;         // countShadowRays' frame
    FrameTargets targets_;
    gl::Buffer frameUniformBuffer_;
    FrameUniforms uniforms_{};
    AnimateLightsPass animate_;
    ResolvePass resolve_;
    BloomPass bloom_;
    AutoExposurePass autoExposure_;
    TonemapPass tonemap_;
    std::unique_ptr<ShadingMethod> method_;
    std::unique_ptr<OverdrawPass> overdraw_;  // built on first use of --view overdraw
    PassTimer timer_;
};

}  // namespace ml
