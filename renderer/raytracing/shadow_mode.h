// --shadows: whether a light stops at what stands between it and the point it lights.
//   off      lights reach every point in their range (the model before issue 62)
//   rays     an exact shadow ray for every (point, light) pair that adds light, in every method,
//            naive tracing the same rays (glsl/include/shadow_rays.glsl)
//   sampled  the compute lighting of deferred and the visibility buffer sums every light
//            unshadowed and traces a few rays a pixel to lights drawn by their light, then reuses
//            and filters the visibility ratio they measure (sampled_shadows.h, issue 63); every
//            other pass (naive, Forward+, the fragment resolve, glass) traces the exact rays
#pragma once

#include <cstdint>
#include <string>

namespace ml {

enum class Shadows { Off, Rays, Sampled };

const char* shadowsName(Shadows shadows);
// "off", "rays" or "sampled"; anything else throws std::invalid_argument naming --shadows.
Shadows parseShadows(const std::string& text);

// --shadows sampled's estimate: rays a pixel, and what reuses and filters their ratio.
struct SampledShadowSettings {
    std::uint32_t raysPerPixel = 2;  // --shadow-rays-per-pixel: 1, 2 or 4
    bool temporal = true;            // --shadow-reuse temporal|none: the ratio averaged over past frames
    bool denoise = true;             // --shadow-denoise on|off: the ratio filtered over its neighbours
    bool operator==(const SampledShadowSettings&) const = default;
};

// 1, 2 or 4; anything else throws std::invalid_argument naming --shadow-rays-per-pixel.
std::uint32_t checkShadowRaysPerPixel(int rays);

}  // namespace ml
