#include "renderer/lights/light_sum.h"

#include <stdexcept>

#include "renderer/gl/extensions.h"

namespace ml {

namespace {
constexpr const char* kInt64Extension = "GL_ARB_gpu_shader_int64";
}

LightSum parseLightSum(const std::string& text) {
    if (text == "auto") return LightSum::Auto;
    if (text == "fixed") return LightSum::Fixed;
    if (text == "float") return LightSum::Float;
    throw std::invalid_argument("--light-sum '" + text + "': expected auto, fixed or float");
}

const char* lightSumName(LightSum sum) {
    switch (sum) {
    case LightSum::Auto: return "auto";
    case LightSum::Fixed: return "fixed";
    case LightSum::Float: return "float";
    }
    return "?";
}

LightSum resolveLightSum(LightSum sum, bool computeLighting) {
    const bool int64 = gl::hasExtension(kInt64Extension);
    if (sum == LightSum::Auto) return int64 && computeLighting ? LightSum::Fixed : LightSum::Float;
    if (sum == LightSum::Fixed && !int64)
        throw std::invalid_argument(std::string("--light-sum fixed: this GPU lacks ") + kInt64Extension + "; use --light-sum float");
    return sum;
}

std::pair<std::string, std::string> lightSumDefine(LightSum sum) {
    if (sum == LightSum::Auto) throw std::logic_error("lightSumDefine: --light-sum auto not resolved (createMethod resolves it)");
    return {"ML_FIXED_LIGHT_SUM", sum == LightSum::Fixed ? "1" : "0"};
}

}  // namespace ml
