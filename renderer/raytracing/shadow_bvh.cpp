#include "renderer/raytracing/shadow_bvh.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <new>
#include <stdexcept>
#include <string>

#include "renderer/raytracing/embree_device.h"
#include "renderer/raytracing/shadow_casters.h"

namespace ml {

namespace {

// Embree's tree, in nodes of our own that its callbacks make (from its thread-local allocator:
// they live as long as the RTCBVH) before the flattening lays them out for the GPU.
struct BuildNode {
    bool leaf;
};
struct InnerNode {
    BuildNode base{false};
    const BuildNode* children[2] = {nullptr, nullptr};
    RTCBounds bounds[2];
};
struct LeafNode {
    BuildNode base{true};
    std::uint32_t count = 0;
    std::uint32_t casters[kShadowBvhMaxLeafSize];
};

// What the callbacks share; they run on Embree's build threads and must not throw.
struct BuildState {
    std::atomic<bool> malformed{false};  // a node or leaf the layout cannot hold
};

void* createNode(RTCThreadLocalAllocator allocator, unsigned int childCount, void* user) {
    if (childCount != 2) static_cast<BuildState*>(user)->malformed = true;
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(InnerNode), alignof(InnerNode));
    return memory != nullptr ? new (memory) InnerNode() : nullptr;
}

void setNodeChildren(void* node, void** children, unsigned int childCount, void* user) {
    if (node == nullptr || childCount != 2) {
        static_cast<BuildState*>(user)->malformed = true;
        return;
    }
    auto* inner = static_cast<InnerNode*>(node);
    for (unsigned i = 0; i < 2; ++i) inner->children[i] = static_cast<const BuildNode*>(children[i]);
}

void setNodeBounds(void* node, const RTCBounds** bounds, unsigned int childCount, void* user) {
    if (node == nullptr || childCount != 2) {
        static_cast<BuildState*>(user)->malformed = true;
        return;
    }
    auto* inner = static_cast<InnerNode*>(node);
    for (unsigned i = 0; i < 2; ++i) inner->bounds[i] = *bounds[i];
}

void* createLeaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive* primitives, size_t count, void* user) {
    if (count == 0 || count > kShadowBvhMaxLeafSize) {
        static_cast<BuildState*>(user)->malformed = true;
        count = count == 0 ? 0 : kShadowBvhMaxLeafSize;
    }
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(LeafNode), alignof(LeafNode));
    if (memory == nullptr) return nullptr;
    auto* leaf = new (memory) LeafNode();
    leaf->count = static_cast<std::uint32_t>(count);
    for (size_t i = 0; i < count; ++i) leaf->casters[i] = primitives[i].primID;
    return leaf;
}

glm::vec4 point(const glm::vec3& p, std::uint32_t w) { return glm::vec4(p, glm::uintBitsToFloat(w)); }

class Flattener {
public:
    Flattener(const std::vector<ShadowCaster>& casters, const std::string& subject, ShadowBvh& out)
        : casters_(casters), subject_(subject), out_(out) {}

    // The reference to `node`, whose nodes and triangles are appended depth-first; `level` is
    // the level `node` would take as an inner node (the root's: 1).
    std::uint32_t emit(const BuildNode* node, std::uint32_t level) {
        if (node == nullptr) throw std::runtime_error(subject_ + ": Embree's shadow BVH has a missing child");
        if (node->leaf) return emitLeaf(reinterpret_cast<const LeafNode*>(node));
        if (level > kShadowBvhMaxDepth)
            throw std::runtime_error(subject_ + ": the shadow BVH is deeper than " + std::to_string(kShadowBvhMaxDepth) +
                                     " levels, more than the traversal's stack of " + std::to_string(ML_SHADOW_STACK) + " holds");
        const auto* inner = reinterpret_cast<const InnerNode*>(node);
        const std::size_t index = out_.nodes.size();
        if (index >= kShadowLeafBit) throw std::runtime_error(subject_ + ": the shadow BVH has more than 2^31 nodes");
        out_.nodes.emplace_back();
        out_.depth = std::max(out_.depth, level);
        const std::uint32_t left = emit(inner->children[0], level + 1);
        const std::uint32_t right = emit(inner->children[1], level + 1);
        const RTCBounds& l = inner->bounds[0];
        const RTCBounds& r = inner->bounds[1];
        GpuBvhNode& n = out_.nodes[index];
        n.leftMin = point({l.lower_x, l.lower_y, l.lower_z}, left);
        n.leftMax = point({l.upper_x, l.upper_y, l.upper_z}, right);
        n.rightMin = point({r.lower_x, r.lower_y, r.lower_z}, 0u);
        n.rightMax = point({r.upper_x, r.upper_y, r.upper_z}, 0u);
        return static_cast<std::uint32_t>(index);
    }

    std::uint32_t emitLeaf(const LeafNode* leaf) {
        const std::size_t first = out_.triangles.size();
        for (std::uint32_t i = 0; i < leaf->count; ++i) {
            const ShadowCaster& c = casters_.at(leaf->casters[i]);
            out_.triangles.push_back(GpuBvhTriangle{point(c.corners[0], c.material), point(c.corners[1], c.sceneTriangle),
                                                    point(c.corners[2], 0u)});
            if (c.material != kShadowOpaque) ++out_.maskTriangles;
        }
        ++out_.leaves;
        return shadowLeafReference(static_cast<std::uint32_t>(first), leaf->count);
    }

private:
    const std::vector<ShadowCaster>& casters_;
    const std::string& subject_;
    ShadowBvh& out_;
};

}  // namespace

ShadowBvh buildShadowBvh(const Scene& scene) {
    const std::string subject = "scene " + scene.name;
    const std::vector<ShadowCaster> casters = shadowCasters(scene);
    if (casters.size() > kShadowTriangleLimit)
        throw std::runtime_error(subject + ": " + std::to_string(casters.size()) +
                                 " triangles, more than the shadow structure's 2^28");
    ShadowBvh out;
    for (const ShadowCaster& c : casters)
        for (const glm::vec3& p : c.corners) out.bounds.extend(p);
    if (casters.empty()) return out;

    EmbreeDevice device(subject);
    const auto start = std::chrono::steady_clock::now();

    std::vector<RTCBuildPrimitive> primitives(casters.size());
    for (std::size_t i = 0; i < casters.size(); ++i) {
        const ShadowCaster& c = casters[i];
        const glm::vec3 lo = glm::min(glm::min(c.corners[0], c.corners[1]), c.corners[2]);
        const glm::vec3 hi = glm::max(glm::max(c.corners[0], c.corners[1]), c.corners[2]);
        primitives[i] = RTCBuildPrimitive{lo.x, lo.y, lo.z, 0u, hi.x, hi.y, hi.z, static_cast<unsigned>(i)};
    }

    RTCBVH bvh = rtcNewBVH(device.get());
    device.check("make a BVH");
    struct ReleaseBvh {
        RTCBVH bvh;
        ~ReleaseBvh() { rtcReleaseBVH(bvh); }
    } release{bvh};

    BuildState state;
    RTCBuildArguments args = rtcDefaultBuildArguments();
    args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;  // binned SAH; see the header
    args.maxBranchingFactor = 2;
    args.maxDepth = kShadowBvhMaxDepth;  // Embree refuses, rather than exceeds, it; emit() checks ours again
    args.sahBlockSize = 1;
    args.minLeafSize = 1;
    args.maxLeafSize = kShadowBvhMaxLeafSize;
    args.traversalCost = kShadowBvhTraversalCost;
    args.intersectionCost = kShadowBvhIntersectionCost;
    args.bvh = bvh;
    args.primitives = primitives.data();
    args.primitiveCount = primitives.size();
    args.primitiveArrayCapacity = primitives.size();  // no spatial splits
    args.createNode = createNode;
    args.setNodeChildren = setNodeChildren;
    args.setNodeBounds = setNodeBounds;
    args.createLeaf = createLeaf;
    args.userPtr = &state;
    const BuildNode* root = static_cast<const BuildNode*>(rtcBuildBVH(&args));
    device.check("build the shadow BVH");
    if (root == nullptr) throw std::runtime_error(subject + ": Embree built no shadow BVH");
    if (state.malformed)
        throw std::runtime_error(subject + ": Embree's shadow BVH has a node or leaf outside the layout (2 children, 1 to " +
                                 std::to_string(kShadowBvhMaxLeafSize) + " triangles a leaf)");

    out.nodes.reserve(casters.size());
    out.triangles.reserve(casters.size());
    Flattener flattener(casters, subject, out);
    if (root->leaf) {
        // One leaf: node 0 holds it on the left, and on the right the same leaf behind an empty box.
        out.nodes.emplace_back();
        out.depth = 1;
        const std::uint32_t leaf = flattener.emitLeaf(reinterpret_cast<const LeafNode*>(root));
        constexpr float inf = std::numeric_limits<float>::infinity();
        GpuBvhNode& n = out.nodes[0];
        n.leftMin = point(out.bounds.min, leaf);
        n.leftMax = point(out.bounds.max, leaf);
        n.rightMin = point(glm::vec3(inf), 0u);
        n.rightMax = point(glm::vec3(-inf), 0u);
    } else {
        flattener.emit(root, 1);
    }
    out.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.triangles.size() != casters.size())
        throw std::runtime_error(subject + ": the shadow BVH holds " + std::to_string(out.triangles.size()) + " of " +
                                 std::to_string(casters.size()) + " triangles");
    return out;
}

}  // namespace ml
