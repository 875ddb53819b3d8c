#include "renderer/scene/material_features.h"

#include <cmath>
#include <vector>

#include "glsl/include/bindings.h"

namespace ml {

std::uint32_t materialFeatures(const Scene& scene) {
    std::vector<bool> drawn(scene.materials.size(), false);
    for (const DrawRange& d : scene.draws)
        if (d.material < drawn.size()) drawn[d.material] = true;
    std::uint32_t f = 0;
    const auto uses = [&](const TextureRef& t) {
        if (!t.present()) return false;
        if (!t.transform.isIdentity()) f |= ML_FEATURE_TEXTURE_TRANSFORM;
        if (t.texCoord == 1 && !scene.uv1.empty()) f |= ML_FEATURE_UV1;
        return true;
    };
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (!drawn[i]) continue;
        const Material& m = scene.materials[i];
        uses(m.baseColorTexture);
        if (uses(m.metallicRoughnessTexture)) f |= ML_FEATURE_METALLIC_ROUGHNESS_MAP;
        // A normal map needs tangents; the loader and the procedural scenes provide them for
        // every vertex when any material has one.
        if (!scene.tangents.empty() && uses(m.normalTexture)) f |= ML_FEATURE_NORMAL_MAP;
        if (uses(m.occlusionTexture)) f |= ML_FEATURE_OCCLUSION_MAP;
        if (m.emissive != glm::vec3(0.0f)) {
            f |= ML_FEATURE_EMISSIVE;
            if (uses(m.emissiveTexture)) f |= ML_FEATURE_EMISSIVE_MAP;
        }
        if (m.unlit) f |= ML_FEATURE_UNLIT;
        if (m.specularModelled()) {
            f |= ML_FEATURE_SPECULAR;
            // Either map needs both slots' records (the specular slots come as a pair).
            if (uses(m.specularTexture) | uses(m.specularColorTexture)) f |= ML_FEATURE_SPECULAR_MAP;
        }
        if (m.clearcoatModelled()) {
            f |= ML_FEATURE_CLEARCOAT;
            // The three maps share one switch; the coat's normal map reads the tangent stream too.
            if (uses(m.clearcoatTexture) | uses(m.clearcoatRoughnessTexture)) f |= ML_FEATURE_CLEARCOAT_MAP;
            if (!scene.tangents.empty() && uses(m.clearcoatNormalTexture)) f |= ML_FEATURE_CLEARCOAT_MAP | ML_FEATURE_NORMAL_MAP;
        }
        if (m.sheenModelled()) {
            f |= ML_FEATURE_SHEEN;
            if (uses(m.sheenColorTexture) | uses(m.sheenRoughnessTexture)) f |= ML_FEATURE_SHEEN_MAP;
        }
        // The anisotropic lobe reads the tangent stream, as a normal map does; a scene without one
        // (which the loader always makes for it) shades the lobe isotropic, and prepareFrame says so.
        if (m.anisotropyModelled() && !scene.tangents.empty()) {
            f |= ML_FEATURE_ANISOTROPY | ML_FEATURE_NORMAL_MAP;
            if (uses(m.anisotropyTexture)) f |= ML_FEATURE_ANISOTROPY_MAP;
        }
        if (m.iridescenceModelled()) {
            f |= ML_FEATURE_IRIDESCENCE;
            if (uses(m.iridescenceTexture) | uses(m.iridescenceThicknessTexture)) f |= ML_FEATURE_IRIDESCENCE_MAP;
        }
        // Transmissive surfaces are drawn as glass: by the transparent pass, as BLEND is.
        if (m.transmissionModelled()) {
            f |= ML_FEATURE_TRANSMISSION;
            if (uses(m.transmissionTexture) | uses(m.thicknessTexture)) f |= ML_FEATURE_TRANSMISSION_MAP;
        }
        if (m.alphaTested()) f |= ML_FEATURE_ALPHA_TEST;
        if (m.drawnAsGlass()) f |= ML_FEATURE_BLEND;
    }
    if (!scene.colors.empty()) f |= ML_FEATURE_VERTEX_COLOR;
    return f;
}

shaders::Defines materialFeatureDefines(std::uint32_t features) {
    return {{"ML_MATERIAL_FEATURES", std::to_string(features)}};
}

std::string describeMaterialFeatures(std::uint32_t features) {
    static const std::pair<std::uint32_t, const char*> kNames[] = {
        {ML_FEATURE_METALLIC_ROUGHNESS_MAP, "metallic-roughness maps"},
        {ML_FEATURE_NORMAL_MAP, "normal maps"},
        {ML_FEATURE_OCCLUSION_MAP, "occlusion maps"},
        {ML_FEATURE_EMISSIVE, "emissive"},
        {ML_FEATURE_EMISSIVE_MAP, "emissive maps"},
        {ML_FEATURE_TEXTURE_TRANSFORM, "texture transforms"},
        {ML_FEATURE_UV1, "TEXCOORD_1"},
        {ML_FEATURE_VERTEX_COLOR, "vertex colours"},
        {ML_FEATURE_ALPHA_TEST, "alpha test"},
        {ML_FEATURE_BLEND, "transparency"},
        {ML_FEATURE_UNLIT, "unlit"},
        {ML_FEATURE_SPECULAR, "specular and IOR"},
        {ML_FEATURE_SPECULAR_MAP, "specular maps"},
        {ML_FEATURE_CLEARCOAT, "clearcoat"},
        {ML_FEATURE_CLEARCOAT_MAP, "clearcoat maps"},
        {ML_FEATURE_SHEEN, "sheen"},
        {ML_FEATURE_SHEEN_MAP, "sheen maps"},
        {ML_FEATURE_ANISOTROPY, "anisotropy"},
        {ML_FEATURE_ANISOTROPY_MAP, "anisotropy maps"},
        {ML_FEATURE_IRIDESCENCE, "iridescence"},
        {ML_FEATURE_IRIDESCENCE_MAP, "iridescence maps"},
        {ML_FEATURE_TRANSMISSION, "transmission and volume"},
        {ML_FEATURE_TRANSMISSION_MAP, "transmission maps"},
    };
    std::string text;
    for (const auto& [bit, name] : kNames) {
        if (!(features & bit)) continue;
        // An anisotropic lobe switches the tangent stream on as a normal map does (ML_FEATURE_NORMAL_MAP).
        const bool tangentsOnly = bit == ML_FEATURE_NORMAL_MAP && (features & ML_FEATURE_ANISOTROPY);
        text += std::string(text.empty() ? "" : ", ") + (tangentsOnly ? "tangents (normal maps or anisotropy)" : name);
    }
    return text.empty() ? "none" : text;
}

float dielectricF0(float ior) {
    const double r = (double(ior) - 1.0) / (double(ior) + 1.0);
    return static_cast<float>(r * r);
}

UvAffine uvAffine(const TextureTransform& t) {
    // KHR_texture_transform's rotation turns the UVs as glTF's sample viewer does: u' = c u + s v,
    // v' = -s u + c v (v runs down the image). The extension's README writes the GLSL matrix with
    // the opposite sign; the Khronos TextureTransformTest model (arrows onto a green marker, a red
    // one for the opposite direction) and the corpus test CorpusVisibleAnswer pin this one.
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    UvAffine a;
    a.column0 = glm::vec2(c, -s) * t.scale.x;
    a.column1 = glm::vec2(s, c) * t.scale.y;
    a.offset = t.offset;
    return a;
}

}  // namespace ml
