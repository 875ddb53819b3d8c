#include "scenes/material_variants.h"

#include "scenes/scene.h"

namespace ml {

void applyMaterialVariant(Scene& scene, std::optional<std::size_t> variant) {
    const MaterialVariants& v = scene.materialVariants;
    if (v.empty()) return;
    const std::vector<std::uint32_t>& chosen = variant ? v.materials.at(*variant) : v.defaults;
    for (std::size_t d = 0; d < scene.draws.size(); ++d) scene.draws[d].material = chosen.at(d);
}

}  // namespace ml
