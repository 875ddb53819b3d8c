// --view: what the frame shows. Values match the ML_VIEW_* constants in glsl/include/bindings.h.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glsl/include/bindings.h"

namespace ml {

enum class DebugView : std::uint32_t {
    Shaded = ML_VIEW_SHADED,
    LightCount = ML_VIEW_LIGHT_COUNT,
    Slices = ML_VIEW_SLICES,
    Clusters = ML_VIEW_CLUSTERS,
    Overflow = ML_VIEW_OVERFLOW,
    Albedo = ML_VIEW_ALBEDO,
    Normal = ML_VIEW_NORMAL,
    Depth = ML_VIEW_DEPTH,
    Overdraw = ML_VIEW_OVERDRAW,  // every method: drawn by OverdrawPass instead of the method
};

const std::vector<std::string>& debugViewNames();
DebugView parseDebugView(const std::string& text);  // throws std::invalid_argument
std::string debugViewName(DebugView view);

}  // namespace ml
