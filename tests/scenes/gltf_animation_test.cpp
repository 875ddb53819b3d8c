// glTF animation, skins and morph targets on files the tests write: each motion lands the
// vertices where the closed form says (scenes/animation_pose.h, the CPU mirror of the GPU's
// pre-pass), static files carry no animation, and every fault is one line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scenes/animation_pose.h"
#include "tests/scenes/gltf_animation_files.h"

namespace ml::gltf_test {
namespace {

// The scene's vertices posed by its first clip at `seconds`.
std::vector<glm::vec3> posedPositions(const Scene& scene, double seconds) {
    Scene posed = scene;
    applyPose(posed, poseAt(*scene.animation, sceneClip(scene, 0), seconds));
    std::vector<glm::vec3> out;
    for (const Vertex& v : posed.vertices) out.push_back(v.position);
    return out;
}

// The first vertex at `p` at rest (vertices keep their order from the file).
std::size_t vertexAt(const Scene& scene, const glm::vec3& p) {
    for (std::size_t i = 0; i < scene.vertices.size(); ++i)
        if (glm::length(scene.vertices[i].position - p) < 1e-6f) return i;
    ADD_FAILURE() << "no vertex at (" << p.x << ", " << p.y << ", " << p.z << ")";
    return 0;
}

TEST(GltfAnimation, StaticFileHasNoAnimation) {
    const fs::path dir = testDir();
    const fs::path file = oneTriangle().writeGlb(dir, "static");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_EQ(scene.animation, nullptr);
    EXPECT_TRUE(warnings.empty());
}

TEST(GltfAnimation, SkinnedStripBendsItsSecondBone) {
    const fs::path dir = testDir();
    const fs::path file = skinnedStrip().g.writeGlb(dir, "skinned-strip");
    std::vector<std::string> warnings;
    const Scene scene = load(file, warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    ASSERT_NE(scene.animation, nullptr);
    ASSERT_EQ(scene.animation->clips.size(), 1u);
    EXPECT_EQ(scene.animation->clips[0].name, "Bend");
    EXPECT_FLOAT_EQ(scene.animation->clips[0].duration, 1.0f);
    EXPECT_EQ(scene.animation->skins.size(), 1u);
    // At rest the strip lies where the joints bind it, not moved by its node's (100, 0, 0).
    const std::size_t tip = vertexAt(scene, {2, 0, 0}), tipTop = vertexAt(scene, {2, 0.2f, 0}),
                      middleTop = vertexAt(scene, {1, 0.2f, 0}), root = vertexAt(scene, {0, 0, 0});
    const std::vector<glm::vec3> bent = posedPositions(scene, 0.999999);
    expectNear(bent[root], {0, 0, 0});
    expectNear(bent[tip], {1, 1, 0}, 1e-4f);
    expectNear(bent[tipTop], {0.8f, 1, 0}, 1e-4f);
    expectNear(bent[middleTop], {0.9f, 0.1f, 0}, 1e-4f);  // half each: (1, 0.2, 0) and (0.8, 0, 0)
    // Half way, slerp gives 45 degrees.
    const float h = std::sqrt(0.5f);
    expectNear(posedPositions(scene, 0.5)[tip], {1 + h, h, 0}, 1e-5f);
    // Normals follow: the bent tip faces +z still (a rotation about z).
    Scene posed = scene;
    applyPose(posed, poseAt(*scene.animation, sceneClip(scene, 0), 0.5));
    expectNear(posed.vertices[tip].normal, {0, 0, 1}, 1e-5f);
}

TEST(GltfAnimation, SkinnedBoundsMove) {
    const fs::path dir = testDir();
    const Scene scene = load(skinnedStrip().g.writeGlb(dir, "skinned-strip"));
    const Bounds rest = posedBounds(scene, 0, 0.0), bent = posedBounds(scene, 0, 0.75);
    expectNear(rest.max, {2, 0.2f, 0});
    EXPECT_GT(bent.max.y, 0.9f);
    EXPECT_LT(bent.max.x, 1.95f);
    // Swept over the loop, the bounds hold every pose.
    const Bounds swept = sweptBounds(scene, 0, 0.0, 1.0 / 60.0);
    EXPECT_GE(swept.max.x, rest.max.x);
    EXPECT_GE(swept.max.y, bent.max.y);
}

TEST(GltfAnimation, MorphedQuadFollowsItsWeight) {
    const fs::path dir = testDir();
    std::vector<std::string> warnings;
    const Scene scene = load(morphedQuad().writeGlb(dir, "morphed-quad"), warnings);
    EXPECT_TRUE(warnings.empty());
    ASSERT_NE(scene.animation, nullptr);
    EXPECT_EQ(scene.animation->morphTargetMeshes, 1u);
    // At rest, the mesh's default weight 0.25.
    EXPECT_NEAR(scene.vertices[0].position.z, 0.25f, 1e-6f);
    for (const auto& [t, z] : {std::pair{0.0, 0.0f}, {1.0, 0.5f}, {1.5, 0.75f}}) {
        const std::vector<glm::vec3> p = posedPositions(scene, t);
        for (const glm::vec3& v : p) EXPECT_NEAR(v.z, z, 1e-6f) << "t " << t;
    }
    // At t = 2 (the clip's end) the loop starts again at 0; just before it, weight 1.
    EXPECT_NEAR(posedPositions(scene, 1.999999)[0].z, 1.0f, 1e-5f);
    EXPECT_NEAR(posedPositions(scene, 2.0)[0].z, 0.0f, 1e-6f);
}

TEST(GltfAnimation, MorphedQuadSteps) {
    const fs::path dir = testDir();
    const Scene scene = load(morphedQuad("STEP").writeGlb(dir, "morphed-quad-step"));
    EXPECT_NEAR(posedPositions(scene, 0.9)[0].z, 0.0f, 1e-6f);
    EXPECT_NEAR(posedPositions(scene, 1.2)[0].z, 0.5f, 1e-6f);
}

TEST(GltfAnimation, NodeAnimatedCubeSlides) {
    const fs::path dir = testDir();
    const Scene scene = load(animatedCube().writeGlb(dir, "animated-cube"));
    ASSERT_NE(scene.animation, nullptr);
    for (double t : {0.0, 0.5, 1.0, 1.5}) {
        const Bounds b = posedBounds(scene, 0, t);
        expectNear(b.center(), {static_cast<float>(2 * t), 0, 0}, 1e-5f);
        expectNear(b.size(), {1, 1, 1}, 1e-5f);
    }
    // With the animation off, the rest pose.
    expectNear(posedBounds(scene, std::nullopt, 1.0).center(), {0, 0, 0});
}

TEST(GltfAnimation, PointerChannelsWarnInOneLine) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    // KHR_animation_pointer's channels have no node (tinygltf drops those: the extension's line
    // says they are skipped); one that names a node as well is counted.
    g.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"path", "pointer"}}}});
    g.doc["animations"][0]["channels"].push_back({{"sampler", 0}, {"target", {{"node", 0}, {"path", "pointer"}}}});
    g.doc["extensionsUsed"] = {"KHR_animation_pointer"};
    const fs::path file = g.writeGlb(dir, "pointer");
    std::vector<std::string> warnings;
    load(file, warnings);
    expectOneLineWarnings(warnings, file);
    EXPECT_EQ(countContaining(warnings, "animation channel skipped"), 1u);
    EXPECT_EQ(countContaining(warnings, "KHR_animation_pointer skipped"), 1u);
}

// --- Faults ------------------------------------------------------------------------------------

TEST(GltfAnimationFaults, SamplerOutputShorterThanItsKeys) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    g.doc["accessors"][g.doc["animations"][0]["samplers"][0]["output"].get<int>()]["count"] = 1;
    expectFault(g.writeGlb(dir, "short-output"), {"output of animations[0] 'Slide' samplers[0]", "count 1", "2 keyframes"});
}

TEST(GltfAnimationFaults, SamplerInputPastItsBuffer) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    g.doc["accessors"][g.doc["animations"][0]["samplers"][0]["input"].get<int>()]["count"] = 1000;
    expectFault(g.writeGlb(dir, "input-past-buffer"), {"input of animations[0] 'Slide' samplers[0]", "overruns"});
}

TEST(GltfAnimationFaults, SamplerOutputPastItsBuffer) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    g.doc["accessors"][g.doc["animations"][0]["samplers"][0]["output"].get<int>()]["byteOffset"] = 4096;
    expectFault(g.writeGlb(dir, "output-past-buffer"), {"output of animations[0] 'Slide' samplers[0]", "overruns"});
}

TEST(GltfAnimationFaults, DecreasingKeyframeTimes) {
    const fs::path dir = testDir();
    Gltf g = oneTriangle();
    addAnimation(g, "Back", 0, "translation", {0.0f, 2.0f, 1.0f}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3", 3);
    expectFault(g.writeGlb(dir, "decreasing-times"), {"animations[0] 'Back' samplers[0]", "decrease at key 2"});
}

TEST(GltfAnimationFaults, EqualKeyframeTimesAreAJump) {
    const fs::path dir = testDir();
    Gltf g = oneTriangle();
    addAnimation(g, "Jump", 0, "translation", {0.0f, 1.0f, 1.0f, 2.0f}, {0, 0, 0, 1, 0, 0, 5, 0, 0, 5, 0, 0}, "VEC3", 3);
    const Scene scene = load(g.writeGlb(dir, "equal-times"));
    EXPECT_NEAR(posedBounds(scene, 0, 0.5).min.x, 0.5f, 1e-6f);
    EXPECT_NEAR(posedBounds(scene, 0, 1.5).min.x, 5.0f, 1e-6f);
}

TEST(GltfAnimationFaults, NaNKeyframeValue) {
    const fs::path dir = testDir();
    Gltf g = oneTriangle();
    addAnimation(g, "Nan", 0, "translation", {0.0f, 1.0f}, {0, 0, 0, NAN, 0, 0}, "VEC3", 3);
    expectFault(g.writeGlb(dir, "nan-output"), {"output of animations[0] 'Nan' samplers[0]", "non-finite", "element 1"});
}

TEST(GltfAnimationFaults, NaNKeyframeTime) {
    const fs::path dir = testDir();
    Gltf g = oneTriangle();
    addAnimation(g, "Nan", 0, "translation", {0.0f, NAN}, {0, 0, 0, 1, 0, 0}, "VEC3", 3);
    expectFault(g.writeGlb(dir, "nan-input"), {"input of animations[0] 'Nan' samplers[0]", "non-finite"});
}

TEST(GltfAnimationFaults, UnknownInterpolation) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    g.doc["animations"][0]["samplers"][0]["interpolation"] = "BOUNCY";
    expectFault(g.writeGlb(dir, "bouncy"), {"animations[0] 'Slide' samplers[0]", "'BOUNCY'"});
}

TEST(GltfAnimationFaults, ChannelTargetOutOfRange) {
    const fs::path dir = testDir();
    Gltf g = animatedCube();
    g.doc["animations"][0]["channels"][0]["target"]["node"] = 7;
    expectFault(g.writeGlb(dir, "target-out-of-range"), {"animations[0] 'Slide' channels[0]", "node index 7"});
}

TEST(GltfAnimationFaults, JointIndexPastTheSkin) {
    const fs::path dir = testDir();
    SkinnedStrip s = skinnedStrip();
    s.g.bin[s.g.doc["bufferViews"][s.g.doc["accessors"][s.jointsAccessor]["bufferView"].get<int>()]["byteOffset"].get<std::size_t>() + 8] = 9;
    expectFault(s.g.writeGlb(dir, "joint-past-skin"), {"JOINTS_0 of meshes[0]", "joint 9", "element 2", "2 joints"});
}

TEST(GltfAnimationFaults, InverseBindMatricesShort) {
    const fs::path dir = testDir();
    expectFault(skinnedStrip(json(), true).g.writeGlb(dir, "short-inverse-bind"),
                {"inverseBindMatrices of skins[0]", "count 1", "short of the skin's 2 joints"});
}

TEST(GltfAnimationFaults, SkinJointOutOfRange) {
    const fs::path dir = testDir();
    expectFault(skinnedStrip(json::array({1, 42})).g.writeGlb(dir, "skin-joint-node"), {"skins[0]", "joint node index 42"});
}

TEST(GltfAnimationFaults, NaNSkinWeight) {
    const fs::path dir = testDir();
    SkinnedStrip s = skinnedStrip();
    const std::size_t offset = s.g.doc["bufferViews"][s.g.doc["accessors"][s.weightsAccessor]["bufferView"].get<int>()]["byteOffset"];
    const float nan = NAN;
    std::memcpy(&s.g.bin[offset + 4], &nan, 4);
    expectFault(s.g.writeGlb(dir, "nan-weight"), {"WEIGHTS_0 of meshes[0]", "element 0", "not finite"});
}

TEST(GltfAnimationFaults, MorphWeightsChannelWithoutTargets) {
    const fs::path dir = testDir();
    Gltf g = oneTriangle();
    addAnimation(g, "Weights", 0, "weights", {0.0f, 1.0f}, {0.0f, 1.0f}, "SCALAR", 1);
    expectFault(g.writeGlb(dir, "weights-without-targets"), {"animations[0] 'Weights' channels[0]", "no mesh with morph targets"});
}

TEST(GltfAnimationFaults, MorphDeltaNaN) {
    const fs::path dir = testDir();
    Gltf g;
    const int delta = g.vec3({{0, 0, NAN}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    json prim = square(g, 0.0f, 0.5f, -1);
    prim["targets"] = json::array({{{"POSITION", delta}}});
    g.scene({g.node({{"mesh", g.mesh({prim})}})});
    expectFault(g.writeGlb(dir, "nan-delta"), {"targets[0] POSITION of meshes[0]", "non-finite", "element 0"});
}

}  // namespace
}  // namespace ml::gltf_test
