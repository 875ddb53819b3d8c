#version 450 core
// The G-buffer pass of clustered deferred shading: what the shading model reads, no position
// (it comes back from depth), in the --gbuffer layout (include/gbuffer_layout.glsl).
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/shading.glsl"
#include "include/material.glsl"
#include "include/scene_fragment.glsl"
#include "include/gbuffer_layout.glsl"

#if ML_GBUFFER_FLOAT_TARGETS == 0
layout(location = 0) out uvec4 o_packed;
#else
layout(location = 0) out vec4 o_target0;
layout(location = 1) out vec4 o_target1;
#if ML_GBUFFER_FLOAT_TARGETS >= 3
layout(location = 2) out vec4 o_target2;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
layout(location = 3) out vec4 o_target3;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
layout(location = 4) out vec4 o_target4;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
layout(location = 5) out vec4 o_target5;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
layout(location = 6) out vec4 o_target6;
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
layout(location = 7) out vec4 o_target7;
#endif
#endif

void main() {
    GBufferTexel t = encodeGBuffer(fragmentSurface());
#if ML_GBUFFER_FLOAT_TARGETS == 0
    o_packed = t.bits;
#else
    o_target0 = t.target[0];
    o_target1 = t.target[1];
#if ML_GBUFFER_FLOAT_TARGETS >= 3
    o_target2 = t.target[2];
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
    o_target3 = t.target[3];
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
    o_target4 = t.target[4];
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
    o_target5 = t.target[5];
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
    o_target6 = t.target[6];
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
    o_target7 = t.target[7];
#endif
#endif
}
