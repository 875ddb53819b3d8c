#include "renderer/lights/spatial_order.h"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace ml {

namespace {

// The low 10 bits of v spread to every third bit (bits 0, 3, 6, ...).
std::uint32_t spreadBits(std::uint32_t v) {
    v &= 0x3FFu;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

std::uint32_t mortonCode(const Light& light, const Bounds& volume, const glm::vec3& scale) {
    if (light.type == LightType::Directional) return 0u;
    const glm::vec3 cell = glm::clamp((light.position - volume.min) * scale, glm::vec3(0.0f), glm::vec3(1023.0f));
    return spreadBits(std::uint32_t(cell.x)) | (spreadBits(std::uint32_t(cell.y)) << 1) | (spreadBits(std::uint32_t(cell.z)) << 2);
}

}  // namespace

void sortLightsSpatially(std::vector<Light>& lights, const Bounds& volume) {
    if (lights.size() < 2 || volume.empty()) return;
    const glm::vec3 size = volume.size();
    const glm::vec3 scale(size.x > 0.0f ? 1024.0f / size.x : 0.0f, size.y > 0.0f ? 1024.0f / size.y : 0.0f,
                          size.z > 0.0f ? 1024.0f / size.z : 0.0f);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keys(lights.size());  // (code, index): ties keep their order
    for (std::size_t i = 0; i < lights.size(); ++i) keys[i] = {mortonCode(lights[i], volume, scale), std::uint32_t(i)};
    std::sort(keys.begin(), keys.end());
    std::vector<Light> sorted;
    sorted.reserve(lights.size());
    for (const auto& key : keys) sorted.push_back(lights[key.second]);
    lights = std::move(sorted);
}

}  // namespace ml
