#include "renderer/context/gl_context.h"

#include <stdexcept>
#include <string>

#include "renderer/context/keep_modules_loaded.h"
#include "renderer/gl/depth_convention.h"
#include "renderer/gl/gl_api.h"

namespace ml {

void loadGlFunctions(GlProcLoader getProcAddress, const std::string& platform) {
    keepLoadedModulesUntilExit();  // the driver is loaded by now (sanitizer builds only)
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress));
    if (version == 0) throw ContextError(platform + ": could not load OpenGL functions");
    const int major = GLAD_VERSION_MAJOR(version);
    const int minor = GLAD_VERSION_MINOR(version);
    if (major < 4 || (major == 4 && minor < 5)) {
        throw ContextError(platform + ": OpenGL 4.5 core is required, the context offers " + std::to_string(major) +
                           "." + std::to_string(minor));
    }
    depth::useReversedDepth();
}

GlInfo queryGlInfo() {
    auto str = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "");
    };
    GlInfo info{str(GL_RENDERER), str(GL_VERSION), str(GL_VENDOR), false};
    info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                    info.renderer.find("softpipe") != std::string::npos ||
                    info.renderer.find("Software") != std::string::npos;
    return info;
}

OffscreenBackend parseBackend(const std::string& text) {
    if (text == "auto") return OffscreenBackend::Auto;
    if (text == "egl") return OffscreenBackend::Egl;
    if (text == "osmesa") return OffscreenBackend::OsMesa;
    throw std::invalid_argument("unknown backend '" + text + "' (expected auto, egl or osmesa)");
}

std::unique_ptr<GlContext> createOffscreenContext(const ContextOptions& options, std::vector<std::string>& notices) {
    switch (options.backend) {
    case OffscreenBackend::Egl: return createEglContext(options);
    case OffscreenBackend::OsMesa: return createOsMesaContext(options);
    case OffscreenBackend::Auto: break;
    }
    try {
        return createEglContext(options);
    } catch (const ContextError& e) {
        notices.push_back(std::string("EGL unavailable (") + e.what() + "); falling back to OSMesa");
    }
    return createOsMesaContext(options);
}

}  // namespace ml

namespace ml {

void checkNoGpuReset(const char* during) {
    const GLenum status = glGetGraphicsResetStatus();
    if (status == GL_NO_ERROR) return;
    const char* who = status == GL_GUILTY_CONTEXT_RESET ? "this context's work" : status == GL_INNOCENT_CONTEXT_RESET ? "another context's work" : "an unknown cause";
    throw GpuResetError(std::string("the GPU reset the GL context during ") + during + " (" + who +
                             "; a single draw of many seconds meets the driver's watchdog, e.g. naive at millions of pixels x tens of "
                             "thousands of lights): the frame is lost; lower --lights or --size");
}

}  // namespace ml
