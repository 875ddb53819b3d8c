#version 450 core
// Light animation: each light drifts upward at its own speed and wraps within the scene's
// vertical extent; a spot also turns about +y at its own rate. Positions and directions are a
// pure function of time, so frame K is reproducible alone. Mirrored by ml::animateLight. Under
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
uniform float u_stochasticCutoff;  // --cutoff stochastic: the cut-off E; 0: ranges as given
uniform uint u_drawSeed;           // the frame's draw (ml::stochasticDrawSeed)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_lightCount) return;
    Light l = baseLights[i];
#if ML_SPOT_LIGHTS
    vec4 cone = baseCones[i];
#endif
    if (u_wrapY.y > 0.0 && u_driftSpeed != 0.0) {
        float speed = u_driftSpeed * (0.5 + hashToUnitFloat(i));
        float y = l.positionRadius.y - u_wrapY.x + speed * u_time;
        l.positionRadius.y = u_wrapY.x + mod(y, u_wrapY.y);
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
