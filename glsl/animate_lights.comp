#version 450 core
// Light animation: each generated light drifts upward from where it was placed at its own speed
// and, past the top of the wrap range, re-enters at the bottom; a spot also turns about +y at its
// own rate. The lights a file placed (the first u_firstDrifting) stay still. Positions and
// directions are a pure function of time, so frame K is reproducible alone, and at time 0 every
// light is exactly where it was placed. Mirrored by ml::animateLight. Under
// --cutoff stochastic it also draws each light's range for the frame (Russian roulette; mirrored
// by ml::stochasticRadius, renderer/lights/light_model.h), so every clustering sees the drawn ranges.
#include "include/bindings.h"
#define ML_LIGHTS_WRITABLE
#include "include/lights.glsl"
#include "include/spot_cone.glsl"
#include "include/hash.glsl"

layout(local_size_x = ML_ANIMATE_WORKGROUP) in;

layout(std430, binding = ML_SSBO_LIGHTS_BASE) readonly buffer BaseLights { Light baseLights[]; };
layout(std430, binding = ML_SSBO_LIGHTS) writeonly buffer AnimatedLights { Light animatedLights[]; };
#if ML_SPOT_LIGHTS
layout(std430, binding = ML_SSBO_LIGHT_CONES_BASE) readonly buffer BaseCones { vec4 baseCones[]; };
layout(std430, binding = ML_SSBO_LIGHT_CONES) writeonly buffer AnimatedCones { vec4 animatedCones[]; };
#endif

uniform uint u_lightCount;
uniform float u_time;        // seconds
uniform float u_driftSpeed;  // metres per second, mean
uniform vec2 u_wrapY;        // min y, height
uniform uint u_firstDrifting;  // lights before it were placed by a file: still
uniform float u_stochasticCutoff;  // --cutoff stochastic: the cut-off E; 0: ranges as given
uniform uint u_drawSeed;           // the frame's draw (ml::stochasticDrawSeed)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_lightCount) return;
    Light l = baseLights[i];
#if ML_SPOT_LIGHTS
    vec4 cone = baseCones[i];
#endif
    if (i >= u_firstDrifting && u_wrapY.y > 0.0 && u_driftSpeed != 0.0) {
        float speed = u_driftSpeed * (0.5 + hashToUnitFloat(i));
        float y = l.positionRadius.y + speed * u_time;
        float top = u_wrapY.x + u_wrapY.y;
        if (y >= top) y -= u_wrapY.y * (floor((y - top) / u_wrapY.y) + 1.0);
        l.positionRadius.y = y;
#if ML_SPOT_LIGHTS
        if (isSpotCone(cone.w)) {
            float turn = 2.0 * hashToUnitFloat(i ^ 0x9E3779B9u) - 1.0;
            float angle = u_driftSpeed * float(ML_SPOT_TURN_PER_METRE) * turn * u_time;
            float c = cos(angle), s = sin(angle);
            vec3 d = cone.xyz;
            cone.xyz = vec3(c * d.x + s * d.z, d.y, c * d.z - s * d.x);
        }
#endif
    }
    if (u_stochasticCutoff > 0.0) {
        vec3 c = l.colorCosInner.rgb;
        float xi = 1.0 - hashToUnitFloat(pcgHash(i) ^ u_drawSeed);
        l.positionRadius.w = sqrt(max(c.r, max(c.g, c.b)) / u_stochasticCutoff) / sqrt(xi);
    }
    animatedLights[i] = l;
#if ML_SPOT_LIGHTS
    animatedCones[i] = cone;
#endif
}
