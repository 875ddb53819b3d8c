// Z-binning (--assign zbin; Drobot 2017, "Improved culling for tiled and clustered rendering",
// seed 001): instead of per-cluster lists, lights sorted by view depth, a [first, last] range of
// sorted indices per z-bin, and a bitmask per screen tile with a bit per sorted light.
//
//   lights ─> [zbin.keys]        cull to the view; key = depth of the near extent; count listed
//          ─> [zbin.sort]        RadixSort of (key, light index): listed lights first, by depth
//          ─> [zbin.bins]        per z-bin: first and last sorted index reaching it
//          ─> [zbin.tile-masks]  per tile, per 32 sorted lights: sphere against the tile frustum
//
//   sorted:  | light 7 | light 2 | light 9 | ... |        (near extent ascending)
//   bin b:   [first_b ........ last_b]                    (8 B per bin)
//   tile t:  word 0: bits of sorted 0..31 | word 1: 32..63 | ...   (4 B x ceil(listed / 32))
//
// A pixel walks its bin's range and shades the lights whose bit its tile has set: a light in
// both reaches the tile's frustum and the bin's depth slab, so nothing that reaches the pixel is
// skipped and nothing is ever dropped.
//
// Memory: tiles x ceil(listed lights / 32) x 4 B of masks (48 x 27 tiles, 1024 lights: 162 KiB;
// a million lights: 162 MiB, refused on llvmpipe's 128 MiB block limit with a message), 8 B per
// bin (32 slices x 8: 2 KiB), 48 B per light for keys, indices, spheres and the sort's scratch.
#pragma once

#include <cstdint>

#include "renderer/clustering/cluster_grid.h"
#include "renderer/clustering/cluster_statistics.h"
#include "renderer/clustering/radix_sort.h"
#include "renderer/gl/buffer.h"
#include "renderer/gl/program.h"
#include "renderer/frame_context.h"

namespace ml {


class ZBinAssignment {
public:
    // depthSamples: ML_MSAA_SAMPLES of the statistics pass, which reads every depth sample.
    ZBinAssignment(bool spotLights, const std::pair<std::string, std::string>& depthSamples);

    // Builds sort, bins and masks for `grid` from the lights; the grid buffer (slicing) must be
    // bound and final. Throws std::runtime_error naming what to lower when the masks cannot
    // fit maxStorageBlock bytes.
    void build(const FrameContext& ctx, const ClusterGrid& grid, std::size_t maxStorageBlock);
    void bindForShading() const;

    // Reads back the last build and counts per visible pixel the lights walked and shaded
    // (a pass over the depth of the last build; a GPU sync).
    ZBinStatistics statistics() const;

    // Read-backs for tests: light index at each sorted position, bin ranges, tile masks.
    std::vector<std::uint32_t> downloadSortedLights() const;
    std::vector<glm::uvec2> downloadBinRanges() const;
    std::vector<std::uint32_t> downloadTileMasks() const;

private:
    gl::Program keysPass_, binsPass_, masksPass_, statsPass_;
    RadixSort sort_;
    gl::Buffer params_;  // words per tile, listed lights
    gl::GrowableBuffer keys_{"zbin.keys"};
    gl::GrowableBuffer sortedLights_{"zbin.sorted-lights"};
    gl::GrowableBuffer lightView_{"zbin.light-view"};
    gl::GrowableBuffer sortedView_{"zbin.sorted-view"};
    gl::GrowableBuffer ranges_{"zbin.bin-ranges"};
    gl::GrowableBuffer masks_{"zbin.tile-masks"};
    mutable gl::GrowableBuffer groupStats_{"zbin.stats"};

    ClusterGrid grid_;
    std::uint32_t lights_ = 0, listed_ = 0, words_ = 0;
    GLuint depth_ = 0;  // depth texture of the last build (statistics)
    int width_ = 0, height_ = 0;
};

}  // namespace ml
