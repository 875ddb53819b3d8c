// The shaders of glsl/, with includes resolved, embedded at build time by tools/embed_shaders.py.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ml::shaders {

struct EmbeddedShader {
    std::string_view name;    // path under glsl/, e.g. "naive_forward.frag"
    std::string_view source;  // resolved source, starting with #version
};

// Generated.
const std::vector<EmbeddedShader>& embedded();
const std::vector<std::string_view>& fileTable();  // source-string ids used by #line

using Defines = std::vector<std::pair<std::string, std::string>>;

// `defines` with one more: a program's variant of another's list.
inline Defines withDefine(Defines defines, std::string name, std::string value) {
    defines.emplace_back(std::move(name), std::move(value));
    return defines;
}

// The source of a shader with `#define NAME VALUE` lines inserted after #version.
// Throws std::runtime_error naming the shader if it is not embedded.
std::string source(std::string_view name, const Defines& defines = {});

// "id=file" pairs, appended to compile errors so the driver's "id:line" can be read.
std::string describeFileTable();

}  // namespace ml::shaders
