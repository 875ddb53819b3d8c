// The transparent pass's capture: every fragment of the transparent (BLEND) ranges that passes
// the opaque depth, kept per pixel for a compute pass to sort, shade and blend
// (glsl/glass_shade.comp). Sized by what the frame needs, as the exact light lists are:
//
// The pixels are those of the frame's window (glsl/include/glass_window.glsl): the whole screen
// tiles around the transparent ranges' projected bounds, to which both rasters are scissored, so
// the clear, the scan and the shading's tiles cover the glass and not the screen (the atrium's
// panes take 4-10 % of it).
//
//   count():  [-clear]  pixels[p] = 0                                (compute)
//             [-count]  raster, no colour, no depth write, early depth test (against a
//                       computed depth, the shader's own: FrameTargets::hasComputedDepth):
//                       pixels[p] = fragments at p
//             [-scan]   pixels[p] = where p's fragments start        (PrefixSum in blocks of
//                                                                    4,096 pixels, each block's
//                                                                    base after the pixels; the
//                                                                    total into a mapped buffer,
//                                                                    then a fence)
//   fill():   [-fill]   the total read behind the fence; the same raster again:
//                       fragments[pixels[p]++] = (depth bits, triangle id), which leaves pixels[p]
//                       where p's fragments end: p's are fragments[pixels[p - 1] .. pixels[p]),
//                       or from its block's base for a block's first pixel
//
// The blocks lie in the fragment buffer in whatever order they were scanned (ScanOrder::BlockBases):
// nothing reads across pixels, and a scan in order waited on a chain of its 900 blocks at
// 2560x1440.
//
// Memory: 4 B per pixel of the window (at most 14.1 MiB at 2560x1440, 31.6 MiB at 3840x2160) and 8 B per fragment
// (the depth, to sort by, and the triangle, to rebuild the surface from); where the glass spans
// more than one texture set, 16 B more per fragment for its shaded colour (the shading runs
// once per set, the blend after the last); where the shading splits deep tiles
// (TransparentPass), the same colours and a word per screen tile and per part, if they fit. The
// worst case is every pixel covered by every transparent triangle; a frame whose fragments do not
// fit one storage buffer is refused in one line that names them. Both rasters run a fragment shader of one atomic: no shading, no colour
// writes (H100, atrium, 2560x1440: 0.01-0.03 ms each; the scan 0.07 ms).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "glsl/include/bindings.h"
#include "renderer/clustering/prefix_sum.h"
#include "renderer/frame_context.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/mapped_words.h"
#include "renderer/gl/program.h"
#include "renderer/scene/raster_program.h"

namespace ml {

// Whether the fragment buffer keeps a colour per fragment after the fragments.
enum class GlassColors {
    None,      // one dispatch shades and blends
    Always,    // glass of several texture sets: a dispatch per set, blended after the last
    WhereRoom, // for the deep tiles' split (TransparentPass), with their list after the colours,
               // where both fit the budget with the fragments; else none and no split
};

class GlassFragments {
public:
    static constexpr std::size_t kBytesPerPixel = 4;
    static constexpr std::size_t kBytesPerFragment = 8;
    static constexpr std::size_t kColorBytesPerFragment = 16;

    // Builds nothing where no material is BLEND (ML_FEATURE_BLEND). budgetBytes: what the
    // fragments may take (0: this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE).
    // timerName: the passes' prefix (<timerName>-count, -scan, -fill).
    GlassFragments(std::string timerName, std::uint32_t materialFeatures, std::size_t budgetBytes);

    // The capture in two halves, so that a method can put work between them and the CPU never
    // waits on the GPU for the total: count() as soon as the opaque depth is final, fill()
    // before the shading. fill() throws std::runtime_error, naming the numbers, when the
    // fragments (with GlassColors::Always, and their colours) do not fit the budget.
    // deepPartsPerTile: with GlassColors::WhereRoom, the most parts the list holds a tile in.
    void count(const FrameContext& ctx, GlassColors colors, std::uint32_t deepPartsPerTile = 0);
    void fill(const FrameContext& ctx);
    bool counted() const { return total_.fenced(); }
    // Binds the pixels and the fragments (with colours after them) at their ML_SSBO_GLASS_* points.
    void bindForShading() const;
    // The frame's window (glsl/include/glass_window.glsl's u_glassWindow): its first pixel, a
    // multiple of ML_SCREEN_TILE, and its size, whole tiles; and its size in tiles.
    const glm::uvec4& window() const { return window_; }
    glm::uvec2 windowTiles() const { return glm::uvec2(window_.z, window_.w) / std::uint32_t(ML_SCREEN_TILE); }
    // Where the colours start in the fragment buffer, in 4-byte words (after the last fragment).
    std::uint32_t colorWordOffset() const { return colorWordOffset_; }
    // After fill() with GlassColors::WhereRoom: whether the colours and the deep tiles' list fit,
    // and where the list starts (words; ML_GLASS_DEEP_* in bindings.h).
    bool hasDeepTileList() const { return deepTileWordOffset_ != 0; }
    std::uint32_t deepTileWordOffset() const { return deepTileWordOffset_; }
    const gl::Buffer& fragmentBuffer() const { return fragmentStore_.buffer(); }

    std::uint64_t fragmentCount() const { return fragments_; }  // of the last capture
    // Bytes the capture's buffers hold now.
    std::size_t bytes() const { return pixels_.buffer().size() + fragmentStore_.buffer().size(); }

private:
    // Draws the transparent ranges with `program` against the opaque depth.
    void rasterGlass(const FrameContext& ctx, const RasterProgram& program) const;

    std::string timerName_;
    RasterProgram count_, fill_;
    gl::Program clear_;  // the counts to zero (glsl/glass_clear_counts.comp)
    PrefixSum scan_{ScanOrder::BlockBases};
    gl::MappedWords total_;  // the scan's total, fenced after count()'s scan until fill() reads it
    glm::uvec4 window_{0, 0, ML_SCREEN_TILE, ML_SCREEN_TILE};
    std::uint32_t pixelCount_ = 0;  // the window's
    GlassColors colors_ = GlassColors::None;
    std::uint32_t deepPartsPerTile_ = 0;
    std::size_t budget_ = 0;
    std::uint64_t fragments_ = 0;
    gl::GrowableBuffer pixels_{"transparent.pixels"};
    gl::GrowableBuffer fragmentStore_{"transparent.fragments"};
    std::uint32_t colorWordOffset_ = 0;
    std::uint32_t deepTileWordOffset_ = 0;
};

}  // namespace ml
