#include "renderer/passes/glass_fragments.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "glsl/include/bindings.h"
#include "renderer/gl/scissor_scope.h"
#include "renderer/scene/transparent_ranges.h"

namespace ml {

namespace {
constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;

RasterProgram captureProgram(const char* label, std::uint32_t materialFeatures, bool fill) {
    return transparentRangesProgram(label, "glass_capture.frag", materialFeatures, {{"ML_GLASS_FILL", fill ? "1" : "0"}});
}

// The whole screen tiles around the transparent ranges' projected bounds; one tile where none is
// on screen (its rasters then keep nothing).
glm::uvec4 windowAround(const FrameContext& ctx) {
    constexpr int kTile = ML_SCREEN_TILE;
    const auto rect = ctx.scene.transparentScreenRect(ctx.uniforms.viewProj, ctx.targets.width(), ctx.targets.height());
    if (!rect) return {0, 0, kTile, kTile};
    const glm::ivec2 first = glm::ivec2(rect->x, rect->y) / kTile * kTile;
    const glm::ivec2 end = (glm::ivec2(rect->x + rect->z, rect->y + rect->w) + (kTile - 1)) / kTile * kTile;
    return glm::uvec4(glm::uvec2(first), glm::uvec2(end - first));
}

// Bytes in the unit that reads best: MiB from one MiB up, KiB below.
std::string byteSize(std::uint64_t bytes) {
    if (bytes >= (1u << 20)) return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
    return std::to_string((bytes + 1023) >> 10) + " KiB";
}
}  // namespace

GlassFragments::GlassFragments(std::string timerName, std::uint32_t materialFeatures, std::size_t budgetBytes)
    : timerName_(std::move(timerName)),
      count_(captureProgram("transparent.capture-count", materialFeatures, false)),
      fill_(captureProgram("transparent.capture-fill", materialFeatures, true)),
      clear_(materialFeatures & ML_FEATURE_BLEND ? gl::Program::compute("glass_clear_counts.comp") : gl::Program()),
      total_("transparent.total", 1),
      budget_(budgetBytes) {
    if (budget_ == 0) {
        GLint64 maxBlock = 0;
        glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
        budget_ = static_cast<std::size_t>(maxBlock);
    }
}

void GlassFragments::count(const FrameContext& ctx, GlassColors colors, std::uint32_t deepPartsPerTile) {
    colors_ = colors;
    deepPartsPerTile_ = deepPartsPerTile;
    window_ = windowAround(ctx);
    pixelCount_ = window_.z * window_.w;
    // Padded to whole groups of four counts, which the clear writes as one uvec4; the scan's
    // block bases after the counts.
    pixels_.ensure(std::max((std::size_t(pixelCount_) + 3) / 4 * 16, (std::size_t(pixelCount_) + PrefixSum::blocksOf(pixelCount_)) * 4));
    pixels_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_GLASS_PIXELS);
    {
        auto pass = ctx.timer.pass(timerName_ + "-clear");
        const std::uint32_t quads = (pixelCount_ + 3) / 4;
        clear_.use();
        clear_.set("u_quads", quads);
        glDispatchCompute(gl::groupsFor(quads, ML_SCAN_WORKGROUP), 1, 1);
        glMemoryBarrier(kComputeToCompute);
    }
    {
        auto pass = ctx.timer.pass(timerName_ + "-count");
        rasterGlass(ctx, count_);
    }
    {
        auto pass = ctx.timer.pass(timerName_ + "-scan");
        // A uint total: 2^32 fragments (32 GiB) lie past any storage buffer, and the fill
        // writes none past the buffer's end.
        scan_.run(pixels_.buffer(), pixelCount_, total_.buffer(), 0);
        glMemoryBarrier(kComputeToCompute | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    }
    total_.fence();
}

void GlassFragments::fill(const FrameContext& ctx) {
    // The total is read from a mapped buffer behind a fence: the CPU waits for the count and
    // its scan alone (long done where the method had work between them), not for the pipeline.
    auto pass = ctx.timer.pass(timerName_ + "-fill");
    const std::uint32_t total = *total_.read();
    fragments_ = total;
    const std::size_t perFragment = kBytesPerFragment + (colors_ == GlassColors::Always ? kColorBytesPerFragment : 0);
    const std::uint64_t need = std::uint64_t(total) * perFragment;
    if (need > budget_)
        throw std::runtime_error("the transparent surfaces cover " + std::to_string(ctx.targets.width()) + "x" +
                                 std::to_string(ctx.targets.height()) + " pixels with " + std::to_string(total) + " fragments x " +
                                 std::to_string(perFragment) + " B = " + byteSize(need) + ", more than the capture's " + byteSize(budget_) +
                                 " (at most one storage buffer); lower the resolution or --transparency off");
    // The colours (16 B each) after the fragments, from a 16-byte boundary; the deep tiles'
    // list (a word per screen tile and its header) after them.
    const std::size_t fragmentBytes = (std::size_t(total) * kBytesPerFragment + 15) / 16 * 16;
    const std::size_t colorBytes = std::size_t(total) * kColorBytesPerFragment;
    const std::size_t tiles = std::size_t(windowTiles().x) * windowTiles().y;
    const std::size_t deepTileBytes = (ML_GLASS_DEEP_TILES + tiles * (1 + std::size_t(deepPartsPerTile_))) * 4;
    colorWordOffset_ = static_cast<std::uint32_t>(fragmentBytes / 4);
    deepTileWordOffset_ = 0;
    std::size_t bytes = fragmentBytes;
    if (colors_ == GlassColors::Always) {
        bytes += colorBytes;
    } else if (colors_ == GlassColors::WhereRoom && fragmentBytes + colorBytes + deepTileBytes <= budget_) {
        deepTileWordOffset_ = static_cast<std::uint32_t>((fragmentBytes + colorBytes) / 4);
        bytes += colorBytes + deepTileBytes;
    }
    fragmentStore_.ensure(std::max<std::size_t>(bytes, 16));
    pixels_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_GLASS_PIXELS);
    fragmentStore_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_GLASS_FRAGMENTS);
    fill_.variant(false).use();
    fill_.variant(false).set("u_capacity", total);
    rasterGlass(ctx, fill_);
}

void GlassFragments::rasterGlass(const FrameContext& ctx, const RasterProgram& program) const {
    // Tested against the opaque depth, writing neither colour nor depth, inside the window; the
    // masks are restored before anything can throw, so a refused frame leaves the next one a
    // clean state.
    beginTransparentRaster(ctx.targets);
    const gl::Program& shader = program.variant(false);
    shader.set("u_glassWindow", window_);
    shader.set("u_testsComputedDepth", ctx.targets.hasComputedDepth() ? 1u : 0u);
    if (ctx.targets.hasComputedDepth()) {
        glDisable(GL_DEPTH_TEST);  // the shader tests against the computed depth
        glBindTextureUnit(ML_TEX_DEPTH, ctx.targets.opaqueDepth().id());
    }
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    {
        gl::ScissorScope scissor{glm::ivec4(window_)};  // inside naive's band, where it draws in bands
        ctx.scene.drawTransparent(program, glm::vec3(ctx.uniforms.cameraPos));
    }
    glEnable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glMemoryBarrier(kComputeToCompute);
}

void GlassFragments::bindForShading() const {
    pixels_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_GLASS_PIXELS);
    fragmentStore_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_GLASS_FRAGMENTS);
}

}  // namespace ml
