#include "renderer/passes/raster_floors.h"

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"

namespace ml {

const std::vector<RasterFloors::Probe>& RasterFloors::probes() {
    static const std::vector<Probe> all = {Probe::ClearDepth,      Probe::ClearIds, Probe::ClearIdsCompute,
                                           Probe::Fullscreen,      Probe::FullscreenDepth, Probe::Scene,
                                           Probe::SceneRopIds,     Probe::SceneDepthOnly,  Probe::SceneNoRaster,
                                           Probe::SceneCompute};
    return all;
}

const char* RasterFloors::name(Probe probe) {
    switch (probe) {
    case Probe::ClearDepth: return "clear-depth";
    case Probe::ClearIds: return "clear-ids";
    case Probe::Fullscreen: return "fullscreen";
    case Probe::FullscreenDepth: return "fullscreen-depth";
    case Probe::Scene: return "scene";
    case Probe::SceneDepthOnly: return "scene-depth-only";
    case Probe::SceneNoRaster: return "scene-no-raster";
    case Probe::ClearIdsCompute: return "clear-ids-compute";
    case Probe::SceneRopIds: return "scene-rop-ids";
    case Probe::SceneCompute: return "scene-compute";
    }
    return "?";
}

RasterFloors::RasterFloors(std::uint32_t materialFeatures)
    : sceneIds_("raster-floors.scene", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "visibility.frag"}}, materialFeatures,
                RasterProgram::Reads::CoverageOnly),
      sceneDepth_("raster-floors.scene-depth", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "depth_only.frag"}},
                  materialFeatures, RasterProgram::Reads::CoverageOnly),
      sceneRopIds_("raster-floors.scene-rop-ids", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "raster_floor_rop_ids.frag"}},
                   materialFeatures, RasterProgram::Reads::CoverageOnly),
      fullscreenIds_("raster-floors.fullscreen", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raster_floor_id.frag"}}),
      fullscreenDepth_("raster-floors.fullscreen-depth",
                       {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "raster_floor_depth.frag"}}),
      clearIds_(gl::Program::compute("visibility_clear_ids.comp")),
      computeRaster_(ComputeRaster::supported() ? std::make_unique<ComputeRaster>(materialFeatures, ComputeRaster::hasPackedAtomics(), ComputeRaster::Extras{})
                                                : nullptr) {
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    emptyVao_ = gl::Handle<gl::VertexArrayDeleter>(vao);
}

void RasterFloors::prepareTargets(const FrameTargets& targets) {
    if (!stamp_.update(targets)) return;
    ids_ = gl::Texture2D("raster-floors.ids", GL_R32UI, stamp_.width(), stamp_.height());
    idsFbo_ = gl::Framebuffer("raster-floors.ids", {&ids_}, &targets.depth());
    depthFbo_ = gl::Framebuffer("raster-floors.depth", {}, &targets.depth());
}

void RasterFloors::run(Probe probe, const FrameContext& ctx) {
    const SceneGpu& scene = ctx.scene;
    prepareTargets(ctx.targets);
    if (probe == Probe::ClearIdsCompute) {
        clearIds_.use();
        glBindImageTexture(ML_IMG_VISIBILITY_IDS, ids_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
        glDispatchCompute(gl::groupsFor(stamp_.width(), ML_SCREEN_TILE), gl::groupsFor(stamp_.height(), ML_SCREEN_TILE), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        return;
    }
    if (probe == Probe::SceneCompute) {
        if (!computeRaster_) return;
        // Its steps are timed inside (visibility.raster-setup, -tiles, -hardware, -finish).
        computeRaster_->run(ctx, ids_);
        ctx.targets.setComputedDepth(nullptr);
        return;
    }
    // The scene probe draws its opaque ranges into depth alone (ids by atomics), the rest as it says.
    const bool depthOnly = probe == Probe::FullscreenDepth || probe == Probe::SceneDepthOnly || probe == Probe::Scene;
    const gl::Framebuffer& fbo = depthOnly ? depthFbo_ : idsFbo_;
    fbo.bind();
    glViewport(0, 0, stamp_.width(), stamp_.height());
    if (probe == Probe::ClearIds) {
        const GLuint background = 0;
        glClearNamedFramebufferuiv(fbo.id(), GL_COLOR, 0, &background);
        return;
    }
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &depth::kClear);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth::kNearer);
    glDepthMask(GL_TRUE);
    switch (probe) {
    case Probe::ClearDepth:
    case Probe::ClearIds:
    case Probe::ClearIdsCompute:
    case Probe::SceneCompute: break;
    case Probe::Fullscreen:
    case Probe::FullscreenDepth:
        (probe == Probe::Fullscreen ? fullscreenIds_ : fullscreenDepth_).use();
        glBindVertexArray(emptyVao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        break;
    case Probe::Scene:
        glBindImageTexture(ML_IMG_VISIBILITY_IDS, ids_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
        scene.draw(sceneIds_, SceneGpu::Ranges::Opaque);
        glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT);
        idsFbo_.bind();
        scene.draw(sceneIds_, SceneGpu::Ranges::AlphaTested);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        break;
    case Probe::SceneRopIds: scene.draw(sceneRopIds_); break;
    case Probe::SceneDepthOnly: scene.draw(sceneDepth_); break;
    case Probe::SceneNoRaster:
        glEnable(GL_RASTERIZER_DISCARD);
        scene.draw(sceneIds_);
        glDisable(GL_RASTERIZER_DISCARD);
        break;
    }
    glBindVertexArray(0);
}

}  // namespace ml
