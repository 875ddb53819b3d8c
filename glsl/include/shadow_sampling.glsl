// --shadows sampled (issue 63): the lighting pass sums every light unshadowed, exactly, and draws
// ML_SHADOW_SAMPLES lights a pixel in proportion to their unshadowed luminance to trace shadow
// rays to. The share of the draws that reach their light estimates the ratio of shadowed to
// unshadowed light (Heitz, Hill and McGuire 2018, "Combining analytic direct illumination and
// stochastic shadows"): with p_i = w_i / W (w_i light i's luminance here, W their sum),
// E[V_drawn] = sum V_i w_i / W, so the ratio times the exact unshadowed sum has the shadowed
// sum's luminance in expectation. Where every light is seen, or none, it is exact (1 or 0).
//
// Each slot keeps the light of least key -log(u) / w_i (u uniform in (0, 1] from the pixel, the
// frame's seed, the light and the slot): light i holds the least key with probability w_i / W
// (exponential races), whatever order the lights come in, so the draw is the same for every
// order the lists hold them in. Needs frame_uniforms, hash and shadow_rays (through shading.glsl).
#include "include/hash.glsl"

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);  // Rec. 709
const uint kSunSampleKey = 0xFFFFFF00u;                  // + the sun's index: no light index is as large

float g_sampleKey[ML_SHADOW_SAMPLES];
vec4 g_sampleTarget[ML_SHADOW_SAMPLES];  // xyz: the light's position (w = 1), or the unit direction towards it (w = 0)
uint g_sampleSeed;

// `layer` tells apart the surfaces one pixel shades (its glass fragments: their triangles).
void beginShadowSampling(ivec2 pixel, uint layer) {
    g_sampleSeed = pcgHash(uint(pixel.x) ^ pcgHash(uint(pixel.y) ^ pcgHash(u_counts.w ^ pcgHash(layer))));
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        g_sampleKey[k] = uintBitsToFloat(0x7F800000u);  // +infinity: nothing drawn yet
        g_sampleTarget[k] = vec4(0.0);
    }
}

// Offers a light that adds `contribution` (unshadowed) to the pixel's draws.
void offerShadowSample(vec3 contribution, vec4 target, uint lightKey) {
    float w = dot(contribution, kLuminance);
    if (!(w > 0.0)) return;
    uint lightHash = pcgHash(lightKey ^ g_sampleSeed);
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        float u = 1.0 - hashToUnitFloat(lightHash + uint(k) * 0x9E3779B9u);  // (0, 1]
        float key = -log(u) / w;
        if (key < g_sampleKey[k]) {
            g_sampleKey[k] = key;
            g_sampleTarget[k] = target;
        }
    }
}

// The first slot that drew the same light as slot k (k where none before it did): a light drawn
// into two slots is traced once.
int firstSlotOfSameLight(int k) {
    int same = k;
    for (int j = k - 1; j >= 0; --j)
        if (g_sampleTarget[j] == g_sampleTarget[k]) same = j;
    return same;
}

// The share of the drawn lights that the surface point sees (1 where no light adds anything),
// traced here (the glass shading; the compute lighting leaves its rays to shadow_trace.comp). (Bit
// masks, not arrays indexed at run time: those went to local memory on the H100 and made four rays
// cost as much as every light's.)
float sampledShadowRatio(vec3 position, vec3 normal) {
    if (isinf(g_sampleKey[0])) return 1.0;
    uint blocked = 0u;
    for (int k = 0; k < ML_SHADOW_SAMPLES; ++k) {
        vec4 t = g_sampleTarget[k];
        int same = firstSlotOfSameLight(k);
        bool hidden = same < k ? ((blocked >> uint(same)) & 1u) != 0u
                               : (t.w > 0.5 ? pointLightShadowed(position, normal, t.xyz) : directionalLightShadowed(position, normal, t.xyz));
        if (hidden) blocked |= 1u << uint(k);
    }
    return float(ML_SHADOW_SAMPLES - bitCount(blocked)) * (1.0 / float(ML_SHADOW_SAMPLES));
}
