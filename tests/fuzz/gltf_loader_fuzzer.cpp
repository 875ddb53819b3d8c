// libFuzzer target for the scene-loading path (issue 7): arbitrary bytes as a .glb (when they
// start with the GLB magic) or a .gltf file, through ml::loadGltf. Loading may succeed or throw
// SceneError with one line; a scene that loads with an animation is posed by each of its first
// clips at a few times (scenes/animation_pose.h); anything else (a crash, a sanitizer report, another exception, a
// multi-line message, a hang past -timeout) is a finding. Built and run by tools/fuzz.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scenes/animation_pose.h"
#include "scenes/gltf_loader.h"

namespace {

std::filesystem::path workDir() {
    static const std::filesystem::path dir = [] {
        const char* base = std::getenv("ML_FUZZ_TMP");
        std::filesystem::path d = base ? base : std::filesystem::temp_directory_path() / "manylights-fuzz";
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::filesystem::path file = workDir() / (glb ? "input.glb" : "input.gltf");
    {
        std::ofstream out(file, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    std::vector<std::string> warnings;
    try {
        const ml::Scene scene = ml::loadGltf(file.string(), warnings);
        if (scene.indices.size() % 3 != 0) std::abort();  // the scene model's invariant
        for (std::uint32_t index : scene.indices)
            if (index >= scene.vertices.size()) std::abort();
        if (scene.animation) {
            // The pose of a few clips at a few times, looping included: no crash, no read past an array.
            for (std::size_t clip = 0; clip < scene.animation->clips.size() && clip < 3; ++clip) {
                ml::Scene posed = scene;
                for (double t : {0.0, 0.37, 1e3, -2.5}) ml::applyPose(posed, ml::poseAt(*scene.animation, &scene.animation->clips[clip], t));
                ml::sweptBounds(scene, clip, 0.0, 1.0 / 60.0, 4);
            }
        }
    } catch (const ml::SceneError& e) {
        const std::string what = e.what();
        if (what.find('\n') != std::string::npos || what.rfind(file.string(), 0) != 0) {
            std::fprintf(stderr, "SceneError is not one line naming the file: %s\n", what.c_str());
            std::abort();
        }
    }
    for (const std::string& w : warnings)
        if (w.find('\n') != std::string::npos) std::abort();
    return 0;
}
