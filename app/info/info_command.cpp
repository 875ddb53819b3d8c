#include "app/info/info_command.h"

#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "app/animation_choice.h"
#include "app/frame_options.h"
#include "app/material_variant_choice.h"
#include "app/report.h"
#include "glsl/include/bindings.h"
#include "renderer/camera/default_camera.h"
#include "renderer/lights/light_set.h"
#include "renderer/scene/material_features.h"
#include "scenes/gltf_loader.h"

namespace ml::app {

namespace {

std::string vec3Text(const glm::vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
    return buf;
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

void printGeometry(const Scene& scene) {
    std::size_t blended = 0, masked = 0;
    for (const DrawRange& d : scene.draws) {
        const Material& m = scene.materials[d.material];
        blended += m.blended();
        masked += m.alphaTested();
    }
    std::printf("geometry: %s, %s, %s (%zu blended, %zu alpha-tested)\n", plural(scene.triangleCount(), "triangle", "triangles").c_str(),
                plural(scene.vertices.size(), "vertex", "vertices").c_str(), plural(scene.draws.size(), "draw range", "draw ranges").c_str(),
                blended, masked);
    std::printf("bounds: %s .. %s (diagonal %.4g)\n", vec3Text(scene.bounds.min).c_str(), vec3Text(scene.bounds.max).c_str(),
                glm::length(scene.bounds.size()));
}

void printMaterials(const Scene& scene) {
    std::map<std::string, std::size_t> modes;
    std::size_t doubleSided = 0;
    for (const Material& m : scene.materials) {
        modes[m.blended() ? "BLEND" : m.alphaTested() ? "MASK" : "OPAQUE"]++;
        doubleSided += m.doubleSided;
    }
    std::string split;
    for (const auto& [mode, n] : modes) split += (split.empty() ? "" : ", ") + std::to_string(n) + " " + mode;
    std::printf("materials: %zu (%s; %zu double-sided), %s, %s\n", scene.materials.size(), split.c_str(), doubleSided,
                plural(scene.images.size(), "image", "images").c_str(), plural(scene.samplers.size(), "sampler", "samplers").c_str());
    std::printf("material features (all modelled): %s\n", describeMaterialFeatures(materialFeatures(scene)).c_str());
    if (scene.extensionsUsed.empty()) {
        std::printf("glTF extensions: none\n");
    } else {
        std::printf("glTF extensions:\n");
        for (const std::string& ext : scene.extensionsUsed)
            std::printf("  %-36s %s\n", ext.c_str(),
                        isModelledGltfExtension(ext) ? "modelled" : "not modelled: skipped, warned about at load (see warnings)");
    }
}

// The file's KHR_materials_variants, and the one drawn (--material-variant).
void printMaterialVariants(const Scene& scene, const std::string& chosen) {
    const std::vector<std::string>& names = scene.materialVariants.names;
    if (names.empty()) {
        std::printf("material variants (KHR_materials_variants): none\n");
        return;
    }
    std::printf("material variants (KHR_materials_variants): %zu\n", names.size());
    for (std::size_t i = 0; i < names.size(); ++i) std::printf("  %zu '%s'\n", i, names[i].c_str());
    const std::optional<std::size_t> drawn = parseMaterialVariant(chosen, scene);
    if (drawn) std::printf("  draws '%s' (--material-variant)\n", names[*drawn].c_str());
    else std::printf("  draws the default materials (--material-variant NAME for another)\n");
}

void printLightsAndCameras(const Scene& scene) {
    std::size_t counts[3] = {0, 0, 0};
    for (const SceneLight& l : scene.lights) ++counts[static_cast<int>(l.type)];
    if (scene.lights.empty()) std::printf("lights (KHR_lights_punctual): none\n");
    else
        std::printf("lights (KHR_lights_punctual): %zu point, %zu spot, %zu directional\n", counts[0], counts[1], counts[2]);
    if (scene.cameras.empty()) std::printf("cameras: none (perspective)\n");
    else std::printf("cameras: %zu\n", scene.cameras.size());
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const SceneCamera& c = scene.cameras[i];
        std::printf("  gltf:%zu %s: yfov %.1f deg, at %s looking at %s\n", i,
                    c.name.empty() ? "(unnamed)" : ("'" + c.name + "'").c_str(), c.pose.fovyDegrees,
                    vec3Text(c.pose.eye).c_str(), vec3Text(c.pose.target).c_str());
    }
}

// The file's clips, skins and morph targets, and what render plays.
void printAnimation(const Scene& scene, const SceneAnimationSettings& chosen) {
    if (!scene.animation) {
        std::printf("animation: none\n");
        return;
    }
    const SceneAnimation& a = *scene.animation;
    std::printf("animation: %s, %s, %s with morph targets; %zu of %zu vertices move\n",
                plural(a.clips.size(), "clip", "clips").c_str(), plural(a.skins.size(), "skin", "skins").c_str(),
                plural(a.morphTargetMeshes, "mesh", "meshes").c_str(), a.restPositions.size(), scene.vertices.size());
    for (std::size_t i = 0; i < a.clips.size(); ++i) std::printf("  %s\n", describeClip(scene, i).c_str());
    if (chosen.clip) std::printf("  plays clip %zu from %.4g s (--animation, --scene-time)\n", *chosen.clip, chosen.startSeconds);
    else std::printf("  plays none: drawn at rest (--animation off)\n");
}

int runInfo(const FrameOptions& o) {
    // What render would do with the same flags: the same preparation, no GL.
    PreparedFrame frame = prepareFrame(o);
    const Scene& scene = frame.scene;
    std::printf("scene: %s (%s)\n", o.scene.c_str(), isBuiltinScene(o.scene) ? "built-in" : "glTF file");
    printGeometry(scene);
    printMaterials(scene);
    printMaterialVariants(scene, o.materialVariant);
    printLightsAndCameras(scene);
    printAnimation(scene, frame.settings.sceneAnimation);
    if (frame.warnings.empty()) std::printf("warnings: none\n");
    else std::printf("warnings: %zu\n", frame.warnings.size());
    for (const std::string& w : frame.warnings) std::printf("  %s\n", w.c_str());

    std::printf("render by default (%dx%d):\n", frame.settings.width, frame.settings.height);
    const Camera& c = frame.settings.camera;
    std::printf("  camera: eye %s, target %s, yfov %.1f deg, near %.4g, far %.4g\n", vec3Text(c.eye).c_str(),
                vec3Text(c.target).c_str(), c.fovyDegrees, c.nearPlane, c.farPlane);
    std::size_t fromFile = 0;
    if (o.sceneLights == "on" && o.lightsFile.empty()) fromFile = scene.lights.size();
    std::printf("  lights: %zu (%zu the file's own, %lld generated, placement %s, radius %.4g)\n", frame.lights.size(), fromFile,
                generatedLightCount(o, scene), lightPlacementName(frame.lightPlacement), lightRadiusFor(o, scene));
    char ev[32];
    std::snprintf(ev, sizeof ev, "EV %+.2f", std::log2(frame.settings.exposure));
    std::printf("  exposure: %s\n", frame.settings.autoExposure ? "auto" : ev);
    if (!frame.notes.empty()) std::printf("  as render says it on a first try:\n");
    for (const std::string& note : frame.notes) std::printf("    %s\n", note.c_str());
    return 0;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<FrameOptions>();
    CLI::App* cmd = app.add_subcommand("info", "describe a scene: geometry, materials and the glTF extensions they use, "
                                               "lights, cameras, bounds, and what render would do by default");
    addFrameOptions(*cmd, *options);
    cmd->add_option("file", options->scene, "a .gltf/.glb file, or a built-in scene (atrium, plane, boxes)");
    cmd->callback([options, &exitCode] { exitCode = runInfo(*options); });
}

}  // namespace ml::app
