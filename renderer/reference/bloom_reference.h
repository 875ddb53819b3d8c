// CPU mirror of the bloom (renderer/passes/bloom_pass.h, glsl/bloom_*.comp) for the tests: the same
// bright pass, 2x2 downsample, separable Gaussian and hand-made bilinear upsample, in the same
// order of operations.
#pragma once

#include <glm/glm.hpp>

#include "renderer/passes/bloom_pass.h"
#include "renderer/image/image.h"

namespace ml {

glm::vec3 bloomBrightPart(glm::vec3 color, float threshold);  // glsl/include/bloom.glsl

// `hdr` with its bloom added, as BloomPass leaves the HDR target (rows top to bottom, as
// FrameRenderer::readHdr gives them).
FloatImage bloomReference(const FloatImage& hdr, const BloomSettings& settings);

}  // namespace ml
