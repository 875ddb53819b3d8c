#include "renderer/methods/clustered_deferred.h"

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"
#include "renderer/methods/deferred_lighting.h"

namespace ml {

namespace {
gl::Program lightingProgram(Resolve resolve, const shaders::Defines& defines) {
    if (resolve == Resolve::Compute) return gl::Program::compute("deferred_lighting.comp", defines);
    return gl::Program("deferred.lighting", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "deferred_lighting.frag"}},
                       defines);
}
}  // namespace

ClusteredDeferred::ClusteredDeferred(const ClusteringSettings& settings, Resolve resolve, GBufferFormat gbuffer, bool prepass,
                                     std::uint32_t materialFeatures, const TransparencySettings& transparency)
    : resolve_(resolve),
      prepass_(prepass),
      gbuffer_(gbuffer, materialFeatures),
      depthPrePass_("deferred.depth", materialFeatures),
      gbufferProgram_("deferred.gbuffer", {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "gbuffer.frag"}},
                      materialFeatures, RasterProgram::Reads::Material, gbuffer_.defines()),
      lightingProgram_(lightingProgram(resolve, deferredLightingDefines(settings, gbuffer_))),
      clustering_(settings, materialFeatures, gbuffer_.defines()),
      transparent_(TransparentPass::overClusterLists("deferred.transparent", materialFeatures, settings, transparency)) {
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    emptyVao_ = gl::Handle<gl::VertexArrayDeleter>(vao);
    gl::label(GL_VERTEX_ARRAY, vao, "fullscreen.vao");
}

void ClusteredDeferred::render(const FrameContext& ctx) {
    const gl::Framebuffer& fbo = gbuffer_.prepare(ctx.targets);
    glViewport(0, 0, ctx.targets.width(), ctx.targets.height());
    if (prepass_) {
        auto pass = ctx.timer.pass("deferred.depth-prepass");
        depthPrePass_.drawDepth(ctx.scene, fbo);
    }
    {
        auto pass = ctx.timer.pass("deferred.gbuffer");
        fbo.bind();
        // No colour clear: every reader of the G-buffer takes the cleared depth as background
        // (deferred_resolve.glsl, the normal bins), and a colour clear costs as much as a
        // full-screen layer of writes on an H100.
        if (prepass_) {
            // Each pixel's surface is rebuilt and written once, not once per fragment of overdraw.
            DepthPrePass::drawNearestOnce(ctx.scene, gbufferProgram_);
        } else {
            depth::beginNearestDepth(fbo.id());
            ctx.scene.draw(gbufferProgram_);
        }
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    // The depth is final: the glass is counted now, its total long known when the fill needs it.
    transparent_.countFragments(ctx, clustering_.settings().view);
    clustering_.build(ctx, &gbuffer_);
    {
        auto pass = ctx.timer.pass(resolve_ == Resolve::Compute ? "deferred.lighting-compute" : "deferred.lighting-fragment");
        bindDeferredLightingInputs(gbuffer_, ctx, clustering_);
        lightingProgram_.use();
        if (resolve_ == Resolve::Compute) {
            dispatchComputeLighting(ctx);
        } else {
            // Colour only: the depth texture is read, so it must not be attached while drawing.
            ctx.targets.hdrOnlyFramebuffer().bind();
            glDisable(GL_DEPTH_TEST);
            glBindVertexArray(emptyVao_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glEnable(GL_DEPTH_TEST);
        }
    }
    // The fragment resolve traces the exact rays (only the compute lighting samples).
    if (resolve_ == Resolve::Compute) applySampledShadows(ctx, clustering_.settings());
    transparent_.render(ctx, &clustering_);
}

}  // namespace ml
