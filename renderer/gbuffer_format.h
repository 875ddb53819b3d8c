// The G-buffer layouts of --gbuffer. One enum, its names, and the bytes each stores per pixel
// (glsl/include/gbuffer_layout.glsl encodes and decodes them; bindings.h numbers them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ml {

enum class GBufferFormat {
    Standard,      // three RGBA16F targets: normal, albedo, specular parameters
    Packed,        // one RGBA32UI target: octahedral normal, albedo RGBA8, specular 2 x half
    TwoComponent,  // two RGBA16F targets; the normal's z is rebuilt as +sqrt: the documented failure case
    Exact,         // two or three RGBA32F targets: ray distance, normal, material as shaded; lossless
};

const std::vector<std::string>& gbufferFormatNames();
GBufferFormat parseGBufferFormat(const std::string& text);  // throws std::invalid_argument naming the value
const char* gbufferFormatName(GBufferFormat format);
// Colour bytes per pixel for a scene whose materials use materialFeatures (the ML_FEATURE_* bits):
// the exact layout keeps emissive and occlusion in a third target only where the scene has them.
// Depth is the frame's own depth buffer, counted with the frame targets.
std::size_t gbufferBytesPerPixel(GBufferFormat format, std::uint32_t materialFeatures);
// The exact layout's targets for these materials (gbuffer_layout.glsl): 2, a third where the scene
// has emissive or occlusion maps, a fourth (and the third) where it has KHR_materials_specular, ior
// or unlit, a fifth (and the others) where it has KHR_materials_clearcoat, a sixth (and the others)
// where it has KHR_materials_sheen, a seventh (and the others) where it has KHR_materials_anisotropy,
// eight where it has KHR_materials_iridescence.
int gbufferExactTargets(std::uint32_t materialFeatures);

}  // namespace ml
