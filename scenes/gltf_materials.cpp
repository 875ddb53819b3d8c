#include "scenes/gltf_materials.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <tuple>

// The implementation lives in Debian's libtinygltf.so (built with stb), so no
// TINYGLTF_IMPLEMENTATION anywhere; stb_image is used directly to decode the images materials use.
#include <stb_image.h>

namespace ml::gltf {
namespace {

// Decodes to RGBA8, rows top to bottom (stb's order, as long as no one turns on its vertical
// flip). The bytes stay as stored: sRGB for colour textures, linear for data textures.
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

std::uint32_t MaterialConverter::materialFor(int gltfMaterial, double meshScale) {
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
    const Material& material = scene_.materials[static_cast<std::size_t>(slot)];
    if (!(material.transmissionModelled() && material.thicknessFactor > 0.0f) || meshScale == 1.0)
        return static_cast<std::uint32_t>(slot);
    const auto [it, added] = scaledVolumes_.try_emplace({gltfMaterial, meshScale}, static_cast<std::uint32_t>(scene_.materials.size()));
    if (added) {
        Material scaled = material;
        scaled.thicknessFactor = static_cast<float>(material.thicknessFactor * meshScale);
        scene_.materials.push_back(std::move(scaled));
    }
    return it->second;
}

namespace {

bool finite(double v) { return std::isfinite(v); }

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

// A tinygltf::Value that must be an array of `n` finite numbers.
bool readNumbers(const tinygltf::Value& v, std::size_t n, double* out) {
    if (!v.IsArray() || v.ArrayLen() != n) return false;
    for (std::size_t i = 0; i < n; ++i) {
        const tinygltf::Value& e = v.Get(static_cast<int>(i));
        if (!e.IsNumber() && !e.IsInt()) return false;
        out[i] = e.GetNumberAsDouble();
        if (!finite(out[i])) return false;
    }
    return true;
}

// A textureInfo given as JSON inside a material extension, as tinygltf parses the core ones.
struct JsonTextureInfo {
    int index = -1;
    int texCoord = 0;
    tinygltf::ExtensionMap extensions;
};

// The textureInfo `info`, or nothing where it is malformed (not an object with an integer index,
// or a texCoord that is not an integer); `why` says which.
std::optional<JsonTextureInfo> parseTextureInfo(const tinygltf::Value& info, std::string* why = nullptr) {
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
        if (why != nullptr) *why = "not a textureInfo (an object with an integer index)";
        return std::nullopt;
    }
    JsonTextureInfo parsed;
    parsed.index = info.Get("index").GetNumberAsInt();
    if (info.Has("texCoord")) {
        if (!info.Get("texCoord").IsInt()) {
            if (why != nullptr) *why = "texCoord is not an integer";
            return std::nullopt;
        }
        parsed.texCoord = info.Get("texCoord").GetNumberAsInt();
    }
    if (info.Has("extensions") && info.Get("extensions").IsObject())
        for (const std::string& key : info.Get("extensions").Keys()) parsed.extensions[key] = info.Get("extensions").Get(key);
    return parsed;
}

}  // namespace

Material MaterialConverter::convertMaterial(std::size_t index) {
    const tinygltf::Material& source = model_.materials[index];
    const std::string what = named("materials", index, source.name);
    const auto factor = [&](double v, const char* name, double lo, double hi) {
        // The spec bounds each factor; a value outside is clamped (a stray value must not blow out
        // shading), a value that is not a number cannot be used at all.
        if (!finite(v)) fail(path_, what + ": " + name + " " + number(v) + " is not a finite number");
        return static_cast<float>(std::clamp(v, lo, hi));
    };
    Material m;
    m.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
    const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
    // KHR_materials_pbrSpecularGlossiness stands in for the metallic-roughness block, which a
    // file keeps only as a fallback for viewers without the extension.
    const auto specularGlossiness = source.extensions.find(kSpecularGlossiness);
    const bool metallicRoughness = specularGlossiness == source.extensions.end();
    if (metallicRoughness) {
        const std::vector<double>& f = pbr.baseColorFactor;
        if (f.size() != 4) fail(path_, what + ": baseColorFactor has " + std::to_string(f.size()) + " numbers, expected 4");
        for (int c = 0; c < 4; ++c) m.baseColorFactor[c] = factor(f[c], "baseColorFactor", 0.0, 1.0);
        m.metallic = factor(pbr.metallicFactor, "metallicFactor", 0.0, 1.0);
        m.roughness = factor(pbr.roughnessFactor, "roughnessFactor", 0.0, 1.0);
        m.baseColorTexture = textureRef(what + " baseColorTexture", pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                        pbr.baseColorTexture.extensions, true);
        m.metallicRoughnessTexture = textureRef(what + " metallicRoughnessTexture", pbr.metallicRoughnessTexture.index,
                                                pbr.metallicRoughnessTexture.texCoord, pbr.metallicRoughnessTexture.extensions, false);
    } else {
        convertSpecularGlossiness(specularGlossiness->second, what, m);
    }
    m.doubleSided = source.doubleSided;

    if (source.alphaMode == "MASK") {
        m.alphaMode = AlphaMode::Mask;
    } else if (source.alphaMode == "BLEND") {
        m.alphaMode = AlphaMode::Blend;
    } else if (source.alphaMode != "OPAQUE") {
        fail(path_, what + ": alphaMode '" + clip(source.alphaMode, 40) + "' is not OPAQUE, MASK or BLEND");
    }
    if (!finite(source.alphaCutoff) || source.alphaCutoff < 0.0)
        fail(path_, what + ": alphaCutoff " + number(source.alphaCutoff) + " is not a number >= 0");
    m.alphaCutoff = static_cast<float>(source.alphaCutoff);

    const tinygltf::NormalTextureInfo& normal = source.normalTexture;
    m.normalTexture = textureRef(what + " normalTexture", normal.index, normal.texCoord, normal.extensions, false);
    if (!finite(normal.scale)) fail(path_, what + ": normalTexture.scale " + number(normal.scale) + " is not a finite number");
    m.normalScale = static_cast<float>(normal.scale);
    const tinygltf::OcclusionTextureInfo& occlusion = source.occlusionTexture;
    m.occlusionTexture = textureRef(what + " occlusionTexture", occlusion.index, occlusion.texCoord, occlusion.extensions, false);
    if (!finite(occlusion.strength) || occlusion.strength < 0.0 || occlusion.strength > 1.0)
        fail(path_, what + ": occlusionTexture.strength " + number(occlusion.strength) + " is outside [0, 1]");
    m.occlusionStrength = static_cast<float>(occlusion.strength);

    const std::vector<double>& e = source.emissiveFactor;
    if (e.size() != 3) fail(path_, what + ": emissiveFactor has " + std::to_string(e.size()) + " numbers, expected 3");
    for (int c = 0; c < 3; ++c) m.emissive[c] = factor(e[c], "emissiveFactor", 0.0, 1.0);
    // KHR_materials_emissive_strength: a multiplier past the factor's [0, 1], for HDR glow.
    const auto strength = source.extensions.find("KHR_materials_emissive_strength");
    if (strength != source.extensions.end() && strength->second.Has("emissiveStrength")) {
        const tinygltf::Value& v = strength->second.Get("emissiveStrength");
        const double s = v.IsNumber() || v.IsInt() ? v.GetNumberAsDouble() : -1.0;
        if (!finite(s) || s < 0.0 || s > 1e6)
            fail(path_, what + ": KHR_materials_emissive_strength emissiveStrength is not a number in [0, 1e6]");
        m.emissive *= static_cast<float>(s);
    }
    m.emissiveTexture = textureRef(what + " emissiveTexture", source.emissiveTexture.index, source.emissiveTexture.texCoord,
                                   source.emissiveTexture.extensions, true);
    convertMaterialExtensions(source, what, m);
    return m;
}

namespace {

// A number field of an extension object, or `fallback` where it is absent; not a finite number: fail.
double extensionNumber(const std::string& path, const std::string& what, const tinygltf::Value& object, const char* extension,
                       const char* field, double fallback) {
    if (!object.Has(field)) return fallback;
    const tinygltf::Value& v = object.Get(field);
    const double x = v.IsNumber() || v.IsInt() ? v.GetNumberAsDouble() : std::nan("");
    if (!finite(x)) fail(path, what + ": " + extension + " " + field + " is not a finite number");
    return x;
}

}  // namespace

void MaterialConverter::convertMaterialExtensions(const tinygltf::Material& source, const std::string& what, Material& m) {
    const auto extension = [&](const char* name) -> const tinygltf::Value* {
        const auto it = source.extensions.find(name);
        if (it == source.extensions.end()) return nullptr;
        if (!it->second.IsObject()) fail(path_, what + ": " + name + " is not a JSON object");
        return &it->second;
    };
    // KHR_materials_unlit: an empty object; the material's base colour is what it shows. The
    // extension asks viewers to ignore the other extensions of such a material (ior, specular).
    if (extension("KHR_materials_unlit") != nullptr) {
        m.unlit = true;
        return;
    }
    // Specular-glossiness sets its own F0 (convertSpecularGlossiness); the extension is not
    // meant to be combined with these two.
    if (source.extensions.count(kSpecularGlossiness) != 0) return;
    if (const tinygltf::Value* ior = extension("KHR_materials_ior")) {
        const double v = extensionNumber(path_, what, *ior, "KHR_materials_ior", "ior", 1.5);
        // The schema allows 0 (F0 = 1, the specular-glossiness conversion) and [1, inf).
        if (v != 0.0 && (v < 1.0 || v > 1e6))
            fail(path_, what + ": KHR_materials_ior ior " + number(v) + " is neither 0 nor in [1, 1e6]");
        m.ior = static_cast<float>(v);
    }
    if (const tinygltf::Value* spec = extension("KHR_materials_specular")) {
        const double factor = extensionNumber(path_, what, *spec, "KHR_materials_specular", "specularFactor", 1.0);
        if (factor < 0.0 || factor > 1.0)
            fail(path_, what + ": KHR_materials_specular specularFactor " + number(factor) + " is outside [0, 1]");
        m.specularFactor = static_cast<float>(factor);
        if (spec->Has("specularColorFactor")) {
            double c[3];
            if (!readNumbers(spec->Get("specularColorFactor"), 3, c) || c[0] < 0.0 || c[1] < 0.0 || c[2] < 0.0 ||
                c[0] > 1e6 || c[1] > 1e6 || c[2] > 1e6)
                fail(path_, what + ": KHR_materials_specular specularColorFactor is not 3 numbers in [0, 1e6]");
            m.specularColorFactor = glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
        }
        if (spec->Has("specularTexture"))
            m.specularTexture = extensionTextureRef(what + " KHR_materials_specular specularTexture", spec->Get("specularTexture"), false);
        if (spec->Has("specularColorTexture"))
            m.specularColorTexture =
                extensionTextureRef(what + " KHR_materials_specular specularColorTexture", spec->Get("specularColorTexture"), true);
    }
    if (const tinygltf::Value* coat = extension("KHR_materials_clearcoat")) {
        const auto unitFactor = [&](const char* field) {
            const double v = extensionNumber(path_, what, *coat, "KHR_materials_clearcoat", field, 0.0);
            if (v < 0.0 || v > 1.0) fail(path_, what + ": KHR_materials_clearcoat " + field + " " + number(v) + " is outside [0, 1]");
            return static_cast<float>(v);
        };
        m.clearcoatFactor = unitFactor("clearcoatFactor");
        m.clearcoatRoughnessFactor = unitFactor("clearcoatRoughnessFactor");
        const auto texture = [&](const char* field) {
            return coat->Has(field) ? extensionTextureRef(what + " KHR_materials_clearcoat " + field, coat->Get(field), false)
                                    : TextureRef{};
        };
        m.clearcoatTexture = texture("clearcoatTexture");
        m.clearcoatRoughnessTexture = texture("clearcoatRoughnessTexture");
        m.clearcoatNormalTexture = texture("clearcoatNormalTexture");
        // The normal textureInfo's scale (glTF's normalTextureInfo), 1 where absent.
        if (coat->Has("clearcoatNormalTexture"))
            m.clearcoatNormalScale = static_cast<float>(
                extensionNumber(path_, what, coat->Get("clearcoatNormalTexture"), "KHR_materials_clearcoat clearcoatNormalTexture", "scale", 1.0));
    }
    if (const tinygltf::Value* sheen = extension("KHR_materials_sheen")) {
        if (sheen->Has("sheenColorFactor")) {
            double c[3];
            if (!readNumbers(sheen->Get("sheenColorFactor"), 3, c) || c[0] < 0.0 || c[1] < 0.0 || c[2] < 0.0 || c[0] > 1.0 ||
                c[1] > 1.0 || c[2] > 1.0)
                fail(path_, what + ": KHR_materials_sheen sheenColorFactor is not 3 numbers in [0, 1]");
            m.sheenColorFactor = glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
        }
        const double roughness = extensionNumber(path_, what, *sheen, "KHR_materials_sheen", "sheenRoughnessFactor", 0.0);
        if (roughness < 0.0 || roughness > 1.0)
            fail(path_, what + ": KHR_materials_sheen sheenRoughnessFactor " + number(roughness) + " is outside [0, 1]");
        m.sheenRoughnessFactor = static_cast<float>(roughness);
        if (sheen->Has("sheenColorTexture"))
            m.sheenColorTexture = extensionTextureRef(what + " KHR_materials_sheen sheenColorTexture", sheen->Get("sheenColorTexture"), true);
        if (sheen->Has("sheenRoughnessTexture"))
            m.sheenRoughnessTexture =
                extensionTextureRef(what + " KHR_materials_sheen sheenRoughnessTexture", sheen->Get("sheenRoughnessTexture"), false);
    }
    if (const tinygltf::Value* aniso = extension("KHR_materials_anisotropy")) {
        const double strength = extensionNumber(path_, what, *aniso, "KHR_materials_anisotropy", "anisotropyStrength", 0.0);
        if (strength < 0.0 || strength > 1.0)
            fail(path_, what + ": KHR_materials_anisotropy anisotropyStrength " + number(strength) + " is outside [0, 1]");
        m.anisotropyStrength = static_cast<float>(strength);
        // Any finite angle: a turn more or less is the same direction.
        m.anisotropyRotation =
            static_cast<float>(extensionNumber(path_, what, *aniso, "KHR_materials_anisotropy", "anisotropyRotation", 0.0));
        if (aniso->Has("anisotropyTexture"))
            m.anisotropyTexture =
                extensionTextureRef(what + " KHR_materials_anisotropy anisotropyTexture", aniso->Get("anisotropyTexture"), false);
    }
    if (const tinygltf::Value* film = extension("KHR_materials_iridescence")) {
        const auto value = [&](const char* field, double fallback) {
            return extensionNumber(path_, what, *film, "KHR_materials_iridescence", field, fallback);
        };
        const double factor = value("iridescenceFactor", 0.0);
        if (factor < 0.0 || factor > 1.0)
            fail(path_, what + ": KHR_materials_iridescence iridescenceFactor " + number(factor) + " is outside [0, 1]");
        const double ior = value("iridescenceIor", 1.3);
        if (!(ior >= 1.0)) fail(path_, what + ": KHR_materials_iridescence iridescenceIor " + number(ior) + " is below 1");
        const double minimum = value("iridescenceThicknessMinimum", 100.0);
        const double maximum = value("iridescenceThicknessMaximum", 400.0);
        if (minimum < 0.0 || maximum < 0.0)
            fail(path_, what + ": KHR_materials_iridescence thickness " + number(minimum < 0.0 ? minimum : maximum) +
                            " nm is negative");
        if (minimum > maximum)
            fail(path_, what + ": KHR_materials_iridescence iridescenceThicknessMinimum " + number(minimum) +
                            " nm is above iridescenceThicknessMaximum " + number(maximum) + " nm");
        m.iridescenceFactor = static_cast<float>(factor);
        m.iridescenceIor = static_cast<float>(ior);
        m.iridescenceThicknessMinimum = static_cast<float>(minimum);
        m.iridescenceThicknessMaximum = static_cast<float>(maximum);
        if (film->Has("iridescenceTexture"))
            m.iridescenceTexture = extensionTextureRef(what + " KHR_materials_iridescence iridescenceTexture", film->Get("iridescenceTexture"), false);
        if (film->Has("iridescenceThicknessTexture"))
            m.iridescenceThicknessTexture = extensionTextureRef(what + " KHR_materials_iridescence iridescenceThicknessTexture",
                                                                film->Get("iridescenceThicknessTexture"), false);
        // The two maps share one texture unit (bindings.h, ML_TEX_IRIDESCENCE): one image and sampler.
        const TextureRef& a = m.iridescenceTexture;
        const TextureRef& b = m.iridescenceThicknessTexture;
        if (m.iridescenceModelled() && a.present() && b.present() && (a.image != b.image || a.sampler != b.sampler))
            fail(path_, what + ": KHR_materials_iridescence iridescenceTexture and iridescenceThicknessTexture are different "
                               "textures; this renderer samples both from one (free texture units run out): use one image");
    }
    if (const tinygltf::Value* transmission = extension("KHR_materials_transmission")) {
        const double factor = extensionNumber(path_, what, *transmission, "KHR_materials_transmission", "transmissionFactor", 0.0);
        if (factor < 0.0 || factor > 1.0)
            fail(path_, what + ": KHR_materials_transmission transmissionFactor " + number(factor) + " is outside [0, 1]");
        m.transmissionFactor = static_cast<float>(factor);
        if (transmission->Has("transmissionTexture"))
            m.transmissionTexture = extensionTextureRef(what + " KHR_materials_transmission transmissionTexture",
                                                        transmission->Get("transmissionTexture"), false);
    }
    // KHR_materials_volume means something only under a transmission (the extension's rule).
    if (const tinygltf::Value* volume = extension("KHR_materials_volume")) {
        const auto value = [&](const char* field, double fallback) {
            return extensionNumber(path_, what, *volume, "KHR_materials_volume", field, fallback);
        };
        const double thickness = value("thicknessFactor", 0.0);
        if (thickness < 0.0) fail(path_, what + ": KHR_materials_volume thicknessFactor " + number(thickness) + " is negative");
        // glTF writes an infinite distance by leaving it out; 0 is not allowed.
        const double distance = value("attenuationDistance", 0.0);
        if (volume->Has("attenuationDistance") && !(distance > 0.0))
            fail(path_, what + ": KHR_materials_volume attenuationDistance " + number(distance) + " is not above 0");
        m.thicknessFactor = static_cast<float>(thickness);
        m.attenuationDistance = static_cast<float>(distance);
        if (volume->Has("attenuationColor")) {
            double c[3];
            if (!readNumbers(volume->Get("attenuationColor"), 3, c) || !(c[0] >= 0.0 && c[1] >= 0.0 && c[2] >= 0.0) || c[0] > 1.0 ||
                c[1] > 1.0 || c[2] > 1.0)
                fail(path_, what + ": KHR_materials_volume attenuationColor is not 3 numbers in [0, 1]");
            m.attenuationColor = glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
        }
        if (volume->Has("thicknessTexture"))
            m.thicknessTexture = extensionTextureRef(what + " KHR_materials_volume thicknessTexture", volume->Get("thicknessTexture"), false);
    }
}

namespace {

// Factors of specular-glossiness: `n` numbers in [0, 1], or `fallback` where absent.
template <std::size_t N>
std::array<float, N> unitFactors(const std::string& path, const std::string& what, const tinygltf::Value& object,
                                 const char* field, float fallback) {
    std::array<float, N> out;
    out.fill(fallback);
    if (!object.Has(field)) return out;
    double v[N];
    const tinygltf::Value& given = object.Get(field);
    const bool read = N == 1 ? (given.IsNumber() || given.IsInt()) && finite(v[0] = given.GetNumberAsDouble())
                             : readNumbers(given, N, v);
    if (!read || std::any_of(v, v + N, [](double x) { return x < 0.0 || x > 1.0; }))
        fail(path, what + ": " + kSpecularGlossiness + " " + field + " is not " + (N == 1 ? "a number" : std::to_string(N) + " numbers") +
                       " in [0, 1]");
    for (std::size_t i = 0; i < N; ++i) out[i] = static_cast<float>(v[i]);
    return out;
}

// The metallic-roughness map a specular-glossiness map stands for: G, the roughness, is
// 1 - glossinessFactor x A; B, the metallic, 0. Baked once at load, so the shaders keep one path.
Image bakeRoughnessFromGlossiness(const Image& specularGlossiness, float glossinessFactor) {
    Image out;
    out.name = specularGlossiness.name + " (roughness from glossiness)";
    out.width = specularGlossiness.width;
    out.height = specularGlossiness.height;
    out.srgb = false;
    out.rgba8.resize(specularGlossiness.rgba8.size());
    for (std::size_t i = 0; i + 3 < out.rgba8.size(); i += 4) {
        const float glossiness = glossinessFactor * (specularGlossiness.rgba8[i + 3] / 255.0f);
        out.rgba8[i + 0] = 255;
        out.rgba8[i + 1] = static_cast<std::uint8_t>(std::lround(255.0f * (1.0f - glossiness)));
        out.rgba8[i + 2] = 0;
        out.rgba8[i + 3] = 255;
    }
    return out;
}

}  // namespace

void MaterialConverter::convertSpecularGlossiness(const tinygltf::Value& sg, const std::string& what, Material& m) {
    if (!sg.IsObject()) fail(path_, what + ": " + kSpecularGlossiness + " is not a JSON object");
    const std::array<float, 4> diffuse = unitFactors<4>(path_, what, sg, "diffuseFactor", 1.0f);
    const std::array<float, 3> specular = unitFactors<3>(path_, what, sg, "specularFactor", 1.0f);
    const float glossiness = unitFactors<1>(path_, what, sg, "glossinessFactor", 1.0f)[0];
    const std::string prefix = what + " " + kSpecularGlossiness + " ";
    // The diffuse colour is the base colour: sRGB, its alpha the coverage; metallic 0.
    m.baseColorFactor = glm::vec4(diffuse[0], diffuse[1], diffuse[2], diffuse[3]);
    if (sg.Has("diffuseTexture")) m.baseColorTexture = extensionTextureRef(prefix + "diffuseTexture", sg.Get("diffuseTexture"), true);
    m.metallic = 0.0f;
    m.roughness = 1.0f - glossiness;
    // The specular colour is the dielectric's F0 itself: ior 0 makes ((ior - 1) / (ior + 1))^2 = 1,
    // and KHR_materials_specular's colour (factor x sRGB map) is then F0, its weight 1.
    m.ior = 0.0f;
    m.specularFactor = 1.0f;
    m.specularColorFactor = glm::vec3(specular[0], specular[1], specular[2]);
    if (!sg.Has("specularGlossinessTexture")) return;
    const TextureRef map = extensionTextureRef(prefix + "specularGlossinessTexture", sg.Get("specularGlossinessTexture"), true);
    if (!map.present()) return;  // no PNG/JPEG source: counted by textureRef
    m.specularColorTexture = map;  // RGB, sRGB; its alpha is not read there
    // Glossiness in the map's alpha moves to a metallic-roughness map's G channel.
    const auto key = std::make_pair(map.image, glossiness);
    auto [it, added] = bakedRoughness_.try_emplace(key, static_cast<int>(scene_.images.size()));
    if (added) {
        const Image& source = scene_.images[static_cast<std::size_t>(map.image)];
        const std::uint64_t texels = std::uint64_t(source.width) * std::uint64_t(source.height);
        if (texels > texelBudget_)
            fail(path_, prefix + "specularGlossinessTexture: its roughness map would exceed the limit of " +
                            std::to_string(kMaxImageTexels) + " texels in all");
        texelBudget_ -= texels;
        scene_.images.push_back(bakeRoughnessFromGlossiness(source, glossiness));
    }
    m.metallicRoughnessTexture = map;
    m.metallicRoughnessTexture.image = it->second;
    m.roughness = 1.0f;  // the map holds 1 - glossinessFactor x A
}

TextureRef MaterialConverter::extensionTextureRef(const std::string& what, const tinygltf::Value& info, bool srgb) {
    std::string why;
    const std::optional<JsonTextureInfo> parsed = parseTextureInfo(info, &why);
    if (!parsed) fail(path_, what + ": " + why);
    return textureRef(what, parsed->index, parsed->texCoord, parsed->extensions, srgb);
}

TextureRef MaterialConverter::textureRef(const std::string& what, int textureIndex, int texCoord,
                                         const tinygltf::ExtensionMap& extensions, bool srgb) {
    TextureRef ref;
    if (textureIndex < 0) return ref;
    if (static_cast<std::size_t>(textureIndex) >= model_.textures.size())
        fail(path_, what + ": texture index " + std::to_string(textureIndex) + " out of range (" +
                        std::to_string(model_.textures.size()) + " textures)");
    ref.texCoord = texCoord;
    // KHR_texture_transform: offset, rotation, scale, and a texCoord that overrides the textureInfo's.
    const auto transform = extensions.find("KHR_texture_transform");
    if (transform != extensions.end()) {
        const tinygltf::Value& t = transform->second;
        const auto bad = [&](const char* field) {
            fail(path_, what + ": KHR_texture_transform " + field + " is not valid (expected finite numbers)");
        };
        double pair[2];
        if (t.Has("offset")) {
            if (!readNumbers(t.Get("offset"), 2, pair)) bad("offset");
            ref.transform.offset = glm::vec2(static_cast<float>(pair[0]), static_cast<float>(pair[1]));
        }
        if (t.Has("scale")) {
            if (!readNumbers(t.Get("scale"), 2, pair)) bad("scale");
            ref.transform.scale = glm::vec2(static_cast<float>(pair[0]), static_cast<float>(pair[1]));
        }
        if (t.Has("rotation")) {
            const tinygltf::Value& r = t.Get("rotation");
            if (!(r.IsNumber() || r.IsInt()) || !finite(r.GetNumberAsDouble())) bad("rotation");
            ref.transform.rotation = static_cast<float>(r.GetNumberAsDouble());
        }
        if (t.Has("texCoord")) {
            const tinygltf::Value& c = t.Get("texCoord");
            if (!c.IsInt()) bad("texCoord");
            ref.texCoord = c.GetNumberAsInt();
        }
    }
    if (ref.texCoord != 0 && ref.texCoord != 1)
        fail(path_, what + ": texCoord " + std::to_string(ref.texCoord) + " is not supported (TEXCOORD_0 and TEXCOORD_1 are)");

    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(textureIndex)];
    if (texture.sampler >= 0) {
        if (static_cast<std::size_t>(texture.sampler) >= model_.samplers.size())
            fail(path_, named("textures", static_cast<std::size_t>(textureIndex), texture.name) + ": sampler index " +
                            std::to_string(texture.sampler) + " out of range (" + std::to_string(model_.samplers.size()) +
                            " samplers)");
        ref.sampler = samplerFor(static_cast<std::size_t>(texture.sampler));
    }
    const int image = texture.source;
    if (image < 0) {
        ++texturesWithoutSource_;  // the image comes through an extension (KTX2, WebP...)
        return TextureRef{};
    }
    if (static_cast<std::size_t>(image) >= model_.images.size())
        fail(path_, named("textures", static_cast<std::size_t>(textureIndex), texture.name) + ": source image index " +
                        std::to_string(image) + " out of range (" + std::to_string(model_.images.size()) + " images)");
    ref.image = imageFor(static_cast<std::size_t>(image), srgb);
    return ref;
}

int MaterialConverter::samplerFor(std::size_t index) {
    int& slot = samplerSlots_[index];
    if (slot >= 0) return slot;
    const tinygltf::Sampler& source = model_.samplers[index];
    const std::string what = named("samplers", index, source.name);
    // glTF uses GL's enum values; -1 is "not given" (then the viewer chooses: ours is trilinear, repeat).
    Sampler s;
    if (source.magFilter != -1) {
        if (!isOneOf(source.magFilter, {0x2600, 0x2601})) fail(path_, what + ": magFilter " + std::to_string(source.magFilter) + " is not NEAREST or LINEAR");
        s.magFilter = source.magFilter;
    }
    if (source.minFilter != -1) {
        if (!isOneOf(source.minFilter, {0x2600, 0x2601, 0x2700, 0x2701, 0x2702, 0x2703}))
            fail(path_, what + ": minFilter " + std::to_string(source.minFilter) + " is not a glTF minification filter");
        s.minFilter = source.minFilter;
    }
    for (const auto& [wrap, name, out] : {std::tuple{source.wrapS, "wrapS", &s.wrapS}, std::tuple{source.wrapT, "wrapT", &s.wrapT}}) {
        if (!isOneOf(wrap, {0x812F, 0x8370, 0x2901}))
            fail(path_, what + ": " + name + " " + std::to_string(wrap) + " is not CLAMP_TO_EDGE, MIRRORED_REPEAT or REPEAT");
        *out = wrap;
    }
    slot = static_cast<int>(scene_.samplers.size());
    scene_.samplers.push_back(s);
    return slot;
}

int MaterialConverter::imageFor(std::size_t index, bool srgb) {
    int& slot = imageSlots_[srgb ? 1 : 0][index];
    if (slot >= 0) return slot;
    // Decoded once: an image read both as colour and as data is held twice, in two colour spaces.
    const int other = imageSlots_[srgb ? 0 : 1][index];
    Image image;
    if (other >= 0) {
        image = scene_.images[static_cast<std::size_t>(other)];
    } else {
        const tinygltf::Image& source = model_.images[index];
        image.name = !source.name.empty() ? source.name : !source.uri.empty() ? source.uri : "image " + std::to_string(index);
        std::string why;
        if (!decodeRgba8(source.image, image, texelBudget_, why)) {
            // One bad image should not cost the whole scene: a white texel leaves the factor alone.
            failedImages_.push_back(named("images", index, source.name.empty() ? source.uri : source.name) + " (" + why + ")");
            image.width = 1;
            image.height = 1;
            image.rgba8 = {255, 255, 255, 255};
        }
    }
    image.srgb = srgb;
    slot = static_cast<int>(scene_.images.size());
    scene_.images.push_back(std::move(image));
    return slot;
}

std::vector<std::string> MaterialConverter::warnings() const {
    std::vector<std::string> lines;
    const auto note = [&](std::size_t n, const std::string& text) {
        if (n > 0) lines.push_back(text);
    };

    note(texturesWithoutSource_, counted(texturesWithoutSource_, "texture", "textures") +
                                     " skipped: no PNG/JPEG source (the image needs an extension)");
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

// A textureInfo inside a material extension (KHR_materials_specular's), where it is well formed
// (convertMaterial fails on the rest, naming it).
std::optional<JsonTextureInfo> extensionTexture(const tinygltf::Material& material, const char* extension, const char* slot) {
    const auto it = material.extensions.find(extension);
    if (it == material.extensions.end() || !it->second.IsObject() || !it->second.Has(slot)) return std::nullopt;
    return parseTextureInfo(it->second.Get(slot));
}

void addExtensionTexture(std::vector<MaterialTexture>& out, const tinygltf::Material& material, const char* extension,
                         const char* slot) {
    if (const std::optional<JsonTextureInfo> info = extensionTexture(material, extension, slot))
        out.push_back({slot, effectiveTexCoord(info->texCoord, info->extensions)});
}

// A coat's normal map needs tangents as the material's own does (KHR_materials_clearcoat), where
// the coat is there at all (a clearcoatFactor of 0 disables the layer).
std::optional<JsonTextureInfo> clearcoatNormalTexture(const tinygltf::Material& material) {
    const auto it = material.extensions.find("KHR_materials_clearcoat");
    if (it == material.extensions.end() || !it->second.IsObject() || !it->second.Has("clearcoatFactor")) return std::nullopt;
    const tinygltf::Value& factor = it->second.Get("clearcoatFactor");
    if (!(factor.IsNumber() || factor.IsInt()) || !(factor.GetNumberAsDouble() > 0.0)) return std::nullopt;
    return extensionTexture(material, "KHR_materials_clearcoat", "clearcoatNormalTexture");
}

// An anisotropic lobe needs tangents as a normal map does (KHR_materials_anisotropy: the file's
// TANGENT, else generated), where the lobe is there at all (a strength of 0 is the isotropic lobe).
bool anisotropic(const tinygltf::Material& material) {
    const auto it = material.extensions.find("KHR_materials_anisotropy");
    if (it == material.extensions.end() || !it->second.IsObject() || !it->second.Has("anisotropyStrength")) return false;
    const tinygltf::Value& strength = it->second.Get("anisotropyStrength");
    return (strength.IsNumber() || strength.IsInt()) && strength.GetNumberAsDouble() > 0.0;
}

}  // namespace

std::vector<MaterialTexture> texturesOf(const tinygltf::Material& material) {
    std::vector<MaterialTexture> out;
    if (material.extensions.count(kSpecularGlossiness) == 0) {  // else the fallback block is never read
        addIfPresent(out, "baseColorTexture", material.pbrMetallicRoughness.baseColorTexture);
        addIfPresent(out, "metallicRoughnessTexture", material.pbrMetallicRoughness.metallicRoughnessTexture);
    }
    addIfPresent(out, "normalTexture", material.normalTexture);
    addIfPresent(out, "occlusionTexture", material.occlusionTexture);
    addIfPresent(out, "emissiveTexture", material.emissiveTexture);
    addExtensionTexture(out, material, kSpecularGlossiness, "diffuseTexture");
    if (material.extensions.count("KHR_materials_unlit") == 0) {  // unlit: the extension's maps are never read
        addExtensionTexture(out, material, "KHR_materials_specular", "specularTexture");
        addExtensionTexture(out, material, "KHR_materials_specular", "specularColorTexture");
        addExtensionTexture(out, material, "KHR_materials_clearcoat", "clearcoatTexture");
        addExtensionTexture(out, material, "KHR_materials_clearcoat", "clearcoatRoughnessTexture");
        addExtensionTexture(out, material, "KHR_materials_clearcoat", "clearcoatNormalTexture");
        addExtensionTexture(out, material, kSpecularGlossiness, "specularGlossinessTexture");
        addExtensionTexture(out, material, "KHR_materials_sheen", "sheenColorTexture");
        addExtensionTexture(out, material, "KHR_materials_sheen", "sheenRoughnessTexture");
        addExtensionTexture(out, material, "KHR_materials_anisotropy", "anisotropyTexture");
        addExtensionTexture(out, material, "KHR_materials_iridescence", "iridescenceTexture");
        addExtensionTexture(out, material, "KHR_materials_iridescence", "iridescenceThicknessTexture");
        addExtensionTexture(out, material, "KHR_materials_transmission", "transmissionTexture");
        addExtensionTexture(out, material, "KHR_materials_volume", "thicknessTexture");
    }
    return out;
}

bool needsTangents(const tinygltf::Material& material) {
    if (material.normalTexture.index >= 0) return true;
    if (material.extensions.count("KHR_materials_unlit") != 0) return false;
    return clearcoatNormalTexture(material).has_value() || anisotropic(material);
}

int tangentTexCoord(const tinygltf::Material& material) {
    if (material.normalTexture.index >= 0)
        return effectiveTexCoord(material.normalTexture.texCoord, material.normalTexture.extensions) == 1.0 ? 1 : 0;
    if (!needsTangents(material)) return 0;
    // The coat's map alone: the tangents follow its UV set (glTF asks both maps to share one).
    std::optional<JsonTextureInfo> info = clearcoatNormalTexture(material);
    // Else the anisotropy's map's (the extension asks it to share the normal map's), else TEXCOORD_0.
    if (!info) info = extensionTexture(material, "KHR_materials_anisotropy", "anisotropyTexture");
    return info && effectiveTexCoord(info->texCoord, info->extensions) == 1.0 ? 1 : 0;
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
