#version 450 core
// --shadows sampled, temporal reuse (--shadow-reuse temporal): each pixel's ratio joins the ratio it
// held in the previous frames, found by reprojecting its world position with the previous frame's
// view and projection (camera motion) and kept only where the previous frame's guide shows the same
// surface there (disocclusion, and surfaces that moved: an animated file's pose). The new ratio is
// averaged in with weight 1 / frames held, up to kMaxHistoryFrames (an exponential average from
// there), so a still view converges on the exact ratio.
//
// A shadow that moves with its light leaves a history that the new rays contradict. The history is
// held to the mean of the pixel's 5x5 neighbours on its surface, plus or minus their spread
// (variance clipping, Salvi 2016), the spread floored at kMinSpread (a few rays a pixel give
// neighbourhoods of all ones where the true ratio is 0.95, and a clip to those alone would pull
// every history towards lit), the window stretched to take in the pixel's own new ratio. Where the
// clip moves the history, the frames it holds drop to kFramesAfterClip, so the ratio catches up in a few frames rather than thirty. A ratio that every
// neighbour shares (0 or 1: lit, or in shadow) passes through exactly.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"
#include "include/octahedral.glsl"
#include "include/shadow_guide.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_SHADOW_LIGHT) uniform sampler2D u_shadowLight;
layout(binding = ML_TEX_SHADOW_GUIDE) uniform sampler2D u_guide;
layout(binding = ML_TEX_SHADOW_GUIDE_PREVIOUS) uniform sampler2D u_previousGuide;
layout(binding = ML_TEX_SHADOW_HISTORY) uniform sampler2D u_previousHistory;
layout(binding = ML_IMG_SHADOW_HISTORY, rg32f) uniform writeonly image2D u_history;
uniform mat4 u_previousViewProj;
uniform uint u_hasHistory;  // 0 on the first frame, or after the targets changed size
uniform float u_maxHistoryFrames;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(u_viewport.xy);
    if (any(greaterThanEqual(p, size))) return;
    float ratio = texelFetch(u_shadowLight, p, 0).a;
    if (ratio < 0.0) {  // no surface
        imageStore(u_history, p, vec4(1.0, 0.0, 0.0, 0.0));
        return;
    }
    ShadowGuide g = readShadowGuide(u_guide, p);

    // The neighbourhood's mean and spread on this surface.
    float sum = 0.0, sumSquares = 0.0, count = 0.0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
            ivec2 q = p + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            float r = texelFetch(u_shadowLight, q, 0).a;
            if (r < 0.0 || !sameShadowSurface(g, readShadowGuide(u_guide, q))) continue;
            sum += r;
            sumSquares += r * r;
            count += 1.0;
        }
    const float kMinSpread = 0.5, kFramesAfterClip = 4.0;
    float mean = count > 0.0 ? sum / count : ratio;  // none where the guide is not finite
    float spread = max(sqrt(max(sumSquares / max(count, 1.0) - mean * mean, 0.0)), kMinSpread);
    // The window reaches the pixel's own ratio too: a pixel that a close light outshines in its
    // neighbourhood (a bright spot whose neighbours are in shadow) keeps its own history.
    float lo = min(mean - spread, ratio), hi = max(mean + spread, ratio);

    float held = 0.0, reused = ratio;
    vec4 clip = u_previousViewProj * vec4(g.position, 1.0);
    if (u_hasHistory != 0u && clip.w > 0.0) {
        vec2 window = (clip.xy / clip.w * 0.5 + 0.5) * u_viewport.xy;
        ivec2 q = ivec2(floor(window));
        if (all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size))) {
            vec2 history = texelFetch(u_previousHistory, q, 0).rg;
            if (history.g > 0.0 && sameShadowSurface(g, readShadowGuide(u_previousGuide, q))) {
                held = history.g;
                reused = clamp(history.r, lo, hi);
                if (reused != history.r) held = min(held, kFramesAfterClip);
            }
        }
    }
    float frames = min(held + 1.0, u_maxHistoryFrames);
    // reused + (ratio - reused) / frames: exactly `ratio` where the two agree.
    imageStore(u_history, p, vec4(reused + (ratio - reused) / frames, frames, 0.0, 0.0));
}
