#include "app/animation_choice.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ml::app {
namespace {

std::size_t clipCount(const Scene& scene) { return scene.animation ? scene.animation->clips.size() : 0; }

// "the file has 2 clips: 0 'Walk', 1 'Run'", "the scene has no animation clips".
std::string availableClips(const Scene& scene) {
    const std::size_t n = clipCount(scene);
    if (n == 0) return "the scene has no animation clips";
    std::string list = "the file has " + std::to_string(n) + (n == 1 ? " clip: " : " clips: ");
    for (std::size_t i = 0; i < n && i < 20; ++i) {
        const std::string& name = scene.animation->clips[i].name;
        list += (i > 0 ? ", " : "") + std::to_string(i) + (name.empty() ? "" : " '" + name + "'");
    }
    if (n > 20) list += ", ...";
    return list;
}

}  // namespace

std::optional<std::size_t> parseAnimationChoice(const std::string& text, const Scene& scene) {
    const std::size_t n = clipCount(scene);
    if (text.empty()) return n > 0 ? std::optional<std::size_t>(0) : std::nullopt;
    if (text == "off") return std::nullopt;
    const bool digits = text.find_first_not_of("0123456789") == std::string::npos && text.size() <= 9;
    if (digits && std::stoul(text) < n) return std::stoul(text);
    for (std::size_t i = 0; i < n; ++i)
        if (scene.animation->clips[i].name == text) return i;
    throw std::invalid_argument("--animation '" + text + "': no such clip; " + availableClips(scene) + " (or off)");
}

SceneAnimationSettings sceneAnimationFor(const std::string& animation, double sceneTime, const Scene& scene) {
    if (!std::isfinite(sceneTime)) throw std::invalid_argument("--scene-time: must be a finite number of seconds");
    return SceneAnimationSettings{parseAnimationChoice(animation, scene), sceneTime};
}

std::string describeClip(const Scene& scene, std::size_t clip) {
    const AnimationClip& c = scene.animation->clips[clip];
    char duration[32];
    std::snprintf(duration, sizeof duration, "%.4g s", c.duration);
    return std::to_string(clip) + (c.name.empty() ? "" : " '" + c.name + "'") + " (" + duration + ", " +
           std::to_string(c.channels.size()) + (c.channels.size() == 1 ? " channel)" : " channels)");
}

}  // namespace ml::app
