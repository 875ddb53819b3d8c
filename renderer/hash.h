// Mirrors glsl/include/hash.glsl, so the CPU can reproduce what the shaders derive from an index.
#pragma once

#include <cstdint>

namespace ml {

constexpr std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// In [0, 1), from the top 24 bits so the conversion to float is exact.
constexpr float hashToUnitFloat(std::uint32_t v) { return static_cast<float>(pcgHash(v) >> 8u) * (1.0f / 16777216.0f); }

}  // namespace ml
