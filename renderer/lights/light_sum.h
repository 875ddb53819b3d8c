// --light-sum: how a shaded point adds up the contributions of its point and spot lights
// (glsl/include/light_sum.glsl says how each sum is kept).
#pragma once

#include <string>
#include <utility>

namespace ml {

enum class LightSum {
    Auto,   // fixed where the lights are shaded in a compute pass and the GPU has 64-bit integers, else float
    Fixed,  // 64-bit fixed point: the same bits in any order, so the lists are not sorted
    Float,  // float: order changes the last bits, so every list is sorted by light index (assign.sort)
};
LightSum parseLightSum(const std::string& text);  // throws std::invalid_argument naming --light-sum
const char* lightSumName(LightSum sum);

// Auto made Fixed or Float for a method and the current GL context. The fixed sum costs each
// light's shading a conversion and three 64-bit adds and saves the sort of every list; on an H100
// (docs/bench/nvidia-h100/light-sum) that paid where a compute pass lights the frame (deferred,
// the visibility buffer: 0.15-0.34 ms less a frame at 1M lights, 1.0-1.3 ms at 4M, even at 65,536)
// and cost Forward+, whose fragments shade every light of their lists, 15-25 % more a frame. So
// Auto is Fixed for `computeLighting` methods alone. Throws std::invalid_argument for Fixed on a
// GPU without 64-bit integers.
LightSum resolveLightSum(LightSum sum, bool computeLighting);

// ML_FIXED_LIGHT_SUM for the programs that shade lights; `sum` resolved (Auto throws std::logic_error).
std::pair<std::string, std::string> lightSumDefine(LightSum sum);

}  // namespace ml
