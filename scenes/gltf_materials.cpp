#include "scenes/gltf_materials.h"

#include <algorithm>
#include <sstream>

// The implementation lives in Debian's libtinygltf.so (built with stb), so no
// TINYGLTF_IMPLEMENTATION anywhere; stb_image is used directly to decode base-colour images.
#include <stb_image.h>

namespace ml::gltf {
namespace {

// Decodes to RGBA8, rows top to bottom (stb's order, as long as no one turns on its vertical
// flip). The colour bytes stay sRGB-encoded, as glTF stores base colour.
bool decodeRgba8(const std::vector<unsigned char>& encoded, Image& out, std::uint64_t& texelBudget, std::string& why) {
    if (encoded.empty()) {
        why = "no image data (external file missing or unreadable)";
        return false;
    }
    const auto failureReason = [] {
        const char* reason = stbi_failure_reason();
        return std::string(reason != nullptr ? reason : "unknown error");
    };
    const int size = static_cast<int>(encoded.size());  // bounded by kMaxFileBytes
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(encoded.data(), size, &w, &h, &channels)) {
        why = "cannot decode: " + failureReason();
        return false;
    }
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) {
        why = "size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(kMaxImageSide);
        return false;
    }
    const std::uint64_t texels = std::uint64_t(w) * std::uint64_t(h);
    if (texels > texelBudget) {
        why = "textures exceed the limit of " + std::to_string(kMaxImageTexels) + " texels in all";
        return false;
    }
    unsigned char* pixels = stbi_load_from_memory(encoded.data(), size, &w, &h, &channels, 4);
    if (pixels == nullptr) {
        why = "cannot decode: " + failureReason();
        return false;
    }
    out.width = w;
    out.height = h;
    out.rgba8.assign(pixels, pixels + std::size_t(w) * std::size_t(h) * 4);
    stbi_image_free(pixels);
    texelBudget -= texels;
    return true;
}

}  // namespace

std::uint32_t MaterialConverter::materialFor(int gltfMaterial) {
    if (gltfMaterial < 0) {
        // Primitives without a material are drawn white, as glTF's default material is.
        if (!defaultMaterial_) {
            defaultMaterial_ = static_cast<std::uint32_t>(scene_.materials.size());
            Material white;
            white.name = "default";
            scene_.materials.push_back(white);
        }
        return *defaultMaterial_;
    }
    int& slot = materialSlots_[static_cast<std::size_t>(gltfMaterial)];
    if (slot < 0) {
        Material converted = convertMaterial(static_cast<std::size_t>(gltfMaterial));
        slot = static_cast<int>(scene_.materials.size());
        scene_.materials.push_back(std::move(converted));
    }
    return static_cast<std::uint32_t>(slot);
}

Material MaterialConverter::convertMaterial(std::size_t index) {
    const tinygltf::Material& source = model_.materials[index];
    const std::string what = named("materials", index, source.name);
    Material m;
    m.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
    const std::vector<double>& f = source.pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4)
        fail(path_, what + ": baseColorFactor has " + std::to_string(f.size()) + " numbers, expected 4");
    // The spec bounds each factor to [0, 1]; clamping keeps a stray value from blowing out shading.
    m.baseColorFactor = glm::clamp(glm::vec4(glm::dvec4(f[0], f[1], f[2], f[3])), 0.0f, 1.0f);
    m.doubleSided = source.doubleSided;
    m.metallic = static_cast<float>(std::clamp(source.pbrMetallicRoughness.metallicFactor, 0.0, 1.0));
    m.roughness = static_cast<float>(std::clamp(source.pbrMetallicRoughness.roughnessFactor, 0.0, 1.0));

    const tinygltf::TextureInfo& info = source.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return m;
    if (static_cast<std::size_t>(info.index) >= model_.textures.size())
        fail(path_, what + ": baseColorTexture index " + std::to_string(info.index) + " out of range (" +
                        std::to_string(model_.textures.size()) + " textures)");
    if (info.texCoord != 0) {
        ++baseColorOnOtherTexcoord_;  // only UV0 is modelled
        return m;
    }
    const int image = model_.textures[static_cast<std::size_t>(info.index)].source;
    if (image < 0) {
        ++texturesWithoutSource_;  // the image comes through an extension (KTX2, WebP...)
        return m;
    }
    if (static_cast<std::size_t>(image) >= model_.images.size())
        fail(path_, named("textures", static_cast<std::size_t>(info.index), model_.textures[static_cast<std::size_t>(info.index)].name) +
                        ": source image index " + std::to_string(image) + " out of range (" +
                        std::to_string(model_.images.size()) + " images)");
    m.baseColorTexture.image = imageFor(static_cast<std::size_t>(image));
    return m;
}

int MaterialConverter::imageFor(std::size_t index) {
    int& slot = imageSlots_[index];
    if (slot >= 0) return slot;
    const tinygltf::Image& source = model_.images[index];
    Image image;
    image.name = !source.name.empty() ? source.name : !source.uri.empty() ? source.uri : "image " + std::to_string(index);
    std::string why;
    if (!decodeRgba8(source.image, image, texelBudget_, why)) {
        // One bad image should not cost the whole scene: a white texel leaves the factor alone.
        failedImages_.push_back(named("images", index, source.name.empty() ? source.uri : source.name) + " (" +
                                        why + ")");
        image.width = 1;
        image.height = 1;
        image.rgba8 = {255, 255, 255, 255};
    }
    slot = static_cast<int>(scene_.images.size());
    scene_.images.push_back(std::move(image));
    return slot;
}

std::vector<std::string> MaterialConverter::warnings() const {
    std::vector<std::string> lines;
    const auto note = [&](std::size_t n, const std::string& text) {
        if (n > 0) lines.push_back(text);
    };
    const tinygltf::Model& model = model_;

    std::size_t normal = 0, occlusion = 0, emissive = 0, metallicRoughness = 0, alpha = 0, emissiveFactor = 0;
    for (const tinygltf::Material& m : model.materials) {
        normal += m.normalTexture.index >= 0;
        occlusion += m.occlusionTexture.index >= 0;
        emissive += m.emissiveTexture.index >= 0;
        metallicRoughness += m.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0;
        alpha += m.alphaMode != "OPAQUE";
        emissiveFactor += std::any_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), [](double v) { return v != 0.0; });
    }
    if (normal + occlusion + emissive + metallicRoughness > 0) {
        std::string kinds;
        const auto kind = [&](std::size_t n, const char* name) {
            if (n > 0) kinds += std::string(kinds.empty() ? "" : ", ") + name + " x" + std::to_string(n);
        };
        kind(normal, "normal");
        kind(occlusion, "occlusion");
        kind(emissive, "emissive");
        kind(metallicRoughness, "metallicRoughness");
        lines.push_back("textures other than baseColor skipped (not modelled): " + kinds);
    }
    note(baseColorOnOtherTexcoord_, "baseColor textures of " + counted(baseColorOnOtherTexcoord_, "material", "materials") +
                                               " skipped: they use a texCoord other than 0 (only UV0 is modelled)");
    note(texturesWithoutSource_, counted(texturesWithoutSource_, "baseColor texture", "baseColor textures") +
                                            " skipped: no PNG/JPEG source (the image needs an extension)");
    note(alpha, "alphaMode of " + counted(alpha, "material", "materials") + " ignored (not modelled; drawn opaque)");
    note(emissiveFactor, "emissiveFactor of " + counted(emissiveFactor, "material", "materials") + " ignored (not modelled)");
    if (!failedImages_.empty()) {
        std::string list;
        for (std::size_t i = 0; i < failedImages_.size() && i < 3; ++i) list += (i ? "; " : "") + failedImages_[i];
        if (failedImages_.size() > 3) list += "; and " + std::to_string(failedImages_.size() - 3) + " more";
        lines.push_back(counted(failedImages_.size(), "image", "images") +
                        " could not be decoded; a 1x1 white texture stands in: " + list);
    }
    return lines;
}

// --- What a material asks of the geometry --------------------------------------------------------

namespace {

// KHR_texture_transform may name the UV set instead of the textureInfo (its texCoord wins).
double effectiveTexCoord(int texCoord, const tinygltf::ExtensionMap& extensions) {
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end() || !it->second.IsObject() || !it->second.Has("texCoord")) return texCoord;
    const tinygltf::Value& value = it->second.Get("texCoord");
    // Not a number: a value no UV set has, so that checkTexCoords names it.
    return value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
}

template <class Info>
void addIfPresent(std::vector<MaterialTexture>& out, const char* slot, const Info& info) {
    if (info.index >= 0) out.push_back({slot, effectiveTexCoord(info.texCoord, info.extensions)});
}

}  // namespace

std::vector<MaterialTexture> texturesOf(const tinygltf::Material& material) {
    std::vector<MaterialTexture> out;
    addIfPresent(out, "baseColorTexture", material.pbrMetallicRoughness.baseColorTexture);
    addIfPresent(out, "metallicRoughnessTexture", material.pbrMetallicRoughness.metallicRoughnessTexture);
    addIfPresent(out, "normalTexture", material.normalTexture);
    addIfPresent(out, "occlusionTexture", material.occlusionTexture);
    addIfPresent(out, "emissiveTexture", material.emissiveTexture);
    return out;
}

bool hasNormalTexture(const tinygltf::Material& material) { return material.normalTexture.index >= 0; }

int normalTextureTexCoord(const tinygltf::Material& material) {
    if (!hasNormalTexture(material)) return 0;
    return effectiveTexCoord(material.normalTexture.texCoord, material.normalTexture.extensions) == 1.0 ? 1 : 0;
}

bool usesTexCoord1(const tinygltf::Material& material) {
    const std::vector<MaterialTexture> textures = texturesOf(material);
    return std::any_of(textures.begin(), textures.end(), [](const MaterialTexture& t) { return t.texCoord == 1.0; });
}

void checkTexCoords(const std::string& path, const tinygltf::Model& model, std::size_t material) {
    for (const MaterialTexture& texture : texturesOf(model.materials[material]))
        if (texture.texCoord != 0.0 && texture.texCoord != 1.0) {
            std::ostringstream value;
            value << texture.texCoord;
            fail(path, named("materials", material, model.materials[material].name) + ": " + texture.slot +
                           " reads texCoord " + value.str() + " (only TEXCOORD_0 and TEXCOORD_1 are supported)");
        }
}

}  // namespace ml::gltf
