// --shadows sampled: what the compute lighting (deferred_lighting.comp) leaves for the shadow
// passes besides the unshadowed frame. Per pixel: the lights' part of its colour (every clustered
// light and sun, unshadowed), where the surface is (its position and normal), which the reuse and
// the filter compare neighbours and past frames by (shadow_temporal.comp, shadow_denoise.comp), and
// the rays it drew, which shadow_trace.comp traces and turns into the ratio. The rays are traced in
// a program of their own because the traversal needs few registers and this one many (inside it
// they ran at a fifth of the exact rays' rate on the H100). Needs
// deferred_resolve, sun_lights, shading (with ML_SHADOW_SAMPLED_LIGHTING), debug_views and
// octahedral (through gbuffer_layout).
layout(binding = ML_IMG_SHADOW_LIGHT, rgba32f) uniform writeonly image2D u_shadowLight;  // rgb: the lights' part; a: the ratio, -1 where no surface
layout(binding = ML_IMG_SHADOW_GUIDE, rgba32f) uniform writeonly image2D u_shadowGuide;  // xyz: world position; w: the normal, 2 x snorm16 octahedral
// The drawn rays, a layer of the frame's rows each: first the origin (w 1 where the pixel drew a
// light, else 0), then each slot's target: a light's position (w 1), a sun's unit direction (w 0),
// or, for a light an earlier slot j drew too, w = 2 + j.
layout(binding = ML_IMG_SHADOW_RAYS, rgba32f) uniform writeonly image2D u_shadowRays;

void storeShadowSampleRays(ivec2 p, bool drawn, vec3 position, vec3 normal) {
    int rows = imageSize(u_shadowRays).y / (ML_SHADOW_SAMPLES + 1);
    imageStore(u_shadowRays, p, drawn ? vec4(shadowRayOrigin(position, normal), 1.0) : vec4(0.0));
    if (!drawn) return;
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        int same = firstSlotOfSameLight(k);
        imageStore(u_shadowRays, p + ivec2(0, (k + 1) * rows), same < k ? vec4(0.0, 0.0, 0.0, 2.0 + float(same)) : g_sampleTarget[k]);
    }
}

// The pixel's HDR colour, unshadowed; its draws are stored for shadow_trace.comp, which puts the
// ratio they measure beside the lights' part (1 until then, and where nothing was drawn).
vec4 finishSampledPixel(ivec2 p, bool surface, ResolvedPixel px, vec3 lightSum) {
    if (!surface) {
        imageStore(u_shadowLight, p, vec4(0.0, 0.0, 0.0, -1.0));
        imageStore(u_shadowGuide, p, vec4(0.0));
        storeShadowSampleRays(p, false, vec3(0.0), vec3(0.0));
        return kBackground;
    }
    vec3 suns = viewShadesLights() ? shadeSuns(px.surface, px.viewDir) : vec3(0.0);
    storeShadowSampleRays(p, !isinf(g_sampleKey[0]), px.surface.position, px.surface.normal);
    imageStore(u_shadowLight, p, vec4(suns + lightSum, 1.0));
    imageStore(u_shadowGuide, p, vec4(px.surface.position, uintBitsToFloat(packSnorm2x16(octEncode(px.surface.normal)))));
    // Summed as finishPixel sums (shadeUnclustered, then the list's lights): the same bits as --shadows off.
    vec3 color = viewShadesLights() ? shadeUnlit(px.surface, px.viewDir) + suns + lightSum : vec3(0.0);
    return vec4(debugViewColor(grid.options.w, px.surface, px.cluster, px.viewDepth, color), 1.0);
}
