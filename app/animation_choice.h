// --animation NAME|INDEX|off and --scene-time: which glTF clip a file plays and from when, checked
// against the scene's clips before anything is drawn.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "renderer/frame_renderer.h"
#include "scenes/scene.h"

namespace ml::app {

// The clip `text` names (empty: the first, where the scene has any; "off": none). Throws
// std::invalid_argument with one line naming the value and the clips there are.
std::optional<std::size_t> parseAnimationChoice(const std::string& text, const Scene& scene);

// --animation and --scene-time resolved for the scene (std::invalid_argument naming the flag).
SceneAnimationSettings sceneAnimationFor(const std::string& animation, double sceneTime, const Scene& scene);

// "0 'Walk' (2.5 s, 57 channels)"; "clip 1 (0 s, 3 channels)" for one without a name.
std::string describeClip(const Scene& scene, std::size_t clip);

}  // namespace ml::app
