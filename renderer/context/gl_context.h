// GL 4.5 core contexts: one interface, three implementations (EGL, OSMesa, GLFW window).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ml {

enum class OffscreenBackend { Auto, Egl, OsMesa };

class ContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ContextOptions {
    OffscreenBackend backend = OffscreenBackend::Auto;
    bool debug = false;  // request a debug context (KHR_debug messages are delivered synchronously)
};

// A current GL 4.5 core context with its functions loaded. Offscreen contexts have no default
// framebuffer worth drawing to: rendering goes to framebuffer objects.
class GlContext {
public:
    virtual ~GlContext() = default;
    // How the context was made, e.g. "EGL device (NVIDIA)", "EGL surfaceless", "OSMesa", "GLFW window".
    virtual std::string platform() const = 0;
    virtual void makeCurrent() = 0;
};

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options);
std::unique_ptr<GlContext> createOsMesaContext(const ContextOptions& options);

// Auto tries EGL, then OSMesa; a fallback adds a one-line notice.
std::unique_ptr<GlContext> createOffscreenContext(const ContextOptions& options, std::vector<std::string>& notices);

// Loads GL entry points through `getProcAddress` and checks for GL 4.5; throws ContextError.
using GlProcLoader = void (*(*)(const char*))();
void loadGlFunctions(GlProcLoader getProcAddress, const std::string& platform);

struct GlInfo {
    std::string renderer;
    std::string version;
    std::string vendor;
    bool software = false;  // llvmpipe/softpipe: timer queries do not reflect real cost
};
GlInfo queryGlInfo();

// A GPU reset of the context: every later GL call is lost with it, so callers stop rather than
// go on to the next frame or point.
struct GpuResetError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// Throws GpuResetError naming `during` when the GPU reset the context (reported where the
// context was made with reset notification; a reset leaves wrong images and no GL error).
void checkNoGpuReset(const char* during);

// Parses "auto", "egl", "osmesa"; throws std::invalid_argument naming the value.
OffscreenBackend parseBackend(const std::string& text);

}  // namespace ml
