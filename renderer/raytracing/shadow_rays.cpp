#include "renderer/raytracing/shadow_rays.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "glsl/include/bindings.h"
#include "renderer/raytracing/shadow_alpha.h"
#include "renderer/raytracing/shadow_bvh.h"

namespace ml {

ShadowRays::ShadowRays(const Scene& scene, std::uint32_t width, bool followsPose) {
    ShadowBvh bvh = buildShadowBvh(scene, width);
    const ShadowAlphaMasks masks = buildShadowAlphaMasks(scene, bvh);
    stats_.triangles = bvh.triangles.size();
    stats_.width = bvh.width;
    stats_.nodes = bvh.nodeCount();
    stats_.depth = bvh.depth;
    stats_.buildSeconds = bvh.buildSeconds;
    if (bvh.nodes.empty()) return;
    const std::size_t nodeBytes = bvh.nodes.size() * sizeof(glm::vec4);
    const std::size_t triangleBytes = bvh.triangles.size() * sizeof(GpuBvhTriangle);
    const std::size_t uvBytes = masks.uvs.size() * sizeof(glm::vec4), materialBytes = masks.materials.size() * sizeof(glm::vec4);
    stats_.maskTriangles = bvh.maskTriangles;
    stats_.bytes = nodeBytes + triangleBytes + uvBytes + materialBytes;
    GLint64 maxBlock = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    if (maxBlock > 0 && stats_.bytes > static_cast<std::size_t>(maxBlock))
        throw std::invalid_argument(scene.name + ": the shadow rays' BVH takes " + std::to_string(stats_.bytes >> 20) +
                                    " MiB, more than this GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" +
                                    std::to_string(maxBlock >> 20) + " MiB); --shadows off renders it unshadowed");
    static_assert(sizeof(GpuBvhTriangle) % 16 == 0);
    firstTriangle_ = static_cast<std::uint32_t>(nodeBytes / 16);
    firstMaterial_ = static_cast<std::uint32_t>((nodeBytes + triangleBytes + uvBytes) / 16);
    // The header (the ray count, zero), then the array the shaders index.
    std::vector<unsigned char> bytes(kHeaderBytes + stats_.bytes);
    unsigned char* at = bytes.data() + kHeaderBytes;
    std::memcpy(at, bvh.nodes.data(), nodeBytes);
    std::memcpy(at + nodeBytes, bvh.triangles.data(), triangleBytes);
    if (uvBytes > 0) std::memcpy(at + nodeBytes + triangleBytes, masks.uvs.data(), uvBytes);
    if (materialBytes > 0) std::memcpy(at + nodeBytes + triangleBytes + uvBytes, masks.materials.data(), materialBytes);
    stats_.bytes += kHeaderBytes;
    buffer_ = gl::Buffer("shadows.bvh", bytes.size(), bytes.data(), 0);
    if (masks.layerCount > 0) {
        // One R8 layer per MASK image; level 0 alone, read with textureLod (shadow_alpha.h).
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
        alphaLayers_ = gl::Handle<gl::TextureDeleter>(id);
        glObjectLabel(GL_TEXTURE, id, -1, "shadows.alpha");
        glTextureStorage3D(id, 1, GL_R8, masks.layerSize, masks.layerSize, masks.layerCount);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage3D(id, 0, 0, 0, 0, masks.layerSize, masks.layerSize, masks.layerCount, GL_RED, GL_UNSIGNED_BYTE,
                            masks.texels.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
        stats_.bytes += masks.texels.size();
    }
    directionalReach_ = 2.0f * glm::length(bvh.bounds.size()) + 1.0f;
    if (followsPose) {
        refit_ = std::make_unique<ShadowBvhRefit>(scene, bvh, firstTriangle_);
        stats_.refitLevels = refit_->levels();
        stats_.bytes += refit_->bytes();
        // A pose may reach past the loaded pose's bounds: the sun's rays go four times as far.
        directionalReach_ = 8.0f * glm::length(bvh.bounds.size()) + 1.0f;
    }
}

void ShadowRays::refit(const SceneGpu& scene) const {
    if (refit_ && !empty()) refit_->run(buffer_, scene);
}

void ShadowRays::bindForShading() const {
    if (empty()) return;
    buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_SHADOW_BVH);
    if (alphaLayers_) glBindTextureUnit(ML_TEX_SHADOW_ALPHA, alphaLayers_.id());
}

void ShadowRays::resetRayCount() const {
    if (empty()) return;
    const GLuint zero = 0;
    glClearNamedBufferSubData(buffer_.id(), GL_R32UI, 0, 8, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

std::uint64_t ShadowRays::rayCount() const {
    if (empty()) return 0;
    std::uint32_t words[2] = {0, 0};
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    buffer_.download(words, sizeof words);
    return (static_cast<std::uint64_t>(words[1]) << 32) | words[0];
}

glm::uvec4 ShadowRays::uniforms() const {
    return glm::uvec4(firstTriangle_, static_cast<std::uint32_t>(stats_.nodes), static_cast<std::uint32_t>(stats_.triangles), firstMaterial_);
}

}  // namespace ml
