#include "renderer/scene/raster_program.h"

#include <algorithm>
#include <string>

#include "glsl/include/bindings.h"
#include "renderer/scene/material_features.h"

namespace ml {

RasterProgram::RasterProgram(std::string_view label, std::vector<gl::ShaderStage> stages, std::uint32_t materialFeatures,
                             Reads reads, shaders::Defines defines)
    : reads_(reads) {
    // G-buffer writers get the features through GBuffer::defines() already.
    const bool given = std::any_of(defines.begin(), defines.end(), [](const auto& d) { return d.first == "ML_MATERIAL_FEATURES"; });
    if (!given) {
        const shaders::Defines features = materialFeatureDefines(materialFeatures);
        defines.insert(defines.end(), features.begin(), features.end());
    }
    opaque_ = gl::Program(label, stages, defines);
    if (materialFeatures & ML_FEATURE_ALPHA_TEST) {
        defines.emplace_back("ML_ALPHA_TEST", "1");
        masked_ = gl::Program(std::string(label) + ".alpha-tested", stages, defines);
    }
}

}  // namespace ml
