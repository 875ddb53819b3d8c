// The transparent pass (glTF alphaMode BLEND). After a method has left its opaque frame in the
// HDR target, the transparent draw ranges are shaded forward with the same lights and blended
// over it ("over": colour * alpha + destination * (1 - alpha)), depth-tested against the opaque
// depth and writing none. Every method draws them in SceneGpu::transparentOrder, back to front
// per draw range, so the naive reference blends the same colours in the same order.
//
// Naive's pass loops over every light; the clustered methods' (Forward+, deferred, visibility)
// loops over the cluster lists, which ClusteredLighting builds to hold every light a
// transparent fragment needs as well (the fitted depth range, --active-only and --normal-cones
// take the transparent surfaces into account). Debug views leave the pass out.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "renderer/clustering/clustering_settings.h"
#include "renderer/frame_context.h"
#include "renderer/scene/raster_program.h"
#include "renderer/scene/transparent_ranges.h"

namespace ml {

class ClusteredLighting;

class TransparentPass {
public:
    // Naive's pass: every fragment loops over every light.
    static TransparentPass overAllLights(std::string timerName, std::uint32_t materialFeatures, bool spotLights);
    // A clustered method's pass: each fragment loops over its cluster's list.
    static TransparentPass overClusterLists(std::string timerName, std::uint32_t materialFeatures, const ClusteringSettings& settings);

    // Shades and blends the transparent ranges into ctx.targets.hdrFramebuffer(); nothing where
    // the scene has none (or --transparency off). `lists` is null for naive.
    void render(const FrameContext& ctx, const ClusteredLighting* lists) const;

private:
    TransparentPass(std::string timerName, RasterProgram program);

    std::string timerName_;
    RasterProgram program_;  // empty where the scene has no transparent material
};

}  // namespace ml
