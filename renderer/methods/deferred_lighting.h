// The lighting pass shared by clustered deferred and the visibility buffer: both light the
// G-buffer with the cluster lists, and both can run it as glsl/deferred_lighting.comp.
#pragma once

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/gbuffer.h"
#include "renderer/methods/shading_method.h"

namespace ml {

// Defines of the lighting programs: the light lists' (lightListDefines), ML_NORMAL_CONES with
// --normal-cones, and the G-buffer's layout (ML_GBUFFER_FORMAT).
shaders::Defines deferredLightingDefines(const ClusteringSettings& clustering, const GBuffer& gbuffer);

// Binds the G-buffer, the depth, the lights and the cluster lists the lighting shaders read.
void bindDeferredLightingInputs(const GBuffer& gbuffer, const FrameContext& ctx, const ClusteredLighting& clustering);

// Runs the bound compute lighting program over the frame, writing the HDR target (and, with
// --shadows sampled, what the shadow passes read beside it).
void dispatchComputeLighting(const FrameContext& ctx);

// --shadows sampled: the drawn rays traced, their visibility ratio reused, filtered and multiplied
// in, after the compute lighting (nothing otherwise); `clustering` the lighting's settings.
void applySampledShadows(const FrameContext& ctx, const ClusteringSettings& clustering);

}  // namespace ml
