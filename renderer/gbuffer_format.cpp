#include "renderer/gbuffer_format.h"

#include <stdexcept>

#include "glsl/include/bindings.h"

namespace ml {

namespace {
struct FormatEntry {
    GBufferFormat format;
    const char* name;
    std::size_t bytesPerPixel;
};
constexpr FormatEntry kFormats[] = {
    {GBufferFormat::Standard, "standard", 24},          // 3 x RGBA16F
    {GBufferFormat::Packed, "packed", 16},              // 1 x RGBA32UI
    {GBufferFormat::TwoComponent, "two-component", 16}, // 2 x RGBA16F
    {GBufferFormat::Exact, "exact", 48},                // 3 x RGBA32F (2 without emissive or occlusion)
};

const FormatEntry& entry(GBufferFormat format) {
    for (const FormatEntry& e : kFormats)
        if (e.format == format) return e;
    throw std::invalid_argument("unhandled G-buffer format");
}
}  // namespace

const std::vector<std::string>& gbufferFormatNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const FormatEntry& e : kFormats) out.emplace_back(e.name);
        return out;
    }();
    return names;
}

GBufferFormat parseGBufferFormat(const std::string& text) {
    for (const FormatEntry& e : kFormats)
        if (text == e.name) return e.format;
    throw std::invalid_argument("--gbuffer '" + text + "': expected exact, standard, packed or two-component");
}

const char* gbufferFormatName(GBufferFormat format) { return entry(format).name; }

int gbufferExactTargets(std::uint32_t materialFeatures) {
    if (materialFeatures & ML_FEATURE_IRIDESCENCE) return 8;
    if (materialFeatures & ML_FEATURE_ANISOTROPY) return 7;
    if (materialFeatures & ML_FEATURE_SHEEN) return 6;
    if (materialFeatures & ML_FEATURE_CLEARCOAT) return 5;
    if (materialFeatures & (ML_FEATURE_SPECULAR | ML_FEATURE_UNLIT)) return 4;
    if (materialFeatures & (ML_FEATURE_EMISSIVE | ML_FEATURE_OCCLUSION_MAP)) return 3;
    return 2;
}

std::size_t gbufferBytesPerPixel(GBufferFormat format, std::uint32_t materialFeatures) {
    const std::size_t bytes = entry(format).bytesPerPixel;
    if (format == GBufferFormat::Exact) return bytes / 3 * static_cast<std::size_t>(gbufferExactTargets(materialFeatures));
    return bytes;
}

}  // namespace ml
