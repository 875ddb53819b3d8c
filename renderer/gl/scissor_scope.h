// A scissor for the life of a scope, inside whatever scissor was already in force, which it
// restores on leaving. A pass that scissors its raster (the glass's capture window) may run
// inside another's: naive forward draws a large frame in scissored bands, and a pass that simply
// disabled the test on leaving turned the rest of those bands into whole frames (on an H100 naive
// took 781 ms a frame at 2560x1440 and 1,024 lights in place of 241: docs/bench/nvidia-h100/naive-bands/).
#pragma once

#include <algorithm>

#include <glm/vec4.hpp>

#include "renderer/gl/gl_api.h"

namespace ml::gl {

class ScissorScope {
public:
    // rect: x, y, width, height in pixels.
    explicit ScissorScope(glm::ivec4 rect) {
        enclosed_ = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
        glGetIntegerv(GL_SCISSOR_BOX, &outer_.x);
        if (enclosed_) rect = intersection(rect, outer_);
        glEnable(GL_SCISSOR_TEST);
        glScissor(rect.x, rect.y, rect.z, rect.w);
    }
    ~ScissorScope() {
        glScissor(outer_.x, outer_.y, outer_.z, outer_.w);
        if (!enclosed_) glDisable(GL_SCISSOR_TEST);
    }
    ScissorScope(const ScissorScope&) = delete;
    ScissorScope& operator=(const ScissorScope&) = delete;

private:
    static glm::ivec4 intersection(glm::ivec4 a, glm::ivec4 b) {
        const int x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
        const int x1 = std::min(a.x + a.z, b.x + b.z), y1 = std::min(a.y + a.w, b.y + b.w);
        return {x0, y0, std::max(x1 - x0, 0), std::max(y1 - y0, 0)};
    }

    bool enclosed_ = false;
    glm::ivec4 outer_{0};
};

}  // namespace ml::gl
