// KHR_materials_variants: a file's named sets of materials (a shoe in red, blue or green), held
// beside the draw ranges so that choosing one changes which material each range draws with and
// nothing else: the geometry, its order and the draw ranges stay as loaded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ml {

struct Scene;

struct MaterialVariants {
    std::vector<std::string> names;  // the file's variants, in its order
    // Per draw range (Scene::draws, in its order): its material without a variant, and under
    // each variant (materials[v][d]), the range's default where the file maps none. Empty where
    // the file has no variants. The loader splits draw ranges so that every triangle of one takes
    // the same material under every variant.
    std::vector<std::uint32_t> defaults;
    std::vector<std::vector<std::uint32_t>> materials;

    bool empty() const { return names.empty(); }
};

// Sets each draw range's material to the one `variant` gives it (an index into
// scene.materialVariants.names), or back to its default for nullopt.
void applyMaterialVariant(Scene& scene, std::optional<std::size_t> variant);

}  // namespace ml
