#include "renderer/raytracing/shadow_alpha.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>

#include "renderer/scene/material_features.h"

namespace ml {
namespace {

// The largest layer: 2048^2 bytes a layer (Sponza's three MASK images are 1024^2).
constexpr int kMaxLayerSize = 2048;

int layerOf(const Material& m, const Scene& scene) {
    const int image = m.baseColorTexture.image;
    return image >= 0 && image < static_cast<int>(scene.images.size()) && scene.images[image].width > 0 ? image : -1;
}

glm::vec2 uvOf(const Scene& scene, std::uint32_t vertex, int texCoord) {
    return texCoord == 1 && scene.uv1.size() == scene.vertices.size() ? scene.uv1[vertex] : scene.vertices[vertex].uv;
}

// Bilinear, texel centres at (i + 0.5) / size, repeat wrap: what GL_LINEAR at level 0 computes.
float sampleRepeat(const std::uint8_t* texels, int width, int height, int stride, glm::vec2 uv) {
    const float x = uv.x * float(width) - 0.5f, y = uv.y * float(height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const auto at = [&](int i, int j) {
        i = ((i % width) + width) % width;
        j = ((j % height) + height) % height;
        return float(texels[(static_cast<std::size_t>(j) * width + i) * stride]) / 255.0f;
    };
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);
    return (1.0f - ay) * ((1.0f - ax) * at(i, j) + ax * at(i + 1, j)) + ay * ((1.0f - ax) * at(i, j + 1) + ax * at(i + 1, j + 1));
}

}  // namespace

ShadowAlphaMasks buildShadowAlphaMasks(const Scene& scene, ShadowBvh& bvh) {
    ShadowAlphaMasks masks;
    if (bvh.maskTriangles == 0) return masks;

    // A layer per image that a MASK material's base colour reads, in image order.
    std::map<int, int> layerOfImage;
    for (const GpuBvhTriangle& t : bvh.triangles) {
        const std::uint32_t material = std::bit_cast<std::uint32_t>(t.v0.w);
        if (material == kShadowOpaque) continue;
        const int image = layerOf(scene.materials.at(material), scene);
        if (image >= 0) layerOfImage.emplace(image, 0);
    }
    for (auto& [image, layer] : layerOfImage) {
        layer = masks.layerCount++;
        masks.layerSize = std::max({masks.layerSize, scene.images[image].width, scene.images[image].height});
    }
    masks.layerSize = std::min(masks.layerSize, kMaxLayerSize);
    const int n = masks.layerSize;
    masks.texels.resize(static_cast<std::size_t>(n) * n * masks.layerCount);
    for (const auto& [image, layer] : layerOfImage) {
        const Image& source = scene.images[image];
        std::uint8_t* out = &masks.texels[static_cast<std::size_t>(layer) * n * n];
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec2 uv((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
                const float a = source.width == n && source.height == n
                                    ? float(source.rgba8[(static_cast<std::size_t>(j) * n + i) * 4 + 3]) / 255.0f
                                    : sampleRepeat(source.rgba8.data() + 3, source.width, source.height, 4, uv);
                out[static_cast<std::size_t>(j) * n + i] = static_cast<std::uint8_t>(std::lround(a * 255.0f));
            }
    }

    masks.materials.assign(3 * scene.materials.size(), glm::vec4(0.0f));
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& material = scene.materials[m];
        if (!material.alphaTested()) continue;
        const UvAffine a = uvAffine(material.baseColorTexture.transform);
        const int image = layerOf(material, scene);
        const int layer = image >= 0 ? layerOfImage.at(image) : -1;
        masks.materials[3 * m] = glm::vec4(a.column0, a.column1);
        masks.materials[3 * m + 1] = glm::vec4(a.offset, material.alphaCutoff, material.baseColorFactor.a);
        masks.materials[3 * m + 2] = glm::vec4(std::bit_cast<float>(layer), 0.0f, 0.0f, 0.0f);
    }

    for (GpuBvhTriangle& t : bvh.triangles) {
        const std::uint32_t material = std::bit_cast<std::uint32_t>(t.v0.w);
        if (material == kShadowOpaque) continue;
        const std::uint32_t triangle = std::bit_cast<std::uint32_t>(t.v1.w);
        const int set = scene.materials.at(material).baseColorTexture.texCoord;
        const glm::vec2 uv0 = uvOf(scene, scene.indices.at(3 * triangle), set), uv1 = uvOf(scene, scene.indices.at(3 * triangle + 1), set),
                        uv2 = uvOf(scene, scene.indices.at(3 * triangle + 2), set);
        t.v2.w = std::bit_cast<float>(static_cast<std::uint32_t>(masks.uvs.size() / 2));
        masks.uvs.push_back(glm::vec4(uv0, uv1));
        masks.uvs.push_back(glm::vec4(uv2, 0.0f, 0.0f));
    }
    return masks;
}

ShadowCoverage shadowAlphaCoverage(const Scene& scene, const ShadowAlphaMasks& masks) {
    return [&scene, &masks](std::uint32_t material, std::uint32_t sceneTriangle, float u, float v) {
        const int set = scene.materials.at(material).baseColorTexture.texCoord;
        const glm::vec2 uv0 = uvOf(scene, scene.indices.at(3 * sceneTriangle), set),
                        uv1 = uvOf(scene, scene.indices.at(3 * sceneTriangle + 1), set),
                        uv2 = uvOf(scene, scene.indices.at(3 * sceneTriangle + 2), set);
        const glm::vec4* record = &masks.materials.at(3 * material);
        const glm::vec2 uv = (1.0f - u - v) * uv0 + u * uv1 + v * uv2;
        const glm::vec2 transformed = glm::vec2(record[0].x, record[0].y) * uv.x + glm::vec2(record[0].z, record[0].w) * uv.y +
                                      glm::vec2(record[1].x, record[1].y);
        float alpha = record[1].w;
        const int layer = std::bit_cast<int>(record[2].x);
        if (layer >= 0) {
            const int n = masks.layerSize;
            alpha *= sampleRepeat(&masks.texels[static_cast<std::size_t>(layer) * n * n], n, n, 1, transformed);
        }
        return alpha >= record[1].z;
    };
}

}  // namespace ml
