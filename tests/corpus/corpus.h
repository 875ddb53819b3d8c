// What the corpus tests share: where the corpus is (ML_CORPUS_DIR, ../shared/corpus beside the
// checkout), the methods they render and the lights they render with.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/lights/light_set.h"
#include "renderer/methods/shading_method.h"

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

}  // namespace ml::test
