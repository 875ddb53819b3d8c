#include "tests/gpu/raster_ids.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/methods/visibility_buffer.h"
#include "renderer/passes/compute_raster.h"

namespace ml::test {

namespace {

template <typename T>
std::vector<T> readTexture(const gl::Texture2D& texture, GLenum format, GLenum type) {
    std::vector<T> out(std::size_t(texture.width()) * texture.height());
    glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(out.size() * sizeof(T)), out.data());
    return out;
}

}  // namespace

RasterResult visibilityRaster(FrameRenderer& renderer, VisibilityRaster raster, bool clipsToViewport) {
    MethodSettings m;
    m.kind = MethodKind::Visibility;
    m.visibilityRaster = raster;
    renderer.setMethod(m);
    const auto& method = dynamic_cast<const VisibilityBuffer&>(renderer.method());
    // A test's knob on a GPU-derived setting, which the renderer exposes read-only.
    if (const ComputeRaster* compute = method.computeRaster()) const_cast<ComputeRaster*>(compute)->setClipsToViewport(clipsToViewport);
    renderer.render(0);
    return lastRaster(renderer);
}

RasterResult lastRaster(const FrameRenderer& renderer) {
    const auto& method = dynamic_cast<const VisibilityBuffer&>(renderer.method());
    RasterResult r;
    r.ids = readTexture<std::uint32_t>(method.triangleIds(), GL_RED_INTEGER, GL_UNSIGNED_INT);
    if (const ComputeRaster* compute = method.computeRaster()) r.depth = readTexture<float>(compute->depth(), GL_RED, GL_FLOAT);
    else r.depth = readTexture<float>(renderer.targets().depth(), GL_DEPTH_COMPONENT, GL_FLOAT);
    return r;
}

IdDifference compareIds(const RasterResult& reference, const RasterResult& test, int width, const std::string& label) {
    IdDifference d;
    for (std::size_t i = 0; i < reference.ids.size() && i < test.ids.size(); ++i) {
        if (reference.ids[i] == test.ids[i]) continue;
        ++d.pixels;
        // A tie: the two depths lie within rounding of each other. A depth plane's terms run up
        // to 1 (the near plane), so its rounding can be a float step of 1, 2^-23, whatever the depth
        // at the pixel; and llvmpipe takes depth from the unsnapped vertices, the compute raster
        // from the snapped ones.
        const float gap = std::abs(reference.depth[i] - test.depth[i]);
        const bool tie = gap <= 0x1p-23f + 1e-6f * reference.depth[i];
        if (!tie) ++d.coverage;
        if (d.pixels <= 8)
            std::printf("  %s (%zu, %zu): %u at %.9g, against %u at %.9g%s\n", label.c_str(), i % width, i / width, reference.ids[i],
                        reference.depth[i], test.ids[i], test.depth[i], tie ? " (a tie)" : "");
    }
    return d;
}

}  // namespace ml::test
