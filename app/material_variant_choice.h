// --material-variant NAME: which of a glTF file's KHR_materials_variants its primitives are drawn
// with, checked against the scene's variants before anything is drawn.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "scenes/scene.h"

namespace ml::app {

// The variant `name` names (empty or "default" where no variant has that name: the file's own
// materials). Throws std::invalid_argument with one line naming the value and the variants
// there are, or saying the scene has none.
std::optional<std::size_t> parseMaterialVariant(const std::string& name, const Scene& scene);

// "2 variants: 'Red', 'Blue'".
std::string describeMaterialVariants(const Scene& scene);

}  // namespace ml::app
