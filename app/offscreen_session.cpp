#include "app/offscreen_session.h"

#include <cstdio>

#include "renderer/gl/debug_output.h"
#include "renderer/gl/gl_api.h"

namespace ml::app {

OffscreenSession openOffscreen(const FrameOptions& options, PreparedFrame& frame) {
    OffscreenSession s;
    std::vector<std::string> notices;
    s.context = createOffscreenContext(frame.context, notices);
    for (const std::string& n : notices) std::fprintf(stderr, "notice: %s\n", n.c_str());
    gl::enableDebugOutput(options.glDebug ? gl::DebugVerbosity::All : gl::DebugVerbosity::ErrorsOnly);
    s.info = queryGlInfo();
    frame.settings.clock = s.info.software ? TimingClock::WallClockAfterFinish : TimingClock::GpuQueries;
    if (options.verbose) {
        std::printf("GL_RENDERER: %s\nGL_VERSION: %s\nplatform: %s\n", s.info.renderer.c_str(), s.info.version.c_str(),
                    s.context->platform().c_str());
    }
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (frame.settings.width > maxSize || frame.settings.height > maxSize)
        throw ContextError("--size " + std::to_string(frame.settings.width) + "x" + std::to_string(frame.settings.height) +
                           ": larger than this GPU's maximum texture size " + std::to_string(maxSize));
    return s;
}

}  // namespace ml::app
