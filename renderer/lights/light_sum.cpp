#include "renderer/lights/light_sum.h"

#include <stdexcept>

#include "renderer/gl/extensions.h"

namespace ml {

namespace {
constexpr const char* kInt64Extension = "GL_ARB_gpu_shader_int64";
}

LightSum parseLightSum(const std::string& text) {
    if (text == "float") return LightSum::Float;
    if (text == "fixed") return LightSum::Fixed;
    throw std::invalid_argument("--light-sum '" + text + "': expected float or fixed");
}

const char* lightSumName(LightSum sum) { return sum == LightSum::Fixed ? "fixed" : "float"; }

void checkLightSumSupported(LightSum sum) {
    if (sum == LightSum::Fixed && !gl::hasExtension(kInt64Extension))
        throw std::invalid_argument(std::string("--light-sum fixed: this GPU lacks ") + kInt64Extension + "; use --light-sum float");
}

std::pair<std::string, std::string> lightSumDefine(LightSum sum) {
    return {"ML_FIXED_LIGHT_SUM", sum == LightSum::Fixed ? "1" : "0"};
}

}  // namespace ml
