#include "renderer/raytracing/embree_occlusion.h"

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/raytracing/embree_device.h"
#include "renderer/raytracing/shadow_bvh_layout.h"
#include "renderer/raytracing/shadow_casters.h"

namespace ml {

struct EmbreeOcclusion::Impl {
    explicit Impl(const Scene& scene) : device("scene " + scene.name) {}
    ~Impl() {
        if (rtcScene != nullptr) rtcReleaseScene(rtcScene);
    }

    EmbreeDevice device;  // released after the scene (members go in reverse order)
    RTCScene rtcScene = nullptr;
    std::vector<std::uint32_t> material;       // per Embree primitive: kShadowOpaque or the MASK material
    std::vector<std::uint32_t> sceneTriangle;  // per Embree primitive
};

namespace {

// The query's context: Embree passes it to the occlusion filter (it must start with the
// RTCIntersectContext that rtcOccluded1 takes).
struct OcclusionQuery {
    RTCIntersectContext context;
    const std::vector<std::uint32_t>* material;
    const std::vector<std::uint32_t>* sceneTriangle;
    const ShadowCoverage* covered;
};

// A hit on an alpha-tested triangle that `covered` says is a hole does not block.
void occlusionFilter(const RTCFilterFunctionNArguments* args) {
    const auto* query = reinterpret_cast<const OcclusionQuery*>(args->context);
    if (query->covered == nullptr || !*query->covered) return;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        const std::uint32_t material = (*query->material)[primitive];
        if (material == kShadowOpaque) continue;
        if (!(*query->covered)(material, (*query->sceneTriangle)[primitive], RTCHitN_u(args->hit, args->N, i),
                               RTCHitN_v(args->hit, args->N, i)))
            args->valid[i] = 0;
    }
}

}  // namespace

EmbreeOcclusion::EmbreeOcclusion(const Scene& scene) : impl_(std::make_unique<Impl>(scene)) {
    const std::vector<ShadowCaster> casters = shadowCasters(scene);
    RTCDevice device = impl_->device.get();
    impl_->rtcScene = rtcNewScene(device);
    impl_->device.check("make a scene");
    rtcSetSceneFlags(impl_->rtcScene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->rtcScene, RTC_BUILD_QUALITY_HIGH);
    impl_->material.reserve(casters.size());
    impl_->sceneTriangle.reserve(casters.size());
    if (!casters.empty()) {
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        impl_->device.check("make a triangle geometry");
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                     3 * sizeof(float), 3 * casters.size()));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                       3 * sizeof(unsigned), casters.size()));
        if (vertices == nullptr || indices == nullptr) {
            rtcReleaseGeometry(geometry);
            impl_->device.check("allocate the triangles");
            throw std::runtime_error("scene " + scene.name + ": Embree allocated no buffer for " +
                                     std::to_string(casters.size()) + " triangles");
        }
        for (std::size_t i = 0; i < casters.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                float* v = vertices + 3 * (3 * i + k);
                v[0] = casters[i].corners[k].x;
                v[1] = casters[i].corners[k].y;
                v[2] = casters[i].corners[k].z;
                indices[3 * i + k] = static_cast<unsigned>(3 * i + k);
            }
            impl_->material.push_back(casters[i].material);
            impl_->sceneTriangle.push_back(casters[i].sceneTriangle);
        }
        rtcSetGeometryOccludedFilterFunction(geometry, occlusionFilter);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(impl_->rtcScene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(impl_->rtcScene);
    impl_->device.check("build its scene");
}

EmbreeOcclusion::~EmbreeOcclusion() = default;

std::size_t EmbreeOcclusion::triangles() const { return impl_->material.size(); }

namespace {

RTCRay segment(glm::vec3 origin, glm::vec3 direction, float tMax) {
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.tnear = 0.0f;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.time = 0.0f;
    ray.tfar = tMax;
    ray.mask = 0xFFFFFFFFu;  // Debian's Embree is built with ray masks: a mask of 0 meets nothing
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

}  // namespace

std::optional<EmbreeOcclusion::Hit> EmbreeOcclusion::firstHit(glm::vec3 origin, glm::vec3 direction, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit{};
    rayHit.ray = segment(origin, direction, tMax);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->rtcScene, &context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    const unsigned primitive = rayHit.hit.primID;
    return Hit{rayHit.ray.tfar, impl_->sceneTriangle.at(primitive), impl_->material.at(primitive), rayHit.hit.u, rayHit.hit.v};
}

bool EmbreeOcclusion::occluded(glm::vec3 origin, glm::vec3 direction, float tMax, const ShadowCoverage& covered) const {
    OcclusionQuery query;
    rtcInitIntersectContext(&query.context);
    query.material = &impl_->material;
    query.sceneTriangle = &impl_->sceneTriangle;
    query.covered = &covered;
    RTCRay ray = segment(origin, direction, tMax);
    rtcOccluded1(impl_->rtcScene, &query.context, &ray);
    // rtcOccluded1 sets tfar to -inf where the ray is blocked.
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace ml
