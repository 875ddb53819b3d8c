// Directional lights ("suns"), mirrored in C++ by ml::GpuSunLights (renderer/gpu_types.h). They
// reach every point, so every shading pass loops over them outside the clusters. Needs shading.glsl.
layout(std140, binding = ML_UBO_SUN_LIGHTS) uniform SunLightsBlock {
    uvec4 u_sunCount;                             // x: directional lights in use
    vec4 u_sunDirection[ML_MAX_SUN_LIGHTS];       // xyz: unit direction the light travels
    vec4 u_sunColor[ML_MAX_SUN_LIGHTS];           // rgb: linear colour times intensity
};

// What a point shows before the clustered lights: the unlit terms and every sun.
vec3 shadeUnclustered(SurfacePoint s, vec3 viewDir) {
    vec3 color = shadeUnlit(s);
    for (uint i = 0u; i < u_sunCount.x; ++i) color += shadeDirectionalLight(s, viewDir, u_sunDirection[i].xyz, u_sunColor[i].rgb);
    return color;
}
