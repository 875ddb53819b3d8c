// Where a frame looks when no --camera is given: the rule `render`, `view` and `bench` share.
//
//   a built-in scene      its own view (Scene::suggestedView), as it always was;
//   a file with cameras   its first camera in glTF's node order (said in one line of output);
//   a file without        the sphere around what a robust share of its surface area occupies,
//                         framed to fill the view, seen from the file's front (+Z, raised
//                         kFramingElevationDegrees), as glTF viewers open a model.
// Clip planes are fitted to the scene's bounds in every case (a file camera keeps its own znear,
// and its zfar where it gives one).
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "renderer/camera/camera.h"
#include "scenes/scene.h"

namespace ml {

inline constexpr float kFramingFovyDegrees = 45.0f;       // the Khronos Sample Viewer's default yfov
inline constexpr float kFramingElevationDegrees = 15.0f;  // slightly above: floors and tops read

struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
};

// Centred on the bounds, just large enough to hold every vertex (tighter than the box's
// half-diagonal: a round object's sphere is its own, not its box's).
BoundingSphere boundingSphere(const Scene& scene);

// What the default camera frames: the surface around what a robust share of its area occupies.
// kFramingSamples points are spread over the triangles by area (renderer/scene/surface_samples.h;
// a fixed seed, so every run frames alike); along each axis their kFramedAreaTail to
// 1 - kFramedAreaTail quantiles make the core, which is widened by kFramedFence of its size on
// each side. The points and vertices inside that fence are framed: a model's own thin ends stay
// in (a model frames as its bounding sphere did), while a stray vertex, a far-off triangle or a
// distant prop falls out and no longer leaves the room or the model small. A scene without area
// keeps its bounding sphere.
inline constexpr float kFramedAreaTail = 0.02f;
inline constexpr float kFramedFence = 0.25f;
inline constexpr std::uint32_t kFramingSamples = 16384;
struct FramedSurface {
    BoundingSphere sphere;  // centred on `framed`, holding every point inside the fence
    Bounds core;            // the middle of the area along each axis
    Bounds framed;          // what lies inside the fence
};
FramedSurface framedSurface(const Scene& scene);

// A camera that looks at the sphere from `direction` (towards the eye) with the sphere just
// inside the narrower of the two fields of view of an `aspect` (width / height) frame.
Camera framingCamera(const BoundingSphere& sphere, float aspect, glm::vec3 direction);
// The front framing: from +Z, raised kFramingElevationDegrees.
Camera frontFramingCamera(const BoundingSphere& sphere, float aspect);

struct DefaultCamera {
    Camera camera;        // clip planes fitted
    std::string choice;   // for a file, one line: which rule chose it ("gltf:0 'Main' (the first of ...)"); empty for a built-in scene
    bool fromFile = false;
};

DefaultCamera defaultCamera(const Scene& scene, float aspect);

}  // namespace ml
