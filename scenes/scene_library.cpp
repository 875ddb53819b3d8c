#include "scenes/scene_library.h"

#include "scenes/gltf_loader.h"
#include "scenes/procedural_scenes.h"

namespace ml {

const std::vector<std::string>& builtinSceneNames() {
    static const std::vector<std::string> names{"atrium", "plane", "boxes"};
    return names;
}

namespace {
bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

Scene loadScene(const SceneRequest& request, std::vector<std::string>& warnings) {
    const std::string& key = request.nameOrPath;
    if (key == "atrium") return makeAtrium(request.detail);
    if (key == "plane") return makePlane();
    if (key == "boxes") return makeBoxes();
    if (endsWith(key, ".gltf") || endsWith(key, ".glb")) return loadGltf(key, warnings);
    throw SceneError(key + ": not a built-in scene (atrium, plane, boxes) nor a .gltf/.glb file");
}

}  // namespace ml
