// --light-sum: how a shaded point adds up the contributions of its point and spot lights
// (glsl/include/light_sum.glsl says how each sum is kept).
#pragma once

#include <string>
#include <utility>

namespace ml {

// The fixed sum spends a conversion and three 64-bit adds on every light a point shades, and
// saves the sort of every list. On an H100 (docs/bench/nvidia-h100/light-sum) that paid only at
// 4,194,304 lights (3840x2160: 8.02-8.94 ms a frame against 8.64-9.65); at 1,048,576 it broke
// even, and at 65,536, for Forward+ (whose fragments shade every light of their lists) and for
// the gas station's glass it cost more than the sort. So float is the default.
enum class LightSum {
    Float,  // float: order changes the last bits, so every list is sorted by light index (assign.sort)
    Fixed,  // 64-bit fixed point: the same bits in any order, so the lists are not sorted
};
LightSum parseLightSum(const std::string& text);  // throws std::invalid_argument naming --light-sum
const char* lightSumName(LightSum sum);

// Throws std::invalid_argument, naming the flag, for Fixed on a GPU without 64-bit integers
// (GL_ARB_gpu_shader_int64).
void checkLightSumSupported(LightSum sum);

// ML_FIXED_LIGHT_SUM for the programs that shade lights.
std::pair<std::string, std::string> lightSumDefine(LightSum sum);

}  // namespace ml
