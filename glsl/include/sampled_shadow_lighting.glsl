// --shadows sampled: what the compute lighting (deferred_lighting.comp) leaves for the shadow
// passes besides the unshadowed frame. Per pixel: the lights' part of its colour (every clustered
// light and sun, unshadowed) with the ratio its drawn rays measured, and where the surface is (its
// position and normal), which the reuse and the filter compare neighbours and past frames by
// (shadow_temporal.comp, shadow_denoise.comp). Needs deferred_resolve, sun_lights, shading (with
// ML_SHADOW_SAMPLED_LIGHTING), debug_views and octahedral (through gbuffer_layout).
layout(binding = ML_IMG_SHADOW_LIGHT, rgba32f) uniform writeonly image2D u_shadowLight;  // rgb: the lights' part; a: the ratio, -1 where no surface
layout(binding = ML_IMG_SHADOW_GUIDE, rgba32f) uniform writeonly image2D u_shadowGuide;  // xyz: world position; w: the normal, 2 x snorm16 octahedral

// The pixel's HDR colour, unshadowed; its draws are traced and the ratio stored beside it.
vec4 finishSampledPixel(ivec2 p, bool surface, ResolvedPixel px, vec3 lightSum) {
    if (!surface) {
        imageStore(u_shadowLight, p, vec4(0.0, 0.0, 0.0, -1.0));
        imageStore(u_shadowGuide, p, vec4(0.0));
        return kBackground;
    }
    vec3 suns = vec3(0.0);
    float ratio = 1.0;
    if (viewShadesLights()) {
        suns = shadeSuns(px.surface, px.viewDir);
        ratio = sampledShadowRatio(px.surface.position, px.surface.normal);
    }
    imageStore(u_shadowLight, p, vec4(suns + lightSum, ratio));
    imageStore(u_shadowGuide, p, vec4(px.surface.position, uintBitsToFloat(packSnorm2x16(octEncode(px.surface.normal)))));
    // Summed as finishPixel sums (shadeUnclustered, then the list's lights): the same bits as --shadows off.
    vec3 color = viewShadesLights() ? shadeUnlit(px.surface) + suns + lightSum : vec3(0.0);
    return vec4(debugViewColor(grid.options.w, px.surface, px.cluster, px.viewDepth, color), 1.0);
}
