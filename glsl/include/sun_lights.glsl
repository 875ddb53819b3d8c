// Directional lights ("suns"), mirrored in C++ by ml::GpuSunLights (renderer/gpu_types.h). They
// reach every point, so every shading pass loops over them outside the clusters. Needs shading.glsl.
layout(std140, binding = ML_UBO_SUN_LIGHTS) uniform SunLightsBlock {
    uvec4 u_sunCount;                             // x: directional lights in use
    vec4 u_sunDirection[ML_MAX_SUN_LIGHTS];       // xyz: unit direction the light travels
    vec4 u_sunColor[ML_MAX_SUN_LIGHTS];           // rgb: linear colour times intensity
};

// Every sun's light at a point (offered to --shadows sampled's draws where it draws them).
vec3 shadeSuns(SurfacePoint s, vec3 viewDir) {
    vec3 color = vec3(0.0);
    for (uint i = 0u; i < u_sunCount.x; ++i) {
        vec3 sun = shadeDirectionalLight(s, viewDir, u_sunDirection[i].xyz, u_sunColor[i].rgb);
        color += sun;
        ML_OFFER_SHADOW_SAMPLE(sun, vec4(-u_sunDirection[i].xyz, 0.0), kSunSampleKey + i);
    }
    return color;
}

// What a point shows before the clustered lights: the unlit terms and every sun.
vec3 shadeUnclustered(SurfacePoint s, vec3 viewDir) { return shadeUnlit(s, viewDir) + shadeSuns(s, viewDir); }

#ifdef ML_SHADOW_SAMPLED_LIGHTING
// A point's colour from the sum of its clustered lights: the unlit terms, the suns and the sum,
// as shadeUnclustered adds them, the lights' part scaled by the drawn rays' ratio. The raw
// estimate, unreused and unfiltered: for surfaces that keep no history (glass fragments).
vec3 sampledShadowColor(SurfacePoint s, vec3 viewDir, vec3 lightSum) {
    vec3 suns = shadeSuns(s, viewDir);
    float ratio = sampledShadowRatio(s.position, s.normal);
    // Where every drawn ray arrives, the sums of --shadows off, bit for bit.
    return ratio == 1.0 ? shadeUnlit(s, viewDir) + suns + lightSum : shadeUnlit(s, viewDir) + (suns + lightSum) * ratio;
}
#endif
