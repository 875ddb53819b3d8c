// Point lights, mirrored in C++ by ml::GpuLight (renderer/gpu_types.h).
struct Light {
    vec4 positionRadius;   // xyz: world position, w: radius where the falloff reaches zero
    vec4 color;            // rgb: linear colour times intensity, w: unused
};

#ifndef ML_LIGHTS_WRITABLE
layout(std430, binding = ML_SSBO_LIGHTS) readonly buffer LightBuffer { Light lights[]; };
#endif
