#include "scenes/gltf_nodes.h"

#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scenes/gltf_common.h"

namespace ml::gltf {

NodeTransform nodeTransform(const std::string& path, const tinygltf::Node& node, std::size_t index) {
    const auto badLength = [&](const char* what, std::size_t got, const char* expected) {
        fail(path, named("nodes", index, node.name) + ": " + what + " has " + std::to_string(got) +
                       " numbers, expected " + expected);
    };
    NodeTransform t;
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) badLength("matrix", node.matrix.size(), "16");
        t.matrix = glm::make_mat4(node.matrix.data());  // glTF and glm are both column-major
        return t;
    }
    if (!node.translation.empty() && node.translation.size() != 3) badLength("translation", node.translation.size(), "3");
    if (!node.rotation.empty() && node.rotation.size() != 4) badLength("rotation", node.rotation.size(), "4");
    if (!node.scale.empty() && node.scale.size() != 3) badLength("scale", node.scale.size(), "3");
    if (!node.translation.empty()) t.translation = glm::make_vec3(node.translation.data());
    if (!node.rotation.empty()) {
        const auto& r = node.rotation;  // glTF stores x, y, z, w
        const glm::dquat q(r[3], r[0], r[1], r[2]);
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length))
            fail(path, named("nodes", index, node.name) + ": rotation quaternion has zero or non-finite length");
        t.rotation = q / length;
    }
    if (!node.scale.empty()) t.scale = glm::make_vec3(node.scale.data());
    return t;
}

glm::dmat4 NodeTransform::local() const {
    if (matrix) return *matrix;
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), translation);
    m *= glm::mat4_cast(rotation);
    return glm::scale(m, scale);
}

FlatScene flattenNodes(const std::string& path, const tinygltf::Model& model) {
    if (model.scenes.empty()) fail(path, "no scene: the file defines no scenes");
    std::size_t sceneIndex = 0;
    if (model.defaultScene >= 0) {
        sceneIndex = static_cast<std::size_t>(model.defaultScene);
        if (sceneIndex >= model.scenes.size())
            fail(path, "scene index " + std::to_string(sceneIndex) + " out of range (" +
                           std::to_string(model.scenes.size()) + " scenes)");
    }
    const tinygltf::Scene& scene = model.scenes[sceneIndex];
    const std::string sceneName = named("scenes", sceneIndex, scene.name);
    if (scene.nodes.empty()) fail(path, sceneName + " is empty: it lists no nodes");

    const std::size_t nodeCount = model.nodes.size();
    enum class Mark : std::uint8_t { unvisited, onPath, done };
    std::vector<Mark> marks(nodeCount, Mark::unvisited);
    std::vector<glm::dmat4> world(nodeCount);
    struct Step {
        std::size_t node;
        std::ptrdiff_t parent;  // -1 for a scene root
        bool leaving;           // pops the node off the current path
    };
    std::vector<Step> stack;
    const auto push = [&](int child, std::ptrdiff_t parent, const std::string& from) {
        if (child < 0 || static_cast<std::size_t>(child) >= nodeCount)
            fail(path, from + ": node index " + std::to_string(child) + " out of range (" + std::to_string(nodeCount) +
                           " nodes)");
        stack.push_back({static_cast<std::size_t>(child), parent, false});
    };
    for (auto it = scene.nodes.rbegin(); it != scene.nodes.rend(); ++it) push(*it, -1, sceneName);

    FlatScene flat;
    while (!stack.empty()) {
        const Step step = stack.back();
        stack.pop_back();
        if (step.leaving) {
            marks[step.node] = Mark::done;
            continue;
        }
        const tinygltf::Node& node = model.nodes[step.node];
        const std::string name = named("nodes", step.node, node.name);
        if (marks[step.node] == Mark::onPath) fail(path, "node cycle: " + name + " is its own ancestor");
        if (marks[step.node] == Mark::done)
            fail(path, name + " is reached twice (more than one parent, or listed twice); glTF nodes must form trees");
        marks[step.node] = Mark::onPath;

        const glm::dmat4 parentWorld = step.parent < 0 ? glm::dmat4(1.0) : world[static_cast<std::size_t>(step.parent)];
        world[step.node] = parentWorld * nodeTransform(path, node, step.node).local();
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model.meshes.size())
                fail(path, name + ": mesh index " + std::to_string(node.mesh) + " out of range (" +
                               std::to_string(model.meshes.size()) + " meshes)");
            flat.meshes.push_back({step.node, static_cast<std::size_t>(node.mesh), world[step.node]});
        }
        if (node.camera >= 0) {
            if (static_cast<std::size_t>(node.camera) >= model.cameras.size())
                fail(path, name + ": cameras[" + std::to_string(node.camera) + "] out of range (" +
                               std::to_string(model.cameras.size()) + " cameras)");
            flat.cameras.push_back({step.node, static_cast<std::size_t>(node.camera), world[step.node]});
        }
        if (const auto ext = node.extensions.find("KHR_lights_punctual"); ext != node.extensions.end()) {
            const tinygltf::Value& light = ext->second.Get("light");
            if (!light.IsNumber() || light.GetNumberAsDouble() != std::floor(light.GetNumberAsDouble()))
                fail(path, name + ": KHR_lights_punctual \"light\" is not an index");
            const double index = light.GetNumberAsDouble();
            if (index < 0.0 || index >= static_cast<double>(model.lights.size()))
                fail(path, name + ": KHR_lights_punctual lights[" + std::to_string(static_cast<long long>(index)) +
                               "] out of range (" + std::to_string(model.lights.size()) + " lights)");
            flat.lights.push_back({step.node, static_cast<std::size_t>(index), world[step.node]});
        }
        stack.push_back({step.node, step.parent, true});
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
            push(*it, static_cast<std::ptrdiff_t>(step.node), name);
    }
    return flat;
}

}  // namespace ml::gltf
