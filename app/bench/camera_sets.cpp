#include "app/bench/camera_sets.h"

namespace ml::app {

namespace {

struct CameraSet {
    const char* name;
    std::vector<std::string> cameras;  // `--camera` values: "default" or px,py,pz,tx,ty,tz,fovy
};

const std::vector<CameraSet>& cameraSets() {
    static const std::vector<CameraSet> sets = {
        {"atrium-set",
         {"default",                          // the atrium's suggested view
          "-15,1.7,-6.3,15,1.7,-6.3,60",      // gallery: eye height, along the ground-floor gallery
          "0,28,0.5,0,0,0,60",                // roof: straight down from above the roof
          "-16,3,-4.5,16,1.5,4.5,60"}},       // corner: across the courtyard from a corner
        // Issue 64: views that see (nearly) every light of the atrium's volume, where the light
        // assignment's count, fill and sort are largest: 2.8 and 3.0 million list entries at
        // 65,536 lights and overlap:32, against 2.0-2.4 million for atrium-set's views.
        {"atrium-above",
         {"0,14,0.5,0,0,0,90",                // courtyard: straight down from just above the roof line
          "0,11,0.5,0,0,0,100"}},             // inside: straight down from under the roof line, wide
    };
    return sets;
}

}  // namespace

std::optional<std::vector<std::string>> namedCameraSet(const std::string& name) {
    for (const CameraSet& s : cameraSets())
        if (name == s.name) return s.cameras;
    return std::nullopt;
}

std::string cameraSetNames() {
    std::string list;
    for (const CameraSet& s : cameraSets()) list += (list.empty() ? "" : ", ") + std::string(s.name);
    return list;
}

}  // namespace ml::app
