// An offscreen GL context made from the frame options, with the messages a user expects.
#pragma once

#include <memory>

#include "app/frame_options.h"
#include "renderer/context/gl_context.h"

namespace ml::app {

struct OffscreenSession {
    std::unique_ptr<GlContext> context;
    GlInfo info;
};

// Creates the context, enables KHR_debug output, picks the timing clock, prints notices
// (and GL_RENDERER/GL_VERSION with --verbose). Throws ContextError.
OffscreenSession openOffscreen(const FrameOptions& options, PreparedFrame& frame);

}  // namespace ml::app
