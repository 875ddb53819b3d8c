// What the corpus tests share: where the corpus is (ML_CORPUS_DIR, ../shared/corpus beside the
// checkout), the methods they render and the lights they render with.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <cstdio>

#include <gtest/gtest.h>

#include "renderer/frame_renderer.h"
#include "renderer/image/image_compare.h"
#include "renderer/lights/light_set.h"
#include "renderer/methods/shading_method.h"
#include "tests/gpu/gpu_test.h"

namespace ml::test {

inline std::string corpusPath(const std::string& relative) { return (std::filesystem::path(ML_CORPUS_DIR) / relative).string(); }

// Naive first: the reference the others are held to.
inline constexpr MethodKind kEveryMethod[] = {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred,
                                              MethodKind::Visibility};

// The scene file's own lights and 48 generated ones (seed 5, the default radius): enough that
// the clustered methods' lists differ per cluster, few enough for naive on llvmpipe.
inline std::vector<Light> ownAndGeneratedLights(const Scene& scene) {
    std::vector<Light> lights = lightsFromScene(scene);
    LightGeneration gen;
    gen.count = 48;
    gen.seed = 5;
    gen.radius = defaultLightRadius(scene.bounds);
    const std::vector<Light> generated = generateLights(lightVolume(scene.bounds), gen);
    lights.insert(lights.end(), generated.begin(), generated.end());
    return lights;
}

// Renders `frame` in every method but naive and holds each to the contract against `reference`
// (naive's frame): at most `maxBadShare` of the pixels over 1/255. One line per method with the
// max error; the images and a diff on failure, named `label` and the method.
inline void expectEveryMethodHoldsTheContract(FrameRenderer& renderer, std::uint32_t frame, const ReferenceFrame& reference,
                                              const std::string& label, double maxBadShare) {
    for (MethodKind kind : kEveryMethod) {
        if (kind == MethodKind::Naive) continue;
        MethodSettings method;
        method.kind = kind;
        renderer.setMethod(method);
        renderer.render(frame);
        const RgbaImage ldr = renderer.readLdr();
        const ImageDifference d = compareImages(ldr, reference.ldr);
        const std::string line = label + " " + methodName(kind);
        std::printf("%-70s max %3.0f/255  over 1/255 %.4f %%\n", line.c_str(), d.maxAbs * 255.0, d.badPixelShare * 100.0);
        EXPECT_LE(d.badPixelShare, maxBadShare) << line << ": max " << d.maxAbs * 255.0 << "/255; images in "
                                                << writeFailureImages(testNameOf(label + "_" + methodName(kind)), ldr, reference.ldr);
    }
}

}  // namespace ml::test
