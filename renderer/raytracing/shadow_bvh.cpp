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
inline constexpr std::uint32_t kMaxChildren = 8;

struct BuildNode {
    bool leaf;
};
struct InnerNode {
    BuildNode base{false};
    std::uint32_t count = 0;
    const BuildNode* children[kMaxChildren] = {};
    RTCBounds bounds[kMaxChildren];
};
struct LeafNode {
    BuildNode base{true};
    std::uint32_t count = 0;
    std::uint32_t casters[kShadowBvhMaxLeafSize];
};

// What the callbacks share; they run on Embree's build threads and must not throw.
struct BuildState {
    std::uint32_t width = 2;
    std::atomic<bool> malformed{false};  // a node or leaf the layout cannot hold
};

bool childCountFits(unsigned int childCount, void* user) {
    auto* state = static_cast<BuildState*>(user);
    if (childCount >= 2 && childCount <= state->width) return true;
    state->malformed = true;
    return false;
}

void* createNode(RTCThreadLocalAllocator allocator, unsigned int childCount, void* user) {
    childCountFits(childCount, user);
    void* memory = rtcThreadLocalAlloc(allocator, sizeof(InnerNode), alignof(InnerNode));
    return memory != nullptr ? new (memory) InnerNode() : nullptr;
}

void setNodeChildren(void* node, void** children, unsigned int childCount, void* user) {
    if (node == nullptr || !childCountFits(childCount, user)) return;
    auto* inner = static_cast<InnerNode*>(node);
    inner->count = childCount;
    for (unsigned i = 0; i < childCount; ++i) inner->children[i] = static_cast<const BuildNode*>(children[i]);
}

void setNodeBounds(void* node, const RTCBounds** bounds, unsigned int childCount, void* user) {
    if (node == nullptr || !childCountFits(childCount, user)) return;
    auto* inner = static_cast<InnerNode*>(node);
    for (unsigned i = 0; i < childCount; ++i) inner->bounds[i] = *bounds[i];
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

// A reference and the stack entries its subtree's traversal needs once it is popped (shadow_bvh.h).
struct Emitted {
    std::uint32_t reference;
    std::uint32_t stackNeed;
};

class Flattener {
public:
    Flattener(const std::vector<ShadowCaster>& casters, const std::string& subject, ShadowBvh& out)
        : casters_(casters), subject_(subject), out_(out), stride_(shadowNodeVec4s(out.width)) {}

    // A new node, its slots empty (wide) or zero (binary); its index.
    std::uint32_t newNode(std::uint32_t level) {
        const std::size_t index = out_.nodeCount();
        if (index >= kShadowLeafBit) throw std::runtime_error(subject_ + ": the shadow BVH has more than 2^31 nodes");
        out_.nodes.resize(out_.nodes.size() + stride_, glm::vec4(0.0f));
        if (out_.width != 2) {
            constexpr float inf = std::numeric_limits<float>::infinity();
            for (std::uint32_t slot = 0; slot < out_.width; ++slot)
                setShadowNodeChild(nodeAt(index), out_.width, slot, ShadowBvhChild{glm::vec3(inf), glm::vec3(-inf), 0u, false});
        }
        out_.depth = std::max(out_.depth, level);
        return static_cast<std::uint32_t>(index);
    }
    glm::vec4* nodeAt(std::size_t index) { return out_.nodes.data() + index * stride_; }

    // `node`'s nodes and triangles appended depth-first; `level` is the level `node` would take
    // as an inner node (the root's: 1).
    Emitted emit(const BuildNode* node, std::uint32_t level) {
        if (node == nullptr) throw std::runtime_error(subject_ + ": Embree's shadow BVH has a missing child");
        if (node->leaf) return {emitLeaf(reinterpret_cast<const LeafNode*>(node)), 0u};
        const auto* inner = reinterpret_cast<const InnerNode*>(node);
        const std::uint32_t index = newNode(level);
        std::uint32_t need = inner->count;
        for (std::uint32_t slot = 0; slot < inner->count; ++slot) {
            const Emitted child = emit(inner->children[slot], level + 1);
            need = std::max(need, slot + child.stackNeed);
            const RTCBounds& b = inner->bounds[slot];
            setShadowNodeChild(nodeAt(index), out_.width, slot,
                               ShadowBvhChild{{b.lower_x, b.lower_y, b.lower_z}, {b.upper_x, b.upper_y, b.upper_z}, child.reference, true});
        }
        return {index, need};
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
    std::uint32_t stride_;
};

}  // namespace

ShadowBvh buildShadowBvh(const Scene& scene, std::uint32_t width) {
    if (!shadowBvhWidthSupported(width))
        throw std::invalid_argument("--shadow-bvh-width " + std::to_string(width) + ": the shadow BVH has 2, 4 or 8 children a node");
    const std::string subject = "scene " + scene.name;
    const std::vector<ShadowCaster> casters = shadowCasters(scene);
    if (casters.size() > kShadowTriangleLimit)
        throw std::runtime_error(subject + ": " + std::to_string(casters.size()) +
                                 " triangles, more than the shadow structure's 2^28");
    ShadowBvh out;
    out.width = width;
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
    state.width = width;
    RTCBuildArguments args = rtcDefaultBuildArguments();
    args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;  // binned SAH; see the header
    args.maxBranchingFactor = width;
    args.maxDepth = kShadowBvhMaxDepth;
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
        throw std::runtime_error(subject + ": Embree's shadow BVH has a node or leaf outside the layout (2 to " + std::to_string(width) +
                                 " children a node, 1 to " + std::to_string(kShadowBvhMaxLeafSize) + " triangles a leaf)");

    Flattener flattener(casters, subject, out);
    if (root->leaf) {
        // One leaf: node 0 holds it in its first slot (binary: in its second too, behind an empty box).
        const std::uint32_t index = flattener.newNode(1);
        const std::uint32_t leaf = flattener.emitLeaf(reinterpret_cast<const LeafNode*>(root));
        setShadowNodeChild(flattener.nodeAt(index), width, 0, ShadowBvhChild{out.bounds.min, out.bounds.max, leaf, true});
        if (width == 2) {
            constexpr float inf = std::numeric_limits<float>::infinity();
            setShadowNodeChild(flattener.nodeAt(index), width, 1, ShadowBvhChild{glm::vec3(inf), glm::vec3(-inf), leaf, true});
        }
        out.stackNeed = width == 2 ? 2u : 1u;
    } else {
        out.stackNeed = flattener.emit(root, 1).stackNeed;
    }
    if (out.stackNeed > static_cast<std::uint32_t>(ML_SHADOW_STACK))
        throw std::runtime_error(subject + ": the shadow BVH (" + std::to_string(width) + " children a node, depth " +
                                 std::to_string(out.depth) + ") could need " + std::to_string(out.stackNeed) +
                                 " stack entries, more than the traversal's " + std::to_string(ML_SHADOW_STACK));
    out.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (out.triangles.size() != casters.size())
        throw std::runtime_error(subject + ": the shadow BVH holds " + std::to_string(out.triangles.size()) + " of " +
                                 std::to_string(casters.size()) + " triangles");
    return out;
}

}  // namespace ml
