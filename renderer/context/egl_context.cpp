// EGL: the device platform first (a hardware GPU such as an NVIDIA one, with no display
// server), then Mesa's surfaceless platform, then any software device. No surface is made:
// the renderer draws into framebuffer objects.
#include "renderer/context/gl_context.h"

#include "renderer/gl/gl_api.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <cstring>

namespace ml {

namespace {

template <typename F>
F eglProc(const char* name) {
    return reinterpret_cast<F>(eglGetProcAddress(name));
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context, std::string platform)
        : display_(display), context_(context), platform_(std::move(platform)) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    std::string platform() const override { return platform_; }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw ContextError(platform_ + ": eglMakeCurrent failed");
    }

private:
    EGLDisplay display_;
    EGLContext context_;
    std::string platform_;
};

// Initialises `display` and makes a current GL 4.5 core context on it, or returns null with `why`.
std::unique_ptr<GlContext> tryDisplay(EGLDisplay display, const std::string& platform, const ContextOptions& options,
                                      std::string& why) {
    if (display == EGL_NO_DISPLAY) {
        why = platform + ": no display";
        return nullptr;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        why = platform + ": eglInitialize failed";
        return nullptr;
    }
    auto fail = [&](const std::string& reason) -> std::unique_ptr<GlContext> {
        why = platform + ": " + reason;
        eglTerminate(display);
        return nullptr;
    };
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) return fail("no EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API) failed");

    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
        const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0)
            return fail("no OpenGL-capable config");
    }
    // With reset notification where the driver offers it: a GPU reset (NVIDIA's watchdog ends a
    // draw of many seconds, leaving a black frame and no GL error) is then reported by
    // glGetGraphicsResetStatus, which checkNoGpuReset turns into an error.
    const EGLint robustAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                    EGL_CONTEXT_MINOR_VERSION, 5,
                                    EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                    EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE,
                                    EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY, EGL_LOSE_CONTEXT_ON_RESET,
                                    EGL_NONE};
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                     EGL_CONTEXT_MINOR_VERSION, 5,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE,
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, robustAttribs);
    if (context == EGL_NO_CONTEXT) context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return fail("could not create a GL 4.5 core context");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        return fail("eglMakeCurrent failed");
    }
    auto result = std::make_unique<EglContext>(display, context, platform);
    loadGlFunctions(reinterpret_cast<GlProcLoader>(&eglGetProcAddress), platform);
    return result;
}

}  // namespace

std::unique_ptr<GlContext> createEglContext(const ContextOptions& options) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!clientExtensions || !getPlatformDisplay) throw ContextError("EGL has no platform extensions");

    std::string reasons;
    auto note = [&](const std::string& why) { reasons += (reasons.empty() ? "" : "; ") + why; };

    // Devices, hardware ones first; software devices are kept for last.
    std::vector<EGLDeviceEXT> hardware, software;
    auto queryDevices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryDeviceString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    if (hasExtension(clientExtensions, "EGL_EXT_platform_device") && queryDevices) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
                (hasExtension(ext, "EGL_MESA_device_software") ? software : hardware).push_back(devices[i]);
            }
        }
    }
    for (std::size_t i = 0; i < hardware.size(); ++i) {
        std::string why;
        auto display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, hardware[i], nullptr);
        if (auto ctx = tryDisplay(display, "EGL device " + std::to_string(i), options, why)) return ctx;
        note(why);
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        std::string why;
        auto display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (auto ctx = tryDisplay(display, "EGL surfaceless", options, why)) return ctx;
        note(why);
    }
    for (EGLDeviceEXT device : software) {
        std::string why;
        auto display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (auto ctx = tryDisplay(display, "EGL software device", options, why)) return ctx;
        note(why);
    }
    throw ContextError(reasons.empty() ? "no EGL device or surfaceless platform" : reasons);
}

}  // namespace ml
