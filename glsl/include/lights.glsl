// Point and spot lights, mirrored in C++ by ml::GpuLight (renderer/gpu_types.h). A point light's
// cone cosines are ML_POINT_LIGHT_CONE_COS: no direction is ever outside its cone.
// ML_SPOT_LIGHTS 0: the light set has no spots (the renderer sets it from the lights), so every
// spot path compiles out and a points-only scene pays nothing for them. 1 unless set.
#ifndef ML_SPOT_LIGHTS
#define ML_SPOT_LIGHTS 1
#endif

struct Light {
    vec4 positionRadius;     // xyz: world position, w: radius where the falloff reaches zero
    vec4 colorCosInner;      // rgb: linear colour times intensity, w: cos of the inner cone angle
};
// A spot's cone, one per light in a buffer of its own (bound only where the set has spots):
// xyz the unit direction the spot points (zero for points), w the cos of the outer cone angle.

#ifndef ML_LIGHTS_WRITABLE
layout(std430, binding = ML_SSBO_LIGHTS) readonly buffer LightBuffer { Light lights[]; };
#if ML_SPOT_LIGHTS
layout(std430, binding = ML_SSBO_LIGHT_CONES) readonly buffer LightConeBuffer { vec4 lightCones[]; };
#endif

// Light i's cone; a point light's where the set has no spots.
vec4 lightCone(uint i) {
#if ML_SPOT_LIGHTS
    return lightCones[i];
#else
    return vec4(0.0, 0.0, 0.0, ML_POINT_LIGHT_CONE_COS);
#endif
}
#endif
