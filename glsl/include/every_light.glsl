// The sum of every light of the frame, in index order: naive's loop, and Forward+'s for a
// fragment whose cluster list was skipped (glsl/forward_plus.frag, --msaa with --active-only).
// Needs lights.glsl and shading.glsl.
#include "include/light_sum.glsl"

vec3 shadeEveryLight(SurfacePoint s, vec3 viewDir) {
    uint n = lightCount();
    LightSum sum = noLight();
    for (uint i = 0u; i < n; ++i) {
        Light l = lights[i];
        vec3 c = shadeLight(s, viewDir, l.positionRadius, l.colorCosInner, lightCone(i));
        addLight(sum, c);
        ML_OFFER_SHADOW_SAMPLE(c, vec4(l.positionRadius.xyz, 1.0), i);
    }
    return lightSumValue(sum);
}
