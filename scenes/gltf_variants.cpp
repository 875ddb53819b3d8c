#include "scenes/gltf_variants.h"

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

constexpr const char* kVariants = "KHR_materials_variants";

// The extension's object on `extensions`, or null where absent; not an object: fail.
const tinygltf::Value* variantsExtension(const std::string& path, const tinygltf::ExtensionMap& extensions,
                                         const std::string& where) {
    const auto it = extensions.find(kVariants);
    if (it == extensions.end()) return nullptr;
    if (!it->second.IsObject()) fail(path, where + kVariants + " is not a JSON object");
    return &it->second;
}

// An integer JSON value in [0, count), else -1.
int indexIn(const tinygltf::Value& v, std::size_t count) {
    if (!v.IsInt() && !v.IsNumber()) return -1;
    const double x = v.GetNumberAsDouble();
    if (!(x >= 0.0 && x < static_cast<double>(count)) || x != static_cast<double>(static_cast<long long>(x))) return -1;
    return static_cast<int>(x);
}

std::string valueText(const tinygltf::Value& v) {
    if (v.IsInt() || v.IsNumber()) {
        const double x = v.GetNumberAsDouble();
        return x == static_cast<double>(static_cast<long long>(x)) ? std::to_string(static_cast<long long>(x)) : std::to_string(x);
    }
    return "(not a number)";
}

}  // namespace

std::vector<std::string> readVariantNames(const std::string& path, const tinygltf::Model& model) {
    const tinygltf::Value* root = variantsExtension(path, model.extensions, "");
    if (root == nullptr) return {};
    const std::string what = std::string(kVariants) + " variants";
    if (!root->Has("variants") || !root->Get("variants").IsArray()) fail(path, what + " is not an array");
    const tinygltf::Value& list = root->Get("variants");
    std::vector<std::string> names;
    for (std::size_t i = 0; i < list.ArrayLen(); ++i) {
        const tinygltf::Value& v = list.Get(static_cast<int>(i));
        if (!v.IsObject() || !v.Has("name") || !v.Get("name").IsString())
            fail(path, what + "[" + std::to_string(i) + "] has no name (a string)");
        names.push_back(v.Get("name").Get<std::string>());
    }
    return names;
}

std::vector<int> primitiveVariantMaterials(const std::string& path, const tinygltf::Model& model,
                                           const tinygltf::Primitive& primitive, std::size_t variantCount,
                                           const std::string& where) {
    const tinygltf::Value* ext = variantsExtension(path, primitive.extensions, where + ": ");
    if (ext == nullptr) return {};
    const std::string what = where + ": " + kVariants;
    if (!ext->Has("mappings") || !ext->Get("mappings").IsArray()) fail(path, what + " mappings is not an array");
    std::vector<int> materials(variantCount, primitive.material);
    std::vector<bool> mapped(variantCount, false);
    const tinygltf::Value& mappings = ext->Get("mappings");
    for (std::size_t i = 0; i < mappings.ArrayLen(); ++i) {
        const tinygltf::Value& m = mappings.Get(static_cast<int>(i));
        const std::string mapping = what + " mappings[" + std::to_string(i) + "]";
        if (!m.IsObject() || !m.Has("material") || !m.Has("variants") || !m.Get("variants").IsArray())
            fail(path, mapping + " is not an object with a material and a variants array");
        const int material = indexIn(m.Get("material"), model.materials.size());
        if (material < 0)
            fail(path, mapping + ": material " + valueText(m.Get("material")) + " out of range (" +
                           std::to_string(model.materials.size()) + " materials)");
        const tinygltf::Value& variants = m.Get("variants");
        for (std::size_t k = 0; k < variants.ArrayLen(); ++k) {
            const int variant = indexIn(variants.Get(static_cast<int>(k)), variantCount);
            if (variant < 0)
                fail(path, mapping + ": variant " + valueText(variants.Get(static_cast<int>(k))) + " out of range (" +
                               std::to_string(variantCount) + " variants)");
            // The extension lets a variant map to one material a primitive.
            if (mapped[static_cast<std::size_t>(variant)])
                fail(path, mapping + ": variant " + std::to_string(variant) + " is listed by two mappings");
            mapped[static_cast<std::size_t>(variant)] = true;
            materials[static_cast<std::size_t>(variant)] = material;
        }
    }
    return materials;
}

}  // namespace ml::gltf
