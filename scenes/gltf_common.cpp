#include "scenes/gltf_common.h"

#include "scenes/scene.h"

namespace ml::gltf {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

std::string clip(std::string_view s, std::size_t maxChars) {
    std::string out;
    for (char c : s.substr(0, maxChars)) out += (static_cast<unsigned char>(c) < 0x20) ? ' ' : c;
    if (s.size() > maxChars) out += "...";
    return out;
}

std::string oneLine(std::string_view text, std::size_t maxLines) {
    std::string out;
    std::size_t kept = 0, dropped = 0, pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trim(text.substr(pos, end - pos));
        pos = end + 1;
        if (line.empty()) continue;
        if (kept < maxLines) {
            if (kept > 0) out += "; ";
            out += clip(line);
            ++kept;
        } else {
            ++dropped;
        }
    }
    if (dropped > 0) out += " (and " + std::to_string(dropped) + " more)";
    return out;
}

[[noreturn]] void fail(const std::string& path, const std::string& fault) {
    throw SceneError(path + ": " + oneLine(fault, 1));
}

std::string named(const char* kind, std::size_t index, const std::string& name) {
    std::string s = std::string(kind) + "[" + std::to_string(index) + "]";
    if (!name.empty()) s += " '" + clip(name, 60) + "'";
    return s;
}

std::string counted(std::size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace ml::gltf
