// What a pass may read and write in one frame: the scene, the lights, the frame's uniforms, its
// targets and its timer. Every method, the clustering and the passes take it, so it sits at the
// renderer's root with the other frame vocabulary (frame_targets, pass_timer), below them all.
#pragma once

#include "renderer/frame_targets.h"
#include "renderer/gl/buffer.h"
#include "renderer/gpu_types.h"
#include "renderer/lights/light_buffers.h"
#include "renderer/pass_timer.h"
#include "renderer/raytracing/sampled_shadows.h"
#include "renderer/raytracing/shadow_rays.h"
#include "renderer/scene/scene_gpu.h"

namespace ml {

// What a method may read and write in one frame.
struct FrameContext {
    const SceneGpu& scene;
    const LightBuffers& lights;
    const gl::Buffer& frameUniforms;    // bound at ML_UBO_FRAME before render()
    const FrameUniforms& uniforms;      // the same values on the CPU
    FrameTargets& targets;              // render into targets.hdr() (+ depth)
    PassTimer& timer;
    const ShadowRays* shadows = nullptr;  // --shadows rays or sampled: the occluders; null when off
    // --shadows sampled: the passes that reuse and filter the compute lighting's ratio (null otherwise)
    SampledShadowPass* sampledShadows = nullptr;

    // What shading reads of the lights: their buffers and, with shadow rays, what blocks them.
    void bindLightsForShading() const {
        lights.bindForReading();
        if (shadows) shadows->bindForShading();
    }
};

}  // namespace ml
