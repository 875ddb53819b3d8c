#include "renderer/scene/scene_gpu.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "glsl/include/bindings.h"
#include "renderer/gpu_types.h"
#include "renderer/scene/material_features.h"

namespace ml {
namespace {

// GL's layout of one multi-draw-indirect command.
struct DrawElementsIndirectCommand {
    std::uint32_t count, instanceCount, firstIndex, baseVertex, baseInstance;
};
static_assert(sizeof(DrawElementsIndirectCommand) == 20, "GL's indirect command layout");

constexpr GLuint kSlotUnits[ML_TEXTURE_SLOTS] = {ML_TEX_BASE_COLOR,       ML_TEX_METALLIC_ROUGHNESS,  ML_TEX_NORMAL,
                                                 ML_TEX_OCCLUSION,        ML_TEX_EMISSIVE,            ML_TEX_SPECULAR,
                                                 ML_TEX_SPECULAR_COLOR,   ML_TEX_CLEARCOAT,           ML_TEX_CLEARCOAT_ROUGHNESS,
                                                 ML_TEX_CLEARCOAT_NORMAL, ML_TEX_SHEEN_COLOR,         ML_TEX_SHEEN_ROUGHNESS,
                                                 ML_TEX_ANISOTROPY,       ML_TEX_IRIDESCENCE,         ML_TEX_IRIDESCENCE,
                                                 ML_TEX_TRANSMISSION,     ML_TEX_THICKNESS};
constexpr GLuint kUnitsBound = ML_TEX_THICKNESS + 1;

// Does this scene bind the slot's unit? The transmission maps' units lie past GL 4.5's minimum
// (bindings.h): only a scene that samples them binds them.
bool bindsSlot(int slot, std::uint32_t features) {
    return kSlotUnits[slot] < 16 || (features & ML_FEATURE_TRANSMISSION_MAP) != 0;
}

// Does the scene's material record hold every slot and the extensions' vec4s (bindings.h)?
bool extendedRecord(std::uint32_t features) { return (features & ML_FEATURES_EXTENDED_RECORD) != 0; }

// The slots a scene's material records and texture bindings hold: the extensions' only where some
// material models one (KHR_materials_specular or ior, KHR_materials_clearcoat, KHR_materials_sheen,
// KHR_materials_anisotropy, KHR_materials_iridescence, KHR_materials_transmission).
int materialSlots(std::uint32_t features) { return extendedRecord(features) ? ML_TEXTURE_SLOTS : ML_CORE_TEXTURE_SLOTS; }

// The texture slots whose shader path this scene compiles in (a slot whose feature is off is never sampled).
std::array<const TextureRef*, ML_TEXTURE_SLOTS> sampledSlots(const Material& m, std::uint32_t features) {
    std::array<const TextureRef*, ML_TEXTURE_SLOTS> slots{};
    slots[ML_SLOT_BASE_COLOR] = &m.baseColorTexture;
    if (features & ML_FEATURE_METALLIC_ROUGHNESS_MAP) slots[ML_SLOT_METALLIC_ROUGHNESS] = &m.metallicRoughnessTexture;
    if (features & ML_FEATURE_NORMAL_MAP) slots[ML_SLOT_NORMAL] = &m.normalTexture;
    if (features & ML_FEATURE_OCCLUSION_MAP) slots[ML_SLOT_OCCLUSION] = &m.occlusionTexture;
    if ((features & ML_FEATURE_EMISSIVE_MAP) && m.emissive != glm::vec3(0.0f)) slots[ML_SLOT_EMISSIVE] = &m.emissiveTexture;
    if ((features & ML_FEATURE_SPECULAR_MAP) && m.specularModelled()) {
        slots[ML_SLOT_SPECULAR] = &m.specularTexture;
        slots[ML_SLOT_SPECULAR_COLOR] = &m.specularColorTexture;
    }
    if ((features & ML_FEATURE_CLEARCOAT_MAP) && m.clearcoatModelled()) {
        slots[ML_SLOT_CLEARCOAT] = &m.clearcoatTexture;
        slots[ML_SLOT_CLEARCOAT_ROUGHNESS] = &m.clearcoatRoughnessTexture;
        if (features & ML_FEATURE_NORMAL_MAP) slots[ML_SLOT_CLEARCOAT_NORMAL] = &m.clearcoatNormalTexture;
    }
    if ((features & ML_FEATURE_SHEEN_MAP) && m.sheenModelled()) {
        slots[ML_SLOT_SHEEN_COLOR] = &m.sheenColorTexture;
        slots[ML_SLOT_SHEEN_ROUGHNESS] = &m.sheenRoughnessTexture;
    }
    if ((features & ML_FEATURE_ANISOTROPY_MAP) && m.anisotropyModelled()) slots[ML_SLOT_ANISOTROPY] = &m.anisotropyTexture;
    if ((features & ML_FEATURE_IRIDESCENCE_MAP) && m.iridescenceModelled()) {
        slots[ML_SLOT_IRIDESCENCE] = &m.iridescenceTexture;  // both on one unit: the loader made them one texture
        slots[ML_SLOT_IRIDESCENCE_THICKNESS] = &m.iridescenceThicknessTexture;
    }
    if ((features & ML_FEATURE_TRANSMISSION_MAP) && m.transmissionModelled()) {
        slots[ML_SLOT_TRANSMISSION] = &m.transmissionTexture;
        slots[ML_SLOT_THICKNESS] = &m.thicknessTexture;
    }
    return slots;
}

void setSamplerParameters(GLuint sampler, const Sampler& s) {
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, s.minFilter);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, s.magFilter);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, s.wrapS);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, s.wrapT);
}

gl::Handle<gl::SamplerDeleter> makeSampler(const std::string& name, const Sampler& s) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    gl::label(GL_SAMPLER, id, name);
    setSamplerParameters(id, s);
    return gl::Handle<gl::SamplerDeleter>(id);
}

}  // namespace

SceneGpu::SceneGpu(const Scene& scene, TriangleOrder order) : features_(ml::materialFeatures(scene)) {
    if (features_ & ML_FEATURE_TRANSMISSION_MAP) {
        // Units 16 and 17 (bindings.h): past GL 4.5's minimum, so asked of the GPU. The transparent
        // pass samples them in a compute shader, and the MSAA forward pass in a fragment shader.
        GLint fragment = 0, compute = 0;
        glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragment);
        glGetIntegerv(GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, &compute);
        if (std::min(fragment, compute) < GLint(kUnitsBound))
            throw std::runtime_error("the scene's KHR_materials_transmission or KHR_materials_volume textures need " +
                                     std::to_string(kUnitsBound) + " texture units a shader stage; this GPU offers " +
                                     std::to_string(std::min(fragment, compute)));
    }
    vertices_ = gl::Buffer::fromSpan<Vertex>("scene.vertices", scene.vertices, 0);

    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    vao_ = gl::Handle<gl::VertexArrayDeleter>(vao);
    gl::label(GL_VERTEX_ARRAY, vao, "scene.vao");
    // Rasterization reads the position alone (scene.vert, location 0); everything else a
    // fragment shades with it rebuilds from storage buffers (glsl/include/triangle_surface.glsl).
    glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(Vertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    // The optional streams, only where the scene's features read them.
    const auto sized = [&](std::size_t n) { return n == scene.vertices.size(); };
    if ((features_ & ML_FEATURE_NORMAL_MAP) && sized(scene.tangents.size()))
        tangents_ = gl::Buffer::fromSpan<glm::vec4>("scene.tangents", scene.tangents, 0);
    else  // no tangents: no normal maps, and the anisotropic lobe isotropic
        features_ &= ~std::uint32_t(ML_FEATURE_NORMAL_MAP | ML_FEATURE_ANISOTROPY | ML_FEATURE_ANISOTROPY_MAP);
    if ((features_ & ML_FEATURE_UV1) && sized(scene.uv1.size())) uv1_ = gl::Buffer::fromSpan<glm::vec2>("scene.uv1", scene.uv1, 0);
    else features_ &= ~std::uint32_t(ML_FEATURE_UV1);
    if ((features_ & ML_FEATURE_VERTEX_COLOR) && sized(scene.colors.size()))
        colors_ = gl::Buffer::fromSpan<glm::vec4>("scene.colors", scene.colors, 0);
    else
        features_ &= ~std::uint32_t(ML_FEATURE_VERTEX_COLOR);

    // Colour images in sRGB storage (sampling returns linear values), data images linear; full
    // mip chains, filtered and wrapped by the material's sampler objects.
    for (const Image& image : scene.images) {
        gl::Texture2D tex("texture." + image.name, image.srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height,
                          gl::fullMipLevels(image.width, image.height));
        // Scene images are stored top row first; glTF UVs put v = 0 at the top, so upload as is.
        glTextureSubImage2D(tex.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba8.data());
        glGenerateTextureMipmap(tex.id());
        textures_.push_back(std::move(tex));
    }
    for (std::size_t i = 0; i < scene.samplers.size(); ++i)
        samplers_.push_back(makeSampler("sampler." + std::to_string(i), scene.samplers[i]));
    defaultSampler_ = makeSampler("sampler.default", Sampler{});
    white_ = gl::Texture2D("texture.white", GL_SRGB8_ALPHA8, 1, 1);
    const std::uint8_t white[4] = {255, 255, 255, 255};
    glTextureSubImage2D(white_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);

    std::vector<GpuMaterial> materials;
    std::vector<int> materialSet;
    std::map<TextureSet, int> setIndex;
    for (const Material& m : scene.materials) {
        GpuMaterial g{};
        g.baseColorFactor = m.baseColorFactor;
        g.emissiveCutoff = glm::vec4(m.emissive, m.alphaCutoff);
        g.factors = glm::vec4(m.metallic, m.roughness, m.normalScale, m.occlusionStrength);
        g.specular = glm::vec4(dielectricF0(m.ior) * m.specularColorFactor, m.specularFactor);
        if (m.clearcoatModelled()) g.clearcoat = glm::vec4(m.clearcoatFactor, m.clearcoatRoughnessFactor, m.clearcoatNormalScale, 0.0f);
        if (m.sheenModelled()) g.sheen = glm::vec4(m.sheenColorFactor, m.sheenRoughnessFactor);
        if (m.anisotropyModelled())
            g.anisotropy = glm::vec4(std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation), m.anisotropyStrength, 0.0f);
        if (m.iridescenceModelled())
            g.iridescence = glm::vec4(m.iridescenceFactor, m.iridescenceIor, m.iridescenceThicknessMinimum, m.iridescenceThicknessMaximum);
        if (m.transmissionModelled()) {
            // The IOR itself (the specular record holds its F0): the refraction and the rough lobe's blur.
            g.transmission = glm::vec4(m.transmissionFactor, m.thicknessFactor, m.attenuationDistance, m.ior);
            g.attenuation = glm::vec4(m.attenuationColor, 0.0f);
            if (!m.blended()) {
                g.info.w |= ML_MATERIAL_TRANSMISSIVE_COVERAGE;
                if (!m.alphaTested()) g.emissiveCutoff.a = 0.0f;  // OPAQUE: covered wherever it is drawn
            }
        }
        if (m.unlit) g.info.w |= ML_MATERIAL_UNLIT;
        TextureSet set{};
        bool textured = false;
        const auto slots = sampledSlots(m, features_);
        for (int slot = 0; slot < materialSlots(features_); ++slot) {
            const UvAffine identity;
            g.uvTransforms[2 * slot] = glm::vec4(identity.column0, identity.column1);
            const TextureRef* ref = slots[slot];
            if (ref == nullptr || !ref->present() || ref->image >= static_cast<int>(textures_.size())) continue;
            const int sampler = ref->sampler >= 0 && ref->sampler < static_cast<int>(samplers_.size()) ? ref->sampler : -1;
            set[slot] = {ref->image, sampler};
            textured = true;
            g.info.x |= 1u << slot;
            if (ref->texCoord == 1 && (features_ & ML_FEATURE_UV1)) g.info.y |= 1u << slot;
            const UvAffine a = uvAffine(ref->transform);
            g.uvTransforms[2 * slot] = glm::vec4(a.column0, a.column1);
            g.uvTransforms[2 * slot + 1] = glm::vec4(a.offset, 0.0f, 0.0f);
        }
        int index = -1;
        if (textured) {
            auto [it, added] = setIndex.try_emplace(set, static_cast<int>(textureSets_.size()));
            if (added) textureSets_.push_back(set);
            index = it->second;
        }
        g.info.z = static_cast<std::uint32_t>(index + 1);
        if (m.doubleSided) g.info.w |= ML_MATERIAL_DOUBLE_SIDED;
        materials.push_back(g);
        materialSet.push_back(index);
    }
    if (materials.empty()) {
        GpuMaterial g{};
        g.baseColorFactor = glm::vec4(1.0f);
        g.factors = glm::vec4(0.0f, 0.5f, 1.0f, 1.0f);
        materials.push_back(g);
        materialSet.push_back(-1);
    }
    // Each record as the scene's shaders declare it (material.glsl): the core slots' part alone
    // where no material models an extension with maps, so that such a scene reads what it read before.
    const std::size_t recordVec4s = ML_GPU_MATERIAL_VEC4S(extendedRecord(features_));
    std::vector<glm::vec4> records;
    records.resize(materials.size() * recordVec4s);
    for (std::size_t i = 0; i < materials.size(); ++i) std::memcpy(&records[i * recordVec4s], &materials[i], recordVec4s * sizeof(glm::vec4));
    materials_ = gl::Buffer::fromSpan<glm::vec4>("scene.materials", records, 0);

    const auto materialOf = [&](const DrawRange& d) { return d.material < scene.materials.size() ? d.material : 0u; };

    // Draw ranges in group order (opaque before alpha-tested, then texture set, then sidedness),
    // for both submissions: where surfaces tie in depth the first drawn wins, so direct and
    // indirect must draw in the same order to give the same image. Transparent ranges come last
    // and belong to no group: only drawTransparent draws them, in its own order. Range i is drawn
    // with baseInstance i, so the per-draw attribute (divisor 1) reads element i.
    const auto blended = [&](const DrawRange& d) {
        const std::uint32_t m = materialOf(d);
        return m < scene.materials.size() && scene.materials[m].drawnAsGlass();
    };
    const auto groupOf = [&](const DrawRange& d) {
        const std::uint32_t m = materialOf(d);
        DrawGroup g;
        if (m < scene.materials.size()) {
            g.alphaTested = scene.materials[m].alphaTested() && (features_ & ML_FEATURE_ALPHA_TEST);
            g.doubleSided = scene.materials[m].doubleSided;
        }
        g.textureSet = materialSet[m];
        return g;
    };
    draws_ = scene.draws;
    std::stable_sort(draws_.begin(), draws_.end(), [&](const DrawRange& a, const DrawRange& b) {
        return std::tuple(blended(a), groupOf(a).key()) < std::tuple(blended(b), groupOf(b).key());
    });
    // The index buffer is laid out in the same order, so triangle ids (a range's first triangle
    // plus gl_PrimitiveID) grow with the draw order: the visibility raster keeps, per pixel, the
    // last fragment to pass its early depth test as the largest id (visibility.frag).
    const std::vector<std::uint32_t> ordered = orderTriangles(scene, order);
    std::vector<std::uint32_t> indices;
    indices.reserve(ordered.size());
    for (DrawRange& d : draws_) {
        const std::uint32_t first = static_cast<std::uint32_t>(indices.size());
        indices.insert(indices.end(), ordered.begin() + d.firstIndex, ordered.begin() + d.firstIndex + d.indexCount);
        d.firstIndex = first;
    }
    indexCount_ = indices.size();
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("scene.indices", indices, 0);
    glVertexArrayElementBuffer(vao, indices_.id());
    std::vector<std::uint32_t> triangleMaterials(indices.size() / 3, 0u);
    for (const DrawRange& d : draws_) std::fill_n(triangleMaterials.begin() + d.firstIndex / 3, d.indexCount / 3, materialOf(d));
    triangleMaterials_ = gl::Buffer::fromSpan<std::uint32_t>("scene.triangle-materials", triangleMaterials, 0);
    std::vector<glm::uvec2> params;
    std::vector<DrawElementsIndirectCommand> commands;
    for (std::uint32_t i = 0; i < draws_.size(); ++i) {
        const DrawRange& d = draws_[i];
        params.emplace_back(materialOf(d), d.firstIndex / 3);
        commands.push_back({d.indexCount, 1, d.firstIndex, 0, i});
        const DrawGroup g = groupOf(d);
        if (blended(d)) {
            TransparentRange t{i, g.textureSet, g.doubleSided, {}, {}, {}};
            for (std::uint32_t k = 0; k < d.indexCount; ++k) t.bounds.extend(scene.vertices[indices[d.firstIndex + k]].position);
            if (scene.animation) {
                t.vertices.assign(indices.begin() + d.firstIndex, indices.begin() + d.firstIndex + d.indexCount);
                std::sort(t.vertices.begin(), t.vertices.end());
                t.vertices.erase(std::unique(t.vertices.begin(), t.vertices.end()), t.vertices.end());
                for (std::uint32_t v : t.vertices) t.loaded.push_back(scene.vertices[v].position);
            }
            transparent_.push_back(t);
            continue;
        }
        if (!g.alphaTested) opaqueTriangles_ += d.indexCount / 3;
        else if (alphaTestedSpans_.empty() || alphaTestedSpans_.back().textureSet != g.textureSet)
            alphaTestedSpans_.push_back({g.textureSet, d.firstIndex / 3, d.indexCount / 3});
        else
            alphaTestedSpans_.back().count += d.indexCount / 3;
        if (groups_.empty() || groups_.back().key() != g.key()) {
            groups_.push_back(g);
            groups_.back().firstRange = i;
        }
        ++groups_.back().rangeCount;
    }
    if (params.empty()) params.emplace_back(0u, 0u);
    drawParams_ = gl::Buffer::fromSpan<glm::uvec2>("scene.draw-params", params, 0);
    glVertexArrayVertexBuffer(vao, 1, drawParams_.id(), 0, sizeof(glm::uvec2));
    glVertexArrayBindingDivisor(vao, 1, 1);
    glEnableVertexArrayAttrib(vao, 3);
    glVertexArrayAttribIFormat(vao, 3, 2, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(vao, 3, 1);
    if (commands.empty()) commands.push_back({0, 0, 0, 0, 0});
    commands_ = gl::Buffer::fromSpan<DrawElementsIndirectCommand>("scene.draw-commands", commands, 0);
}

DrawSubmission parseDrawSubmission(const std::string& text) {
    if (text == "direct") return DrawSubmission::Direct;
    if (text == "indirect") return DrawSubmission::Indirect;
    throw std::invalid_argument("--draw '" + text + "': expected direct or indirect");
}

const char* drawSubmissionName(DrawSubmission submission) {
    return submission == DrawSubmission::Indirect ? "indirect" : "direct";
}

void SceneGpu::bindTextureSet(int set) const {
    // Slots that share a unit (KHR_materials_iridescence's two maps) bind the one with a texture:
    // the loader made them one texture where both have one.
    std::array<bool, kUnitsBound> unitTextured{};
    for (int slot = 0; slot < materialSlots(features_); ++slot) {
        if (!bindsSlot(slot, features_)) continue;
        const SlotBinding b = set >= 0 && set < static_cast<int>(textureSets_.size()) ? textureSets_[static_cast<std::size_t>(set)][slot]
                                                                                     : SlotBinding{};
        if (b.texture < 0 && unitTextured[kSlotUnits[slot]]) continue;
        unitTextured[kSlotUnits[slot]] = b.texture >= 0;
        glBindTextureUnit(kSlotUnits[slot], b.texture >= 0 ? textures_[static_cast<std::size_t>(b.texture)].id() : white_.id());
        glBindSampler(kSlotUnits[slot], b.sampler >= 0 ? samplers_[static_cast<std::size_t>(b.sampler)].id() : defaultSampler_.id());
    }
}

std::size_t SceneGpu::drawCallsPerPass() const {
    return submission_ == DrawSubmission::Indirect ? groups_.size() : draws_.size();
}

void SceneGpu::setCullState(bool doubleSided) const {
    if (backfaceCulling_ && !doubleSided) glEnable(GL_CULL_FACE);  // GL's defaults: CCW front, cull back
    else glDisable(GL_CULL_FACE);
}

void SceneGpu::drawGroups(std::size_t first, std::size_t end) const {
    const std::uint32_t firstRange = groups_[first].firstRange;
    const std::uint32_t endRange = groups_[end - 1].firstRange + groups_[end - 1].rangeCount;
    if (submission_ == DrawSubmission::Indirect) {
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                    reinterpret_cast<const void*>(std::uintptr_t(firstRange) * sizeof(DrawElementsIndirectCommand)),
                                    static_cast<GLsizei>(endRange - firstRange), 0);
        return;
    }
    for (std::uint32_t i = firstRange; i < endRange; ++i) {
        const DrawRange& d = draws_[i];
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                                            reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)), 1, i);
    }
}

void SceneGpu::bindDrawState() const {
    glBindVertexArray(vao_.id());
    bindGeometryStorage();  // fragments rebuild their texture coordinates from their triangle
}

void SceneGpu::draw(const RasterProgram& program, Ranges which) const {
    bindDrawState();
    if (submission_ == DrawSubmission::Indirect) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
    const gl::Program* current = nullptr;
    for (std::size_t first = 0; first < groups_.size();) {
        const DrawGroup& g = groups_[first];
        if ((which == Ranges::Opaque && g.alphaTested) || (which == Ranges::AlphaTested && !g.alphaTested)) {
            ++first;
            continue;
        }
        const bool textured = program.readsMaterial() || g.alphaTested;
        std::size_t end = first + 1;
        // Without textures, one call covers every following group with the same cull state.
        if (!textured)
            while (end < groups_.size() && !groups_[end].alphaTested && groups_[end].doubleSided == g.doubleSided) ++end;
        const gl::Program& variant = program.variant(g.alphaTested);
        if (&variant != current) {
            variant.use();
            current = &variant;
        }
        if (textured) bindTextureSet(g.textureSet);
        setCullState(g.doubleSided);
        drawGroups(first, end);
        first = end;
    }
    if (submission_ == DrawSubmission::Indirect) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glDisable(GL_CULL_FACE);
    unbindSamplers();
}

std::vector<std::uint32_t> SceneGpu::transparentOrder(const glm::vec3& eye) const {
    std::vector<std::uint32_t> order(transparent_.size());
    std::vector<float> distance(transparent_.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) {
        order[i] = i;
        const glm::vec3 d = transparent_[i].bounds.center() - eye;
        distance[i] = glm::dot(d, d);
    }
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return distance[a] > distance[b]; });
    return order;
}

std::vector<int> SceneGpu::transparentTextureSets() const {
    std::vector<int> sets;
    for (const TransparentRange& r : transparent_) sets.push_back(r.textureSet);
    std::sort(sets.begin(), sets.end());
    sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
    return sets;
}

void SceneGpu::drawTransparent(const RasterProgram& program, const glm::vec3& eye) const {
    if (!hasTransparent()) return;
    bindDrawState();
    program.variant(false).use();
    for (std::uint32_t t : transparentOrder(eye)) {
        const TransparentRange& r = transparent_[t];
        bindTextureSet(r.textureSet);
        setCullState(r.doubleSided);
        const DrawRange& d = draws_[r.range];
        glDrawElementsInstancedBaseInstance(GL_TRIANGLES, static_cast<GLsizei>(d.indexCount), GL_UNSIGNED_INT,
                                            reinterpret_cast<const void*>(std::uintptr_t(d.firstIndex) * sizeof(std::uint32_t)), 1,
                                            r.range);
    }
    glDisable(GL_CULL_FACE);
    unbindSamplers();
}

std::optional<glm::vec2> SceneGpu::transparentDepthRange(const glm::mat4& view, float cameraNear, float cameraFar) const {
    if (!hasTransparent()) return std::nullopt;
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (const TransparentRange& r : transparent_) {
        // View depth is linear in the position, so a box's extremes are at its corners.
        for (int k = 0; k < 8; ++k) {
            const glm::vec3 p((k & 1) ? r.bounds.max.x : r.bounds.min.x, (k & 2) ? r.bounds.max.y : r.bounds.min.y,
                              (k & 4) ? r.bounds.max.z : r.bounds.min.z);
            const float depth = -(view * glm::vec4(p, 1.0f)).z;
            lo = std::min(lo, depth);
            hi = std::max(hi, depth);
        }
    }
    if (hi < cameraNear || lo > cameraFar) return std::nullopt;
    return glm::vec2(std::max(lo, cameraNear), std::min(hi, cameraFar));
}

std::optional<glm::ivec4> SceneGpu::transparentScreenRect(const glm::mat4& viewProj, int width, int height) const {
    if (!hasTransparent()) return std::nullopt;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const TransparentRange& r : transparent_) {
        for (int k = 0; k < 8; ++k) {
            const glm::vec3 p((k & 1) ? r.bounds.max.x : r.bounds.min.x, (k & 2) ? r.bounds.max.y : r.bounds.min.y,
                              (k & 4) ? r.bounds.max.z : r.bounds.min.z);
            const glm::vec4 clip = viewProj * glm::vec4(p, 1.0f);
            if (clip.w <= 0.0f) return glm::ivec4(0, 0, width, height);
            const glm::vec2 window = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width, height);
            lo = glm::min(lo, window);
            hi = glm::max(hi, window);
        }
    }
    // Widened by a pixel each side: the box's projection is exact, the rounding of it is not.
    const glm::ivec2 a = glm::max(glm::ivec2(glm::floor(glm::max(lo, glm::vec2(-1.0f)))) - 1, glm::ivec2(0));
    const glm::ivec2 b = glm::min(glm::ivec2(glm::ceil(glm::min(hi, glm::vec2(width + 1, height + 1)))) + 1, glm::ivec2(width, height));
    if (a.x >= b.x || a.y >= b.y) return std::nullopt;
    return glm::ivec4(a, b - a);
}

void SceneGpu::unbindSamplers() const {
    for (int slot = 0; slot < ML_TEXTURE_SLOTS; ++slot)
        if (bindsSlot(slot, features_)) glBindSampler(kSlotUnits[slot], 0);
}

void SceneGpu::refitTransparentBounds(const std::function<glm::vec3(std::uint32_t, const glm::vec3&)>& posed) {
    for (TransparentRange& range : transparent_) {
        if (range.vertices.empty()) continue;
        range.bounds = Bounds{};
        for (std::size_t i = 0; i < range.vertices.size(); ++i) range.bounds.extend(posed(range.vertices[i], range.loaded[i]));
    }
}

void SceneGpu::bindVertexStreamsForWriting() const {
    vertices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTICES);
    if (tangents_) tangents_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTEX_TANGENTS);
}

void SceneGpu::bindGeometryStorage() const {
    vertices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTICES);
    indices_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_INDICES);
    triangleMaterials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_TRIANGLE_MATERIALS);
    materials_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_MATERIALS);
    if (tangents_) tangents_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTEX_TANGENTS);
    if (uv1_) uv1_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTEX_UV1);
    if (colors_) colors_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_VERTEX_COLORS);
}

std::size_t SceneGpu::bytes() const {
    return vertices_.size() + indices_.size() + materials_.size() + triangleMaterials_.size() + tangents_.size() + uv1_.size() +
           colors_.size();
}

}  // namespace ml
