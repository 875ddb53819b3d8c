// KHR_materials_variants as a file states it: the root's variant names, and each primitive's
// mappings from variants to materials. Internal to scenes/gltf_*.cpp; the scene holds the result
// as MaterialVariants (scenes/material_variants.h).
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace ml::gltf {

// The names of the root's KHR_materials_variants.variants, in order; none where the file has no
// such extension. Throws "<path>: KHR_materials_variants variants[1] has no name" and the like.
std::vector<std::string> readVariantNames(const std::string& path, const tinygltf::Model& model);

// The glTF material the primitive takes under each of `variantCount` variants: the mapping that
// lists the variant, else the primitive's own material (-1: glTF's default). Empty where the
// primitive has no mappings. `where` names the primitive in messages ("meshes[0] 'Shoe'
// primitive 2"); a material or variant index out of range, or a variant two mappings list,
// throws one line naming the file and the primitive.
std::vector<int> primitiveVariantMaterials(const std::string& path, const tinygltf::Model& model,
                                           const tinygltf::Primitive& primitive, std::size_t variantCount,
                                           const std::string& where);

}  // namespace ml::gltf
