// A depth pre-pass, and the raster after it that lets each pixel's nearest fragment through
// once: Forward+ shades that way, and deferred writes its G-buffer that way, so neither pays its
// per-fragment work (shading, or rebuilding the surface and writing 16-48 bytes) on overdraw.
//
//   drawDepth:       depth only, nearest kept (alpha-tested ranges discard as the later pass does);
//                    stencil cleared to 0
//   drawNearestOnce: depth EQUAL, no depth writes; the stencil lets a pixel's first passing
//                    fragment through and counts it, so later ones at the same depth fail
//
// scene.vert's gl_Position is invariant, so both passes compute the same depth for a fragment
// and exactly the nearest surface passes EQUAL. Where two surfaces tie in depth, the stencil
// keeps the first drawn, as a single depth-tested pass (GREATER, depth_convention.h) does: the
// frame is bit for bit the one-pass frame. The framebuffer's depth needs a stencil
// (ShadingMethod::needsStencil).
#pragma once

#include <cstdint>
#include <string_view>

#include "renderer/gl/framebuffer.h"
#include "renderer/scene/raster_program.h"
#include "renderer/scene/scene_gpu.h"

namespace ml {

class DepthPrePass {
public:
    // label: the depth program's, as a capture tool shows it (e.g. "deferred.depth").
    DepthPrePass(std::string_view label, std::uint32_t materialFeatures);

    // Binds fbo, clears its depth and stencil and draws the scene's depth alone; the caller sets
    // the viewport and times the pass. Leaves the depth test on (nearer passes) with writes on.
    void drawDepth(const SceneGpu& scene, const gl::Framebuffer& fbo) const;

    // Draws program over the scene into the bound framebuffer, whose depth drawDepth wrote: each
    // pixel's first nearest fragment alone passes. Restores the depth state drawDepth left.
    static void drawNearestOnce(const SceneGpu& scene, const RasterProgram& program);

private:
    RasterProgram depthProgram_;
};

}  // namespace ml
