#include "renderer/debug_view.h"

#include <stdexcept>

namespace ml {

const std::vector<std::string>& debugViewNames() {
    // Indexed by the enum's value.
    static const std::vector<std::string> names{"shaded", "light-count", "slices", "clusters",
                                                "overflow", "albedo", "normal", "depth", "overdraw"};
    return names;
}

DebugView parseDebugView(const std::string& text) {
    const auto& names = debugViewNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == text) return static_cast<DebugView>(i);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("--view '" + text + "': expected one of " + list);
}

std::string debugViewName(DebugView view) { return debugViewNames().at(static_cast<std::size_t>(view)); }

}  // namespace ml
