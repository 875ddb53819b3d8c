#include "app/material_variant_choice.h"

#include <stdexcept>

namespace ml::app {

std::string describeMaterialVariants(const Scene& scene) {
    const std::vector<std::string>& names = scene.materialVariants.names;
    std::string list = std::to_string(names.size()) + (names.size() == 1 ? " variant: " : " variants: ");
    for (std::size_t i = 0; i < names.size() && i < 20; ++i) list += (i > 0 ? ", '" : "'") + names[i] + "'";
    if (names.size() > 20) list += ", ...";
    return list;
}

std::optional<std::size_t> parseMaterialVariant(const std::string& name, const Scene& scene) {
    if (name.empty()) return std::nullopt;
    const std::vector<std::string>& names = scene.materialVariants.names;
    if (names.empty())
        throw std::invalid_argument("--material-variant '" + name + "': " + scene.name +
                                    " has no material variants (KHR_materials_variants)");
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return i;
    if (name == "default") return std::nullopt;
    throw std::invalid_argument("--material-variant '" + name + "': no such variant; the file has " +
                                describeMaterialVariants(scene) + " (or default)");
}

}  // namespace ml::app
