#include "renderer/raytracing/shadow_bvh_layout.h"

namespace ml {

namespace {

// The wide node's group of four that holds `slot`.
template <typename Vec4>
Vec4* groupOf(Vec4* node, std::uint32_t slot) { return node + (slot / 4) * ML_SHADOW_WIDE_GROUP_VEC4S; }

}  // namespace

ShadowBvhChild shadowNodeChild(const glm::vec4* node, std::uint32_t width, std::uint32_t slot) {
    ShadowBvhChild child;
    if (width == 2) {
        const glm::vec4* box = node + 2 * slot;
        child.lo = glm::vec3(box[0]);
        child.hi = glm::vec3(box[1]);
        child.reference = glm::floatBitsToUint(node[slot].w);
        child.present = true;
        return child;
    }
    const glm::vec4* g = groupOf(node, slot);
    const int k = static_cast<int>(slot % 4);
    child.lo = {g[0][k], g[2][k], g[4][k]};
    child.hi = {g[1][k], g[3][k], g[5][k]};
    child.reference = glm::floatBitsToUint(g[6][k]);
    child.present = child.reference != 0u;
    return child;
}

void setShadowNodeChild(glm::vec4* node, std::uint32_t width, std::uint32_t slot, const ShadowBvhChild& child) {
    if (width == 2) {
        glm::vec4* box = node + 2 * slot;
        box[0] = glm::vec4(child.lo, box[0].w);
        box[1] = glm::vec4(child.hi, box[1].w);
        node[slot].w = glm::uintBitsToFloat(child.reference);
        return;
    }
    glm::vec4* g = groupOf(node, slot);
    const int k = static_cast<int>(slot % 4);
    g[0][k] = child.lo.x, g[2][k] = child.lo.y, g[4][k] = child.lo.z;
    g[1][k] = child.hi.x, g[3][k] = child.hi.y, g[5][k] = child.hi.z;
    g[6][k] = glm::uintBitsToFloat(child.reference);
}

}  // namespace ml
