// The visibility buffer's compute raster (--vis-raster compute): the opaque triangles rastered by
// compute shaders instead of the graphics units, which on an H100 (few of them, 132 SMs) cannot
// write a depth-tested pixel faster than a floor the scene's raster already sits on
// (`manylights raster-floors`, docs/benchmarks.md).
//
//   setup (a thread per triangle) ──small──> rastered there, pixel by pixel
//        │                         ──large──> binning ──> tile pass (a workgroup per triangle and 16x16 tile)
//        │                         ──large, a few 8x8 tiles──> binned there ──> tile pass
//        └─ a vertex at or behind the eye plane, or past the guard band ──> the tile pass, as homogeneous edge planes
//           (on a GPU that clips at the viewport, as llvmpipe does: the hardware, into the same store)
//   alpha-tested ranges, a setup per texture set ──small──> rastered there, each pixel alpha-tested
//        │                                        ──large──> their own binning and tile pass (per set)
//        └─ across the eye plane or past the guard band ──> the hardware, per set, into the same store
//   finish: the store ──> the id target (index + 1) and an R32F depth, the undrawn pixels emptied;
//           for fitted slicing, the least and greatest view depth drawn (cluster.depth-range then
//           reduces nothing)
//
// Which pixels a triangle covers and at what depth follows the hardware's rules (snapped
// vertices, the fill rule, the depth plane; glsl/include/compute_raster.glsl), so the ids equal
// the hardware raster's but where two surfaces tie in depth. The store resolves nearest depth,
// then smallest id (the first drawn, as GL_LESS keeps) by one 64-bit atomicMin where the GPU has
// GL_NV_shader_atomic_int64, or by two passes of 32-bit atomics (depth, then id) where it has not,
// as on Mesa's llvmpipe, so the tests run the same raster. The store is not reset between frames:
// every other frame inverts its words and resolves by atomicMax, and the finish empties only the
// pixels a frame left (include/compute_raster.glsl).
//
// The depth is a colour target, which the passes that sample depth read (FrameTargets::opaqueDepth);
// the glass's capture tests against it in its fragment shader; for the passes that depth-test the
// glass in hardware it is copied into the depth buffer over the glass's screen bounds alone.
#pragma once

#include <cstdint>
#include <string>

#include "glsl/include/bindings.h"
#include "renderer/frame_context.h"
#include "renderer/frame_targets_stamp.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/methods/visibility_raster.h"

namespace ml {


class ComputeRaster {
public:
    // What this GPU can run: the compute raster needs GL_ARB_gpu_shader_int64 (its edges), and
    // resolves in one pass with GL_NV_shader_atomic_int64.
    static bool supported();
    static bool hasPackedAtomics();
    // The raster `choice` runs on this GPU: Auto and Compute resolved. Throws
    // std::invalid_argument naming the flag where this GPU cannot run the compute raster.
    static VisibilityRaster resolve(VisibilityRaster choice);

    // What a frame's later passes need of the raster besides the ids and depth().
    struct Extras {
        // Fitted slicing: the drawn pixels' view depth range, reduced by the finish
        // (FrameTargets::opaqueViewDepthRange), so that cluster.depth-range reads no depth.
        bool viewDepthRange = false;
        // Passes that depth-test the glass in hardware (--active-only and --normal-cones mark its
        // samples): the depth copied into the depth buffer under the glass. The glass's capture
        // tests against depth() itself.
        bool depthUnderGlass = false;
    };
    ComputeRaster(std::uint32_t materialFeatures, bool packedAtomics, Extras extras);

    // Rasters the scene's opaque and alpha-tested ranges into `ids` (triangle index + 1, 0 where
    // nothing is) and depth(), and what `extras` asks for. Sets ctx.targets' opaque depth to
    // depth(), and its view depth range where asked.
    void run(const FrameContext& ctx, const gl::Texture2D& ids);
    const gl::Texture2D& depth() const { return depth_; }
    // Whether triangles that cross the viewport's sides or the eye plane go to the hardware (set
    // from the GPU: Mesa's software rasterizers clip at the viewport). Tests turn it off on
    // llvmpipe to run the homogeneous path.
    void setClipsToViewport(bool clips) { clipsToViewport_ = clips; }

    // Where the last frame's triangles went (a GPU read; --stats, tests): the rest of the opaque
    // ones were rastered by the setup pass, or culled.
    struct Work {
        std::uint32_t opaqueTriangles = 0;
        std::uint32_t large = 0;     // to the tile pass
        std::uint32_t setupBinned = 0;  // of them, binned by their setup invocation (ML_RASTER_SETUP_BIN_TILES)
        std::uint32_t clipped = 0;   // to the tile pass as homogeneous planes (crossing the eye plane, past the guard band)
        std::uint32_t tiles = 0;     // (triangle, tile) pairs the tile pass ran
        std::uint32_t fineTiles = 0; // of them, 8x8 tiles (ML_RASTER_FINE_EXTENT)
        std::uint32_t hardware = 0;  // to the hardware (crossing the viewport where the GPU clips there, or past the lists)
        std::uint32_t alphaTested = 0;       // the alpha-tested triangles, of which
        std::uint32_t alphaLarge = 0;        // to their tile pass
        std::uint32_t alphaTiles = 0;        // (triangle, tile) pairs it ran
        std::uint32_t alphaFineTiles = 0;    // of them, 8x8 tiles
        std::uint32_t alphaHardware = 0;     // to the hardware (across the eye plane, or past the lists)
    };
    Work lastWork() const;

private:
    void prepare(const FrameContext& ctx);
    void rasterPass(const FrameContext& ctx, int pass);
    void setupAlphaTested(const FrameContext& ctx, int pass);
    void binAlphaTested(const FrameContext& ctx);
    void tileAlphaTested(const FrameContext& ctx, int pass);
    void drawAlphaTestedOnHardware(const FrameContext& ctx, int pass);
    void finish(const FrameContext& ctx, const gl::Texture2D& ids);
    void copyDepthUnderGlass(const FrameContext& ctx);

    bool packed_;
    Extras extras_;
    int passes_;
    bool clipsToViewport_;
    gl::Program setup_[2], tiles_[2], bin_, finish_, depthCopy_;
    gl::Program hardwareList_[2];
    gl::Program alphaSetup_[2], alphaTiles_[2], alphaBin_, alphaHardwareList_[2];  // where the scene has alpha-tested materials
    gl::Handle<gl::VertexArrayDeleter> emptyVao_;
    gl::Buffer store_, work_, large_, pairs_, alphaPairs_, hardware_, clipped_;
    std::size_t largeCapacity_ = 0, pairCapacity_ = 0, alphaPairCapacity_ = 0;
    gl::Texture2D depth_;
    gl::Framebuffer depthFbo_;
    FrameTargetsStamp stamp_;
    std::size_t sceneTriangles_ = 0;
    std::uint32_t opaqueTriangles_ = 0;
    std::uint32_t alphaTestedTriangles_ = 0;
    GLuint storeFlip_ = 0;  // u_storeFlip: 0, or ~0u on every other frame
    std::size_t workWords_ = ML_RASTER_WORK_WORDS;  // and a draw command per alpha-tested span
};

}  // namespace ml
