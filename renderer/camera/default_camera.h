// Where a frame looks when no --camera is given: the rule `render`, `view` and `bench` share.
//
//   a built-in scene      its own view (Scene::suggestedView), as it always was;
//   a file with cameras   its first camera in glTF's node order (said in one line of output);
//   a file without        its bounding sphere framed to fill the view, seen from the file's front
//                         (+Z, raised kFramingElevationDegrees), as glTF viewers open a model.
// Clip planes are fitted to the scene's bounds in every case (a file camera keeps its own znear,
// and its zfar where it gives one).
#pragma once

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
