// A raster pass's program over the scene, in two variants: one for opaque draw ranges and, where
// the scene has alpha-tested materials (MASK), one that discards uncovered fragments
// (ML_ALPHA_TEST). A discard turns off early depth testing for the draws it is in, so only the
// masked ranges pay for it. SceneGpu::draw picks the variant per draw group.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "renderer/gl/program.h"

namespace ml {

class RasterProgram {
public:
    // What the pass reads of a material: all of it (shading, G-buffer), or only coverage (depth
    // pre-pass, visibility raster), which needs textures bound for the masked ranges alone.
    enum class Reads { Material, CoverageOnly };

    RasterProgram() = default;
    RasterProgram(std::string_view label, std::vector<gl::ShaderStage> stages, std::uint32_t materialFeatures, Reads reads,
                  shaders::Defines defines = {});

    const gl::Program& variant(bool alphaTested) const { return alphaTested && masked_ ? masked_ : opaque_; }
    bool readsMaterial() const { return reads_ == Reads::Material; }

private:
    gl::Program opaque_;
    gl::Program masked_;  // empty where the scene has no alpha-tested material
    Reads reads_ = Reads::Material;
};

}  // namespace ml
