#include "renderer/raytracing/shadow_bvh_traversal.h"

#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ml {

namespace {

// GLSL's min and max, operand for operand (they differ from std::min/max only with NaN, which
// the arithmetic above never makes).
float glslMin(float x, float y) { return y < x ? y : x; }
float glslMax(float x, float y) { return x < y ? y : x; }

glm::vec3 cross3(const glm::vec3& a, const glm::vec3& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
float dot3(const glm::vec3& a, const glm::vec3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

float inverseOf(float d) {
    const float kTiny = 1e-30f;
    return 1.0f / (std::fabs(d) < kTiny ? (d < 0.0f ? -kTiny : kTiny) : d);
}

float offsetCoordinate(float p, float n) {
    const float kOrigin = 1.0f / 32.0f, kFloatScale = 1.0f / 65536.0f, kIntScale = 256.0f;
    const std::int32_t offset = static_cast<std::int32_t>(kIntScale * n);  // toward zero, as GLSL's int()
    const std::int32_t bits = std::bit_cast<std::int32_t>(p);
    const float moved = std::bit_cast<float>(p < 0.0f ? bits - offset : bits + offset);
    return std::fabs(p) < kOrigin ? p + kFloatScale * n : moved;
}

}  // namespace

glm::vec3 shadowRayInverse(glm::vec3 d) { return {inverseOf(d.x), inverseOf(d.y), inverseOf(d.z)}; }

bool shadowBoxHit(glm::vec3 lo, glm::vec3 hi, glm::vec3 origin, glm::vec3 inverse, float tMax) {
    const glm::vec3 t0 = (lo - origin) * inverse, t1 = (hi - origin) * inverse;
    const glm::vec3 tNear(glslMin(t0.x, t1.x), glslMin(t0.y, t1.y), glslMin(t0.z, t1.z));
    const glm::vec3 tFar(glslMax(t0.x, t1.x), glslMax(t0.y, t1.y), glslMax(t0.z, t1.z));
    const float enter = glslMax(glslMax(tNear.x, tNear.y), glslMax(tNear.z, 0.0f));
    const float leave = glslMin(glslMin(tFar.x, tFar.y), glslMin(tFar.z, tMax));
    return enter <= leave;
}

bool shadowTriangleHit(const GpuBvhTriangle& triangle, glm::vec3 origin, glm::vec3 direction, float tMax, float& u, float& v) {
    const glm::vec3 a(triangle.v0), b(triangle.v1), c(triangle.v2);
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = cross3(direction, e2);
    const float det = dot3(e1, p);
    if (det == 0.0f) return false;
    const float inv = 1.0f / det;
    const glm::vec3 s = origin - a;
    u = dot3(s, p) * inv;
    if (u < 0.0f || u > 1.0f) return false;
    const glm::vec3 q = cross3(s, e1);
    v = dot3(direction, q) * inv;
    if (v < 0.0f || u + v > 1.0f) return false;
    const float t = dot3(e2, q) * inv;
    return t > 0.0f && t < tMax;
}

bool occludedByBvh(const ShadowBvh& bvh, glm::vec3 origin, glm::vec3 direction, float tMax, const ShadowCoverage& covered,
                   ShadowTraversalCounts* counts) {
    const std::size_t nodes = bvh.nodeCount();
    const auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    if (nodes == 0 || !finite(origin) || !finite(direction) || !std::isfinite(tMax)) return false;
    ShadowTraversalCounts ignored;
    ShadowTraversalCounts& work = counts ? *counts : ignored;
    ++work.rays;
    const glm::vec3 inverse = shadowRayInverse(direction);
    std::uint32_t stack[ML_SHADOW_STACK];
    std::uint32_t top = 0;
    stack[top++] = 0u;
    const auto push = [&](std::uint32_t reference) {
        if (top >= static_cast<std::uint32_t>(ML_SHADOW_STACK))
            throw std::logic_error("shadow BVH traversal: the stack of " + std::to_string(ML_SHADOW_STACK) +
                                   " references overflowed (tree depth " + std::to_string(bvh.depth) + ")");
        stack[top++] = reference;
        ++work.pushes;
    };
    const std::size_t references = bvh.width * nodes;
    std::size_t step = 0;
    for (; top > 0 && step <= references; ++step) {
        const std::uint32_t reference = stack[--top];
        if (shadowReferenceIsLeaf(reference)) {
            const std::uint32_t first = shadowLeafFirst(reference), count = shadowLeafCount(reference);
            for (std::uint32_t i = 0; i < count; ++i) {
                const GpuBvhTriangle& triangle = bvh.triangles.at(first + i);
                float u = 0.0f, v = 0.0f;
                ++work.triangles;
                if (!shadowTriangleHit(triangle, origin, direction, tMax, u, v)) continue;
                const std::uint32_t material = glm::floatBitsToUint(triangle.v0.w);
                if (material == kShadowOpaque || !covered || covered(material, glm::floatBitsToUint(triangle.v1.w), u, v))
                    return true;
            }
            continue;
        }
        if (reference >= nodes) throw std::logic_error("shadow BVH traversal: node " + std::to_string(reference) + " past the end");
        ++work.nodes;
        for (std::uint32_t slot = 0; slot < bvh.width; ++slot) {
            const ShadowBvhChild child = shadowNodeChild(bvh.node(reference), bvh.width, slot);
            if (!child.present) continue;
            ++work.boxes;
            if (shadowBoxHit(child.lo, child.hi, origin, inverse, tMax)) push(child.reference);
        }
    }
    if (top > 0)
        throw std::logic_error("shadow BVH traversal: more than width * nodes + 1 = " + std::to_string(references + 1) +
                               " references popped; the tree is not a tree");
    return false;
}

glm::vec3 shadowRayOrigin(glm::vec3 p, glm::vec3 n) {
    return {offsetCoordinate(p.x, n.x), offsetCoordinate(p.y, n.y), offsetCoordinate(p.z, n.z)};
}

}  // namespace ml
