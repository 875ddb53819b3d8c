#include "renderer/gl/debug_output.h"

#include <atomic>
#include <cstdio>
#include <mutex>

#include "renderer/gl/gl_api.h"

namespace ml::gl {

namespace {

std::atomic<int> g_errors{0};
std::mutex g_mutex;
std::string g_lastError;
DebugVerbosity g_verbosity = DebugVerbosity::ErrorsOnly;

// No exception may cross this callback: GL calls it from inside the driver.
void GLAPIENTRY onDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* /*user*/) noexcept {
    const bool isError = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
    if (!isError && (g_verbosity == DebugVerbosity::ErrorsOnly || severity == GL_DEBUG_SEVERITY_NOTIFICATION)) return;
    const std::string text(message, length >= 0 ? static_cast<std::size_t>(length) : std::char_traits<char>::length(message));
    if (isError) {
        ++g_errors;
        std::lock_guard lock(g_mutex);
        g_lastError = text;
    }
    std::fprintf(stderr, "GL %s (id %u): %s\n", isError ? "error" : "message", id, text.c_str());
}

}  // namespace

void enableDebugOutput(DebugVerbosity verbosity) {
    g_verbosity = verbosity;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

int debugErrorCount() { return g_errors.load(); }

std::string lastDebugError() {
    std::lock_guard lock(g_mutex);
    return g_lastError;
}

void resetDebugErrors() {
    g_errors = 0;
    std::lock_guard lock(g_mutex);
    g_lastError.clear();
}

std::string drainGlErrors() {
    std::string out;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%s0x%04X", out.empty() ? "" : ", ", e);
        out += buf;
    }
    return out;
}

}  // namespace ml::gl
