// The visibility raster writes opaque ranges' triangle ids by imageAtomicMax behind an early
// depth test (visibility.frag) and alpha-tested ranges' through the ROPs. The nearest fragment
// must win as a colour write would: on coplanar ties the first drawn, whichever quad that is.
#include <gtest/gtest.h>

#include "gpu_test.h"

namespace ml::test {
namespace {

class VisibilityIds : public GpuTest {};

// Two coplanar quads of different colours overlapping in the middle; no lights, so the ambient
// term shows which one each pixel kept. Drawn in either order, the visibility buffer must keep
// what naive's single LESS pass keeps.
TEST_F(VisibilityIds, CoplanarTiesResolveAsInNaiveInEitherDrawOrder) {
    const TestQuad red{{0.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    const TestQuad blue{{0.5f, 0.5f, 0.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
    for (bool redFirst : {true, false}) {
        SCOPED_TRACE(redFirst ? "red first" : "blue first");
        const Scene scene = redFirst ? quadScene({red, blue}) : quadScene({blue, red});
        FrameSettings s = smallFrame(scene, CameraPose{{0.7f, 0.4f, 4.0f}, {0.0f, 0.0f, 0.0f}, 60.0f}, 160, 90);
        s.ambient = 1.0f;
        FrameRenderer renderer(scene, {}, s);
        renderer.render(0);
        const RgbaImage naive = renderer.readLdr();
        MethodSettings m;
        m.kind = MethodKind::Visibility;
        renderer.setMethod(m);
        renderer.render(0);
        const RgbaImage test = renderer.readLdr();
        // The middle pixel lies in both quads: the first drawn colours it.
        const std::size_t middle = (std::size_t(45) * 160 + 80) * 4;
        const int first = naive.pixels[middle + (redFirst ? 0 : 2)], second = naive.pixels[middle + (redFirst ? 2 : 0)];
        EXPECT_GT(first, second + 100) << "naive kept the quad drawn second";
        ASSERT_EQ(test.pixels.size(), naive.pixels.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < test.pixels.size(); ++i) differing += test.pixels[i] > naive.pixels[i] + 1 || naive.pixels[i] > test.pixels[i] + 1;
        EXPECT_EQ(differing, 0u) << "images in " << writeFailureImages(redFirst ? "red-first" : "blue-first", test, naive);
    }
}

}  // namespace
}  // namespace ml::test
