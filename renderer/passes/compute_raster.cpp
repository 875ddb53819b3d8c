#include "renderer/passes/compute_raster.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <vector>

#include "glsl/include/bindings.h"
#include "renderer/gl/depth_convention.h"
#include "renderer/gl/extensions.h"
#include "renderer/gl/scissor_scope.h"
#include "renderer/scene/material_features.h"

namespace ml {

namespace {

// Which fill rule this GPU's rasterizer applies, in GL's y-up window coordinates: 0 owns top and
// left edges, 1 bottom and left ones. Found once a process (one GPU) by drawing a rectangle whose
// horizontal edges run through pixel centres and reading back which of them it covered.
int hardwareEdgeRule() {
    static const int rule = [] {
        GLuint texture = 0, fbo = 0, vao = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, GL_R8, 4, 4);
        glCreateFramebuffers(1, &fbo);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture, 0);
        glCreateVertexArrays(1, &vao);
        const gl::Program probe("compute-raster.edge-rule", {{GL_VERTEX_SHADER, "compute_raster_edge_rule.vert"},
                                                             {GL_FRAGMENT_SHADER, "compute_raster_edge_rule.frag"}});
        GLint previousFbo = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFbo);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, 4, 4);
        const GLfloat zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        probe.use();
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, 6);
        std::uint8_t pixels[16] = {};  // 4-byte rows: the default pack alignment holds
        glGetTextureImage(texture, 0, GL_RED, GL_UNSIGNED_BYTE, sizeof pixels, pixels);
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFbo));
        glDeleteVertexArrays(1, &vao);
        glDeleteFramebuffers(1, &fbo);
        glDeleteTextures(1, &texture);
        // The probe's rectangle spans pixel centres y = 1.5 to 2.5 across column 1: its bottom
        // edge runs through row 1's centre, its top edge through row 2's.
        return pixels[1 * 4 + 1] != 0 ? 1 : 0;
    }();
    return rule;
}

// Mesa's software rasterizers clip every triangle at the viewport's sides (its draw module has
// no guard band); hardware rasterizers clip only where a triangle leaves a guard band far wider.
bool clipsToViewport() {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos;
}

int subpixelBits() {
    GLint bits = 0;
    glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
    return std::clamp(bits, 4, 8);
}

shaders::Defines rasterDefines(bool packed, int pass) {
    return {{"ML_RASTER_ATOMIC64", packed ? "1" : "0"},
            {"ML_RASTER_PASS", std::to_string(pass)},
            {"ML_SUBPIXEL_BITS", std::to_string(subpixelBits())},
            {"ML_RASTER_EDGE_RULE", std::to_string(hardwareEdgeRule())}};
}

// Of the first `count` records of a list (`stride` words each), those whose word `at` has a bit of
// `mask` set: the pairs whose tile is 8x8 (ML_RASTER_FINE_PAIR in a pair's second word), the
// large triangles their setup binned (ML_RASTER_BINNED in the last of a record's 12 words).
std::uint32_t marked(const gl::Buffer& list, std::uint32_t count, std::size_t stride, std::size_t at, GLuint mask) {
    std::vector<GLuint> words(stride * std::size_t(count));
    if (count > 0) list.download(words.data(), words.size() * sizeof(GLuint));
    std::uint32_t hits = 0;
    for (std::size_t i = at; i < words.size(); i += stride) hits += (words[i] & mask) != 0 ? 1 : 0;
    return hits;
}

constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT;

// Pixels a finishing invocation reads and writes (glsl/compute_raster_finish.comp).
constexpr int kFinishPixels = 2;

}  // namespace

bool ComputeRaster::supported() { return gl::hasExtension("GL_ARB_gpu_shader_int64"); }
bool ComputeRaster::hasPackedAtomics() { return supported() && gl::hasExtension("GL_NV_shader_atomic_int64"); }

VisibilityRaster ComputeRaster::resolve(VisibilityRaster choice) {
    switch (choice) {
    // The hardware raster. On the H100 the compute raster is faster on every camera measured and,
    // since depth is reversed, within the contract on every 2560x1440 frame measured; but where
    // two surfaces meet, the pixels on the line keep whichever the H100's depth rounding says
    // is nearer, which the compute raster cannot reproduce: 2 such pixels on an atrium frame at
    // 160x90 (the contract allows 1), and tests that hold the visibility buffer to naive's ties
    // fail on the H100 with it (docs/bench/nvidia-h100/reversed-depth/).
    case VisibilityRaster::Auto: return VisibilityRaster::Hardware;
    case VisibilityRaster::Hardware: return choice;
    case VisibilityRaster::Compute:
    case VisibilityRaster::ComputeTwoPass:
        if (!supported())
            throw std::invalid_argument(std::string("--vis-raster ") + visibilityRasterName(choice) +
                                        ": this GPU lacks GL_ARB_gpu_shader_int64 (use hardware)");
        return choice == VisibilityRaster::Compute && !hasPackedAtomics() ? VisibilityRaster::ComputeTwoPass : choice;
    }
    return VisibilityRaster::Hardware;
}

ComputeRaster::ComputeRaster(std::uint32_t materialFeatures, bool packedAtomics, Extras extras)
    : packed_(packedAtomics), extras_(extras), passes_(packedAtomics ? 1 : 2), clipsToViewport_(clipsToViewport()) {
    for (int pass = 0; pass < passes_; ++pass) {
        const shaders::Defines defines = rasterDefines(packed_, pass);
        const std::string suffix = passes_ == 1 ? "" : (pass == 0 ? ".depth" : ".ids");
        const shaders::Defines features = materialFeatureDefines(materialFeatures);
        // The setup reads each triangle's material bits, at the scene's record stride.
        shaders::Defines setup = defines;
        setup.insert(setup.end(), features.begin(), features.end());
        setup_[pass] = gl::Program::compute("compute_raster_triangles.comp", setup);
        tiles_[pass] = gl::Program::compute("compute_raster_tiles.comp", defines);
        shaders::Defines list = shaders::withDefine(defines, "ML_COMPUTE_RASTER", "1");
        list.insert(list.end(), features.begin(), features.end());
        hardwareList_[pass] = gl::Program("visibility.compute-raster.hardware" + suffix,
                                          {{GL_VERTEX_SHADER, "compute_raster_hardware.vert"}, {GL_FRAGMENT_SHADER, "visibility.frag"}},
                                          list);
        if (materialFeatures & ML_FEATURE_ALPHA_TEST) {
            shaders::Defines alpha = shaders::withDefine(defines, "ML_RASTER_ALPHA_TEST", "1");
            alpha.insert(alpha.end(), features.begin(), features.end());
            alphaSetup_[pass] = gl::Program::compute("compute_raster_triangles.comp", alpha);
            alphaTiles_[pass] = gl::Program::compute("compute_raster_tiles.comp", alpha);
            alphaHardwareList_[pass] = gl::Program("visibility.compute-raster.alpha-tested" + suffix,
                                                   {{GL_VERTEX_SHADER, "compute_raster_hardware.vert"}, {GL_FRAGMENT_SHADER, "visibility.frag"}},
                                                   shaders::withDefine(list, "ML_ALPHA_TEST", "1"));
        }
    }
    bin_ = gl::Program::compute("compute_raster_bin.comp", rasterDefines(packed_, 0));
    if (materialFeatures & ML_FEATURE_ALPHA_TEST)
        alphaBin_ = gl::Program::compute("compute_raster_bin.comp", shaders::withDefine(rasterDefines(packed_, 0), "ML_RASTER_ALPHA_TEST", "1"));
    shaders::Defines finish = shaders::withDefine(rasterDefines(packed_, 0), "ML_RASTER_FINISH_PIXELS", std::to_string(kFinishPixels));
    finish_ = gl::Program::compute("compute_raster_finish.comp",
                                   shaders::withDefine(finish, "ML_RASTER_VIEW_DEPTH_RANGE", extras_.viewDepthRange ? "1" : "0"));
    if ((materialFeatures & ML_FEATURE_BLEND) && extras_.depthUnderGlass)
        depthCopy_ = gl::Program("visibility.compute-raster.depth-copy",
                                 {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "compute_raster_depth.frag"}});
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    emptyVao_ = gl::Handle<gl::VertexArrayDeleter>(vao);
}

void ComputeRaster::prepare(const FrameContext& ctx) {
    if (stamp_.update(ctx.targets)) {
        const std::size_t pixels = std::size_t(stamp_.width()) * std::size_t(stamp_.height());
        // The store starts empty; the finish empties only the pixels a frame left.
        store_ = gl::Buffer("compute-raster.store", pixels * 8, nullptr, 0);
        const GLuint empty = ML_RASTER_STORE_EMPTY;
        glClearNamedBufferData(store_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
        depth_ = gl::Texture2D("compute-raster.depth", GL_R32F, stamp_.width(), stamp_.height());
        depthFbo_ = gl::Framebuffer("compute-raster.depth-copy", {}, &ctx.targets.depth());
        // Pairs: up to 64 layers of the screen's tiles (the atrium at 2560x1440 needs about 16); a
        // triangle past it goes to the hardware.
        const std::size_t tiles = std::size_t(gl::groupsFor(stamp_.width(), ML_RASTER_TILE)) * gl::groupsFor(stamp_.height(), ML_RASTER_TILE);
        pairCapacity_ = std::max<std::size_t>(64 * tiles, 1u << 16);
        pairs_ = gl::Buffer("compute-raster.pairs", pairCapacity_ * 8, nullptr, 0);
        // The alpha-tested triangles' pairs: 16 layers (Sponza's foliage at 2560x1440 needs a few).
        alphaPairCapacity_ = std::max<std::size_t>(16 * tiles, 1u << 16);
        if (alphaBin_) alphaPairs_ = gl::Buffer("compute-raster.alpha-tested-pairs", alphaPairCapacity_ * 8, nullptr, 0);
    }
    if (ctx.scene.triangleCount() != sceneTriangles_) {
        sceneTriangles_ = ctx.scene.triangleCount();
        largeCapacity_ = std::max<std::size_t>(sceneTriangles_, 1);
        large_ = gl::Buffer("compute-raster.large", largeCapacity_ * 48, nullptr, 0);
        hardware_ = gl::Buffer("compute-raster.hardware", largeCapacity_ * 4, nullptr, 0);
        clipped_ = gl::Buffer("compute-raster.clipped", largeCapacity_ * 80, nullptr, 0);
    }
    // The counters, then each alpha-tested span's draw of its hardware list, which starts at the
    // span's first triangle (the opaque list fills at most the opaque triangles' entries).
    std::vector<GLuint> initial = {0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0, ~0u, 0, ~0u, ~0u};
    static_assert(ML_RASTER_WORK_WORDS == 25 && ML_RASTER_WORK_VIEW_DEPTH_RANGE == 21 && ML_RASTER_WORK_PAIR_END == 23);
    for (const SceneGpu::TriangleSpan& span : ctx.scene.alphaTestedSpans()) initial.insert(initial.end(), {0, 1, 3 * span.first, 0});
    if (initial.size() != workWords_ || !work_) {
        workWords_ = initial.size();
        work_ = gl::Buffer("compute-raster.work", workWords_ * sizeof(GLuint));
    }
    work_.upload(initial.data(), initial.size() * sizeof(GLuint));
}

void ComputeRaster::run(const FrameContext& ctx, const gl::Texture2D& ids) {
    prepare(ctx);
    ctx.scene.bindGeometryStorage();
    store_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_DEPTH_IDS);
    work_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_WORK);
    large_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_LARGE);
    pairs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_PAIRS);
    hardware_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_HARDWARE);
    clipped_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_CLIPPED);
    for (int pass = 0; pass < passes_; ++pass) rasterPass(ctx, pass);
    finish(ctx, ids);
    storeFlip_ = ~storeFlip_;  // the next frame's words invert this one's (include/compute_raster.glsl)
    ctx.targets.setComputedDepth(&depth_, extras_.viewDepthRange ? ViewDepthRange{&work_, ML_RASTER_WORK_VIEW_DEPTH_RANGE} : ViewDepthRange{});
    if (ctx.scene.hasTransparent() && extras_.depthUnderGlass) {
        auto timed = ctx.timer.pass("visibility.raster-glass-depth");
        copyDepthUnderGlass(ctx);
    }
}

void ComputeRaster::finish(const FrameContext& ctx, const gl::Texture2D& ids) {
    auto timed = ctx.timer.pass("visibility.raster-finish");
    finish_.use();
    finish_.set("u_storeFlip", storeFlip_);
    glBindImageTexture(ML_IMG_VISIBILITY_IDS, ids.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glBindImageTexture(ML_IMG_RASTER_DEPTH, depth_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(gl::groupsFor(stamp_.width(), ML_RASTER_FINISH_ROW * kFinishPixels), stamp_.height(), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | kComputeToCompute);
}

// Each step runs the opaque triangles' work, then the alpha-tested triangles' (where the scene has
// them), with no barrier between the two: they append to lists of their own and meet only in the
// store's atomics, so the GPU overlaps them (an alpha test early in a frame may then miss an
// opaque surface that would have hidden it, and test for nothing).
void ComputeRaster::rasterPass(const FrameContext& ctx, int pass) {
    const GLuint opaque = static_cast<GLuint>(ctx.scene.opaqueTriangleCount());
    opaqueTriangles_ = opaque;
    alphaTestedTriangles_ = 0;
    for (const SceneGpu::TriangleSpan& span : ctx.scene.alphaTestedSpans()) alphaTestedTriangles_ += span.count;
    const bool alphaTested = alphaSetup_[pass] && alphaTestedTriangles_ > 0;
    std::optional<PassTimer::Scope> timed;
    timed.emplace(ctx.timer, "visibility.raster-setup");
    gl::Program& setup = setup_[pass];
    setup.use();
    setup.set("u_firstTriangle", 0u);
    setup.set("u_triangles", opaque);
    setup.set("u_cullBackFaces", ctx.scene.backfaceCulling() ? 1u : 0u);
    setup.set("u_largeCapacity", static_cast<GLuint>(largeCapacity_));
    setup.set("u_largeFirst", 0u);
    setup.set("u_clipsToViewport", clipsToViewport_ ? 1u : 0u);
    setup.set("u_storeFlip", storeFlip_);
    if (pass == 0) setup.set("u_pairCapacity", static_cast<GLuint>(pairCapacity_));  // it lists a few large triangles' pairs
    glDispatchCompute(gl::groupsFor(opaque, ML_RASTER_WORKGROUP), 1, 1);
    if (alphaTested) setupAlphaTested(ctx, pass);
    glMemoryBarrier(kComputeToCompute | GL_COMMAND_BARRIER_BIT);

    timed.reset();
    timed.emplace(ctx.timer, "visibility.raster-tiles");
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, work_.id());
    if (pass == 0) {
        bin_.use();
        bin_.set("u_largeCapacity", static_cast<GLuint>(largeCapacity_));
        bin_.set("u_pairCapacity", static_cast<GLuint>(pairCapacity_));
        bin_.set("u_largeFirst", 0u);
        pairs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_PAIRS);
        glDispatchComputeIndirect(ML_RASTER_WORK_BIN_DISPATCH * sizeof(GLuint));
        if (alphaTested) binAlphaTested(ctx);
        glMemoryBarrier(kComputeToCompute | GL_COMMAND_BARRIER_BIT);
    }
    tiles_[pass].use();
    tiles_[pass].set("u_storeFlip", storeFlip_);
    pairs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_PAIRS);
    glDispatchComputeIndirect(ML_RASTER_WORK_TILE_DISPATCH * sizeof(GLuint));
    if (alphaTested) tileAlphaTested(ctx, pass);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);

    // The hardware's share, into the same store: no depth test, no colour, no depth write.
    timed.reset();
    timed.emplace(ctx.timer, "visibility.raster-hardware");
    depthFbo_.bind();
    glViewport(0, 0, stamp_.width(), stamp_.height());
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glMemoryBarrier(kComputeToCompute);
    hardwareList_[pass].use();
    hardwareList_[pass].set("u_cullBackFaces", ctx.scene.backfaceCulling() ? 1u : 0u);
    hardwareList_[pass].set("u_listFirst", 0u);
    hardwareList_[pass].set("u_storeFlip", storeFlip_);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, work_.id());
    glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(std::uintptr_t(ML_RASTER_WORK_HARDWARE_DRAW * sizeof(GLuint))));
    if (alphaTested) drawAlphaTestedOnHardware(ctx, pass);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glMemoryBarrier(kComputeToCompute);
}

// The alpha-tested triangles, one span per texture set, each step with the span's textures bound
// (the binning reads none): their large triangles follow the opaque ones in the large list, their
// pairs have a buffer of their own, and their hardware lists a draw per span.
void ComputeRaster::setupAlphaTested(const FrameContext& ctx, int pass) {
    const auto& spans = ctx.scene.alphaTestedSpans();
    gl::Program& setup = alphaSetup_[pass];
    setup.use();
    setup.set("u_cullBackFaces", ctx.scene.backfaceCulling() ? 1u : 0u);
    setup.set("u_largeCapacity", static_cast<GLuint>(largeCapacity_));
    setup.set("u_largeFirst", opaqueTriangles_);
    setup.set("u_clipsToViewport", clipsToViewport_ ? 1u : 0u);
    setup.set("u_storeFlip", storeFlip_);
    for (std::size_t i = 0; i < spans.size(); ++i) {
        ctx.scene.bindTextureSet(spans[i].textureSet);
        setup.set("u_firstTriangle", spans[i].first);
        setup.set("u_triangles", spans[i].count);
        setup.set("u_hardwareDraw", static_cast<GLuint>(ML_RASTER_WORK_WORDS + 4 * i));
        glDispatchCompute(gl::groupsFor(spans[i].count, ML_RASTER_WORKGROUP), 1, 1);
    }
    ctx.scene.unbindSamplers();
}

void ComputeRaster::binAlphaTested(const FrameContext& ctx) {
    alphaBin_.use();
    alphaBin_.set("u_largeCapacity", static_cast<GLuint>(largeCapacity_));
    alphaBin_.set("u_pairCapacity", static_cast<GLuint>(alphaPairCapacity_));
    alphaBin_.set("u_largeFirst", opaqueTriangles_);
    alphaBin_.set("u_spans", static_cast<GLuint>(ctx.scene.alphaTestedSpans().size()));
    alphaPairs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_PAIRS);
    glDispatchComputeIndirect(ML_RASTER_WORK_ALPHA_BIN_DISPATCH * sizeof(GLuint));
}

void ComputeRaster::tileAlphaTested(const FrameContext& ctx, int pass) {
    gl::Program& tiles = alphaTiles_[pass];
    tiles.use();
    tiles.set("u_storeFlip", storeFlip_);
    alphaPairs_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RASTER_PAIRS);
    for (const SceneGpu::TriangleSpan& span : ctx.scene.alphaTestedSpans()) {
        ctx.scene.bindTextureSet(span.textureSet);
        tiles.set("u_firstTriangle", span.first);
        tiles.set("u_triangles", span.count);
        glDispatchComputeIndirect(ML_RASTER_WORK_ALPHA_TILE_DISPATCH * sizeof(GLuint));
    }
    ctx.scene.unbindSamplers();
}

void ComputeRaster::drawAlphaTestedOnHardware(const FrameContext& ctx, int pass) {
    const auto& spans = ctx.scene.alphaTestedSpans();
    gl::Program& list = alphaHardwareList_[pass];
    list.use();
    list.set("u_cullBackFaces", ctx.scene.backfaceCulling() ? 1u : 0u);
    list.set("u_storeFlip", storeFlip_);
    for (std::size_t i = 0; i < spans.size(); ++i) {
        ctx.scene.bindTextureSet(spans[i].textureSet);
        list.set("u_listFirst", spans[i].first);
        glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(std::uintptr_t((ML_RASTER_WORK_WORDS + 4 * i) * sizeof(GLuint))));
    }
    ctx.scene.unbindSamplers();
}

void ComputeRaster::copyDepthUnderGlass(const FrameContext& ctx) {
    const auto rect = ctx.scene.transparentScreenRect(ctx.uniforms.viewProj, stamp_.width(), stamp_.height());
    if (!rect) return;
    depthFbo_.bind();
    glViewport(0, 0, stamp_.width(), stamp_.height());
    gl::ScissorScope scissor(glm::ivec4(rect->x, rect->y, rect->z, rect->w));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    depthCopy_.use();
    glBindTextureUnit(ML_TEX_DEPTH, depth_.id());
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(depth::kNearer);
}

ComputeRaster::Work ComputeRaster::lastWork() const {
    std::vector<GLuint> words(workWords_);
    work_.download(words.data(), words.size() * sizeof(GLuint));
    Work w;
    w.opaqueTriangles = opaqueTriangles_;
    w.alphaTested = alphaTestedTriangles_;
    w.alphaLarge = words[ML_RASTER_WORK_ALPHA_LARGE_COUNT];
    w.alphaTiles = std::min(words[ML_RASTER_WORK_ALPHA_PAIR_COUNT], words[ML_RASTER_WORK_ALPHA_PAIR_END]);
    for (std::size_t at = ML_RASTER_WORK_WORDS; at < words.size(); at += 4) w.alphaHardware += words[at] / 3;
    w.large = std::min<std::uint32_t>(words[ML_RASTER_WORK_LARGE_COUNT], static_cast<std::uint32_t>(largeCapacity_));
    w.tiles = std::min(words[ML_RASTER_WORK_PAIR_COUNT], words[ML_RASTER_WORK_PAIR_END]);
    w.hardware = words[ML_RASTER_WORK_HARDWARE_DRAW] / 3;
    w.clipped = words[ML_RASTER_WORK_CLIPPED_COUNT];
    w.fineTiles = marked(pairs_, w.tiles, 2, 1, ML_RASTER_FINE_PAIR);
    w.setupBinned = marked(large_, w.large, 12, 11, ML_RASTER_BINNED);
    if (alphaPairs_) w.alphaFineTiles = marked(alphaPairs_, w.alphaTiles, 2, 1, ML_RASTER_FINE_PAIR);
    return w;
}

}  // namespace ml
