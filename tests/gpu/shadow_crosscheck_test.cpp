// The GPU's shadow decisions held to Embree's (issue 62): a shadow that every method gets wrong
// alike passes the contract against naive, so this test reads each decision out of rendered
// frames and casts the same ray on the CPU with Embree's own ray caster (rtcOccluded1 over the
// same triangles, embree_occlusion.h), sharing nothing with our BVH or its traversal.
//
// One light at a time, three frames: the light with shadows off (A), on (B), and the light
// black (C, the ambient term alone). Where A differs from C the light adds something, so the GPU
// traced a ray; it found the light hidden where B differs from A (B is then C). On the CPU: the
// pixel centre's primary ray (Embree's nearest hit), the point and normal there, the ray origin
// moved off the surface as the GPU moves it (shadowRayOrigin), and rtcOccluded1 to the light.
// Rays within a stated epsilon of an edge are set apart and counted: a ray whose answer changes
// when the light moves by 1e-3 of the ray's length or the origin by 1e-4 of its distance from
// the eye along the surface, and pixels whose primary hit is on a silhouette (a quarter pixel
// away the primary ray meets a surface whose plane misses this point by over 1e-3 of its
// distance) or on an alpha-tested triangle. Every other pair must agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "gpu_test.h"
#include "renderer/raytracing/embree_occlusion.h"
#include "renderer/raytracing/shadow_alpha.h"
#include "renderer/raytracing/shadow_bvh.h"
#include "renderer/raytracing/shadow_bvh_traversal.h"

namespace ml::test {
namespace {

class ShadowCrossCheck : public GpuTest {};

constexpr int kWidth = 320, kHeight = 180;
constexpr std::size_t kPairsPerLight = 2500;
constexpr float kFar = 1e6f;  // primary rays: past any scene here

struct Tally {
    std::size_t compared = 0, nearAnEdge = 0, shadowed = 0, lit = 0, disagreements = 0;
};

bool samePixel(const FloatImage& a, const FloatImage& b, std::size_t i) {
    return a.pixels[3 * i] == b.pixels[3 * i] && a.pixels[3 * i + 1] == b.pixels[3 * i + 1] && a.pixels[3 * i + 2] == b.pixels[3 * i + 2];
}

FloatImage renderHdr(const Scene& scene, const Light& light, FrameSettings s, Shadows shadows) {
    s.shadows = shadows;
    FrameRenderer renderer(scene, {light}, s);
    renderer.render(0);
    return renderer.readHdr();
}

// The world ray through (x, y) of the frame (y up from the bottom; FloatImage's rows run top
// down), from the eye, unit length: the
// projection is unprojected at a depth between the planes, so neither reversed nor infinite
// depth matters.
std::pair<glm::vec3, glm::vec3> primaryRay(const FrameSettings& s, float x, float y) {
    const glm::mat4 inverse = glm::inverse(s.camera.projection(float(s.width) / float(s.height)) * s.camera.view());
    const glm::vec2 ndc(x / float(s.width) * 2.0f - 1.0f, y / float(s.height) * 2.0f - 1.0f);
    const glm::vec4 inside = inverse * glm::vec4(ndc, 0.5f, 1.0f);
    return {s.camera.eye, glm::normalize(glm::vec3(inside) / inside.w - s.camera.eye)};
}

void crossCheck(const Scene& scene, const std::vector<Light>& lights, FrameSettings s, Tally& tally) {
    const EmbreeOcclusion embree(scene);
    ShadowBvh bvh = buildShadowBvh(scene);
    const ShadowAlphaMasks masks = buildShadowAlphaMasks(scene, bvh);
    const ShadowCoverage covered = shadowAlphaCoverage(scene, masks);
    for (const Light& light : lights) {
        Light black = light;
        black.color = glm::vec3(0.0f);
        const FloatImage a = renderHdr(scene, light, s, Shadows::Off), b = renderHdr(scene, light, s, Shadows::Rays),
                         c = renderHdr(scene, black, s, Shadows::Off);
        std::vector<std::size_t> reached;
        for (std::size_t i = 0; i < static_cast<std::size_t>(kWidth) * kHeight; ++i)
            if (!samePixel(a, c, i)) reached.push_back(i);
        EXPECT_GT(reached.size(), static_cast<std::size_t>(kWidth) * kHeight / 10) << "the light reaches little of the frame";
        const std::size_t stride = std::max<std::size_t>(1, reached.size() / kPairsPerLight);
        for (std::size_t k = 0; k < reached.size(); k += stride) {
            const std::size_t i = reached[k];
            const float x = float(i % kWidth) + 0.5f, y = float(kHeight - 1 - static_cast<int>(i / kWidth)) + 0.5f;
            const auto [from, direction] = primaryRay(s, x, y);
            const std::optional<EmbreeOcclusion::Hit> hit = embree.firstHit(from, direction, kFar);
            // A pixel no casting triangle covers (BLEND surfaces cast none) is not compared.
            if (!hit) continue;
            ++tally.compared;
            bool apart = hit->material != kShadowOpaque;
            const std::uint32_t* corner = &scene.indices[3 * hit->sceneTriangle];
            const float w0 = 1.0f - hit->u - hit->v;
            const glm::vec3 position = w0 * scene.vertices[corner[0]].position + hit->u * scene.vertices[corner[1]].position +
                                       hit->v * scene.vertices[corner[2]].position;
            // A silhouette: a quarter pixel away the primary ray meets a surface whose plane
            // passes over 1e-3 of the distance from this point.
            for (const glm::vec2 d : {glm::vec2(0.25f, 0.0f), glm::vec2(-0.25f, 0.0f), glm::vec2(0.0f, 0.25f), glm::vec2(0.0f, -0.25f)}) {
                const auto [nearFrom, nearDirection] = primaryRay(s, x + d.x, y + d.y);
                const std::optional<EmbreeOcclusion::Hit> near = embree.firstHit(nearFrom, nearDirection, kFar);
                if (!near) {
                    apart = true;
                    continue;
                }
                const std::uint32_t* c = &scene.indices[3 * near->sceneTriangle];
                const glm::vec3 p0 = scene.vertices[c[0]].position;
                const glm::vec3 plane = glm::cross(scene.vertices[c[1]].position - p0, scene.vertices[c[2]].position - p0);
                if (!(std::abs(glm::dot(glm::normalize(plane), position - p0)) <= 1e-3f * hit->t)) apart = true;
            }
            glm::vec3 normal = glm::normalize(w0 * scene.vertices[corner[0]].normal + hit->u * scene.vertices[corner[1]].normal +
                                              hit->v * scene.vertices[corner[2]].normal);
            if (glm::dot(normal, direction) > 0.0f) normal = -normal;  // the side the camera sees
            const glm::vec3 origin = shadowRayOrigin(position, normal);
            const bool hidden = embree.occluded(origin, light.position - origin, 1.0f, covered);
            const float reach = 1e-3f * glm::length(light.position - origin);
            const float slide = 1e-4f * glm::length(position - s.camera.eye);
            const glm::vec3 along = glm::normalize(glm::cross(normal, std::abs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
            const glm::vec3 across = glm::cross(normal, along);
            for (const glm::vec3& d : {glm::vec3(reach, 0, 0), glm::vec3(-reach, 0, 0), glm::vec3(0, reach, 0), glm::vec3(0, -reach, 0),
                                       glm::vec3(0, 0, reach), glm::vec3(0, 0, -reach)})
                if (embree.occluded(origin, light.position + d - origin, 1.0f, covered) != hidden) apart = true;
            for (const glm::vec3& d : {slide * along, -slide * along, slide * across, -slide * across}) {
                const glm::vec3 moved = shadowRayOrigin(position + d, normal);
                if (embree.occluded(moved, light.position - moved, 1.0f, covered) != hidden) apart = true;
            }
            if (apart) {
                ++tally.nearAnEdge;
                continue;
            }
            const bool gpuHidden = !samePixel(b, a, i);
            ++(hidden ? tally.shadowed : tally.lit);
            if (gpuHidden != hidden) {
                ++tally.disagreements;
                if (tally.disagreements <= 5)
                    ADD_FAILURE() << "pixel (" << i % kWidth << ", " << i / kWidth << "), light at (" << light.position.x << ", "
                                  << light.position.y << ", " << light.position.z << "): the GPU says " << (gpuHidden ? "hidden" : "lit")
                                  << ", Embree " << (hidden ? "hidden" : "lit");
            }
            if (gpuHidden) {
                EXPECT_TRUE(samePixel(b, c, i)) << "a hidden light still adds light at pixel " << i;
            }
        }
    }
}

void expectAgreement(const std::string& name, std::uint32_t seed, MethodKind kind) {
    SCOPED_TRACE(name + ", " + methodName(kind));
    const TestScene t = testScene(name, 4, seed);
    FrameSettings s = smallFrame(t.scene, kWidth, kHeight);
    s.method.kind = kind;
    s.transparency = false;  // the pixel is the opaque surface the primary ray meets
    // Four lights, one at a time, whose reach covers the scene, so that occluders stand between
    // them and much of the frame; still, as the CPU must know where they are.
    const float reach = 2.0f * glm::length(t.scene.bounds.size());
    std::vector<Light> lights;
    for (Light light : t.lights) {
        light.radius = reach;
        light.color = glm::vec3(6.0f);
        light.drifts = false;
        lights.push_back(light);
    }
    Tally tally;
    crossCheck(t.scene, lights, s, tally);
    std::printf("%s, %s: %zu pairs compared, %zu set apart near an edge (%.2f %%); of the rest %zu hidden, %zu lit, %zu disagree\n",
                name.c_str(), methodName(kind).c_str(), tally.compared, tally.nearAnEdge,
                tally.compared ? 100.0 * double(tally.nearAnEdge) / double(tally.compared) : 0.0, tally.shadowed, tally.lit,
                tally.disagreements);
    EXPECT_EQ(tally.disagreements, 0u);
    // The test can fail: both answers occur, often, and few pairs are set apart.
    EXPECT_GT(tally.shadowed, 300u);
    EXPECT_GT(tally.lit, 300u);
    // Set apart on llvmpipe at 320x180: the boxes 1.6 % of pairs, the atrium 17 % (its fine
    // geometry: about 9 % on silhouettes, 5 % by the origin's slide, 1.3 % by the light's move,
    // 0.2 % on foliage).
    EXPECT_LT(double(tally.nearAnEdge), 0.25 * double(tally.compared));
}

TEST_F(ShadowCrossCheck, NaiveAgreesWithEmbreeInTheBoxes) { expectAgreement("boxes", 3, MethodKind::Naive); }
TEST_F(ShadowCrossCheck, TheVisibilityBufferAgreesWithEmbreeInTheBoxes) { expectAgreement("boxes", 3, MethodKind::Visibility); }
TEST_F(ShadowCrossCheck, NaiveAgreesWithEmbreeInTheAtrium) { expectAgreement("atrium", 5, MethodKind::Naive); }
TEST_F(ShadowCrossCheck, TheVisibilityBufferAgreesWithEmbreeInTheAtrium) { expectAgreement("atrium", 5, MethodKind::Visibility); }

}  // namespace
}  // namespace ml::test
