// The costs that bound the visibility raster, each measured on its own (`manylights
// raster-floors`): the clears of depth and of the id target; a full-screen triangle writing what
// the pass writes (depth and an R32UI id) and depth alone, which is the pixel floor; the scene
// drawn as the pass draws it, with depth alone, and with rasterization discarded (vertex and
// primitive work only); and the compute raster (--vis-raster compute), which leaves the graphics
// units for the SMs. Every probe but clear-ids clears depth alone, as the pass does.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/frame_context.h"
#include "renderer/frame_targets.h"
#include "renderer/frame_targets_stamp.h"
#include "renderer/gl/framebuffer.h"
#include "renderer/gl/program.h"
#include "renderer/gl/texture.h"
#include "renderer/passes/compute_raster.h"
#include "renderer/scene/raster_program.h"
#include "renderer/scene/scene_gpu.h"

namespace ml {

class RasterFloors {
public:
    enum class Probe {
        ClearDepth,       // depth cleared, nothing drawn
        ClearIds,         // the id target cleared by the ROPs, nothing drawn
        ClearIdsCompute,  // the id target cleared by a compute pass (what the pass does)
        Fullscreen,       // + one full-screen triangle: depth and an id colour output at every pixel
        FullscreenDepth,  // + one full-screen triangle, depth alone
        Scene,            // the visibility raster's draws: ids by image atomics (without its clear)
        SceneRopIds,      // the same draws writing ids through the ROPs, as the pass did before
        SceneDepthOnly,   // the same draws with depth alone (no colour target, empty shader)
        SceneNoRaster,    // the same draws with GL_RASTERIZER_DISCARD: vertices and primitives only
        SceneCompute,     // the compute raster of the same ranges, ids and depth (where the GPU runs it)
    };
    static const std::vector<Probe>& probes();
    static const char* name(Probe probe);  // "clear", "fullscreen", ...

    explicit RasterFloors(std::uint32_t materialFeatures);

    // Whether this GPU runs the probe (the compute raster needs 64-bit integers).
    bool supports(Probe probe) const { return probe != Probe::SceneCompute || computeRaster_; }
    // Runs one probe into the frame's depth and its own id target (the frame uniforms bound); a
    // probe the GPU does not support runs nothing.
    void run(Probe probe, const FrameContext& ctx);

private:
    void prepareTargets(const FrameTargets& targets);

    RasterProgram sceneIds_, sceneDepth_, sceneRopIds_;
    gl::Program fullscreenIds_, fullscreenDepth_, clearIds_;
    std::unique_ptr<ComputeRaster> computeRaster_;  // null where the GPU has no 64-bit integers
    gl::Handle<gl::VertexArrayDeleter> emptyVao_;
    gl::Texture2D ids_;
    gl::Framebuffer idsFbo_, depthFbo_;
    FrameTargetsStamp stamp_;
};

}  // namespace ml
