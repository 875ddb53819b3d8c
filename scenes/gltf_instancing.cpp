// EXT_mesh_gpu_instancing (https://github.com/KhronosGroup/glTF/tree/main/extensions/2.0/Vendor/EXT_mesh_gpu_instancing).
#include "scenes/gltf_instancing.h"

#include <cmath>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "scenes/gltf_common.h"

namespace ml::gltf {
namespace {

// The extension allows exactly what glTF allows for POSITION (TRANSLATION, SCALE) and TANGENT
// (ROTATION: a unit quaternion), KHR_mesh_quantization's integer forms included.
const Format& kTranslationFormat = kPositionFormat;
const Format& kScaleFormat = kPositionFormat;
const Format& kRotationFormat = kTangentFormat;

}  // namespace

std::vector<MeshInstance> gpuInstances(const std::string& path, const tinygltf::Model& model, const AccessorReader& reader,
                                       const MeshInstance& placed, std::size_t& budget) {
    const tinygltf::Node& node = model.nodes[placed.node];
    const auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
    if (ext == node.extensions.end()) return {placed};
    const std::string what = named("nodes", placed.node, node.name) + ": EXT_mesh_gpu_instancing";
    if (!ext->second.IsObject() || !ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject())
        fail(path, what + " has no \"attributes\" object");
    const tinygltf::Value& attributes = ext->second.Get("attributes");

    std::optional<std::size_t> count;
    // Reads one attribute (absent: empty), all of them with one count.
    const auto read = [&](const char* name, const Format& format) -> std::vector<float> {
        if (!attributes.Has(name)) return {};
        const tinygltf::Value& index = attributes.Get(name);
        if (!index.IsInt() || index.GetNumberAsInt() < 0 || static_cast<std::size_t>(index.GetNumberAsInt()) >= model.accessors.size())
            fail(path, what + " " + name + " is not an accessor index in range (" + std::to_string(model.accessors.size()) +
                           " accessors)");
        const int accessor = index.GetNumberAsInt();
        const Use use{name, static_cast<int>(placed.mesh), 0, static_cast<int>(placed.node)};
        if (count && reader.count(accessor) != *count)
            fail(path, describe(model, accessor, use) + ": count " + std::to_string(reader.count(accessor)) +
                           " differs from the other instance attributes' " + std::to_string(*count));
        std::vector<float> values = reader.floats(accessor, use, format, budget);
        count = reader.count(accessor);
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                fail(path, describe(model, accessor, use) + ": non-finite value (NaN or infinity) at element " +
                               std::to_string(i / (values.size() / *count)));
        return values;
    };
    const std::vector<float> translations = read("TRANSLATION", kTranslationFormat);
    const std::vector<float> rotations = read("ROTATION", kRotationFormat);
    const std::vector<float> scales = read("SCALE", kScaleFormat);
    if (!count) fail(path, what + " lists none of TRANSLATION, ROTATION and SCALE");
    budget -= *count;

    std::vector<MeshInstance> instances;
    instances.reserve(*count);
    for (std::size_t i = 0; i < *count; ++i) {
        glm::dmat4 trs(1.0);
        if (!translations.empty()) trs = glm::translate(trs, glm::dvec3(translations[3 * i], translations[3 * i + 1], translations[3 * i + 2]));
        if (!rotations.empty()) {
            const glm::dquat q(rotations[4 * i + 3], rotations[4 * i], rotations[4 * i + 1], rotations[4 * i + 2]);  // x, y, z, w
            const double length = glm::length(q);
            if (!(length > 0.0))
                fail(path, what + " ROTATION of instance " + std::to_string(i) + " is a zero quaternion");
            trs *= glm::mat4_cast(q / length);
        }
        if (!scales.empty()) trs = glm::scale(trs, glm::dvec3(scales[3 * i], scales[3 * i + 1], scales[3 * i + 2]));
        instances.push_back({placed.node, placed.mesh, placed.world * trs, trs});
    }
    return instances;
}

}  // namespace ml::gltf
