#include "renderer/gl/shader_sources.h"

#include <stdexcept>

namespace ml::shaders {

std::string source(std::string_view name, const Defines& defines) {
    for (const EmbeddedShader& shader : embedded()) {
        if (shader.name != name) continue;
        std::string text(shader.source);
        const std::size_t versionEnd = text.find('\n') + 1;
        std::string injected;
        for (const auto& [key, value] : defines) injected += "#define " + key + " " + value + "\n";
        text.insert(versionEnd, injected);
        return text;
    }
    throw std::runtime_error("shader '" + std::string(name) + "' is not embedded in this build");
}

std::string describeFileTable() {
    std::string out;
    const auto& table = fileTable();
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (!out.empty()) out += ", ";
        out += std::to_string(i) + "=" + std::string(table[i]);
    }
    return out;
}

}  // namespace ml::shaders
