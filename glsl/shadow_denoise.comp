#version 450 core
// --shadows sampled, the last pass: the ratio filtered over the pixel's neighbours on its surface
// (--shadow-denoise on) and multiplied into the lights' part of the unshadowed frame,
//   hdr = unlit + ratio * lights  =  hdr_unshadowed + (ratio - 1) * lights.
// As Heitz, Hill and McGuire (2018) filter it: the shadowed and the unshadowed light are filtered
// apart, each neighbour's ratio weighted by its own unshadowed luminance, and divided, so a
// neighbour that little light reaches says little about the pixel. The weights fall off as a
// Gaussian of the distance in pixels, narrower as the pixel's reused history grows (the history
// has averaged its noise already), and are zero across an edge in depth or normal
// (shadow_guide.glsl). Where every neighbour shares one ratio (0 or 1), the two sums are the same
// numbers summed alike, so the pixel keeps that ratio exactly: a frame with nothing in the way is
// the unshadowed frame, bit for bit.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/octahedral.glsl"
#include "include/shadow_guide.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_SHADOW_LIGHT) uniform sampler2D u_shadowLight;
layout(binding = ML_TEX_SHADOW_GUIDE) uniform sampler2D u_guide;
layout(binding = ML_TEX_SHADOW_HISTORY) uniform sampler2D u_history;
layout(binding = ML_IMG_HDR, rgba32f) uniform image2D u_hdr;
uniform uint u_reused;    // 1: the ratio is the temporal pass's (u_history); 0: this frame's rays alone
uniform int u_radius;     // the filter's reach in pixels; 0: no filter
const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);  // as shadow_sampling.glsl draws by

// The ratio at q and the frames it holds.
vec2 ratioAt(ivec2 q, vec4 light) { return u_reused != 0u ? texelFetch(u_history, q, 0).rg : vec2(light.a, 1.0); }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(u_viewport.xy);
    if (any(greaterThanEqual(p, size))) return;
    vec4 light = texelFetch(u_shadowLight, p, 0);
    if (light.a < 0.0) return;  // no surface
    vec2 centre = ratioAt(p, light);
    float ratio = centre.x;
    if (u_radius > 0) {
        ShadowGuide g = readShadowGuide(u_guide, p);
        float sigma = clamp(2.0 * inversesqrt(max(centre.y, 1.0)), 0.3, 2.0);
        float falloff = -0.5 / (sigma * sigma);
        float shadowed = 0.0, unshadowed = 0.0;
        for (int dy = -u_radius; dy <= u_radius; ++dy)
            for (int dx = -u_radius; dx <= u_radius; ++dx) {
                ivec2 q = p + ivec2(dx, dy);
                if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
                vec4 neighbour = texelFetch(u_shadowLight, q, 0);
                if (neighbour.a < 0.0 || !sameShadowSurface(g, readShadowGuide(u_guide, q))) continue;
                float w = exp(falloff * float(dx * dx + dy * dy)) * dot(neighbour.rgb, kLuminance);
                shadowed += w * ratioAt(q, neighbour).x;
                unshadowed += w;
            }
        if (unshadowed > 0.0) ratio = shadowed / unshadowed;
    }
    if (ratio != 1.0) imageStore(u_hdr, p, imageLoad(u_hdr, p) + vec4((ratio - 1.0) * light.rgb, 0.0));
}
