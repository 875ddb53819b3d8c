// OSMesa: Mesa's off-screen GL, the fallback where EGL is missing. GL 4.5 core via llvmpipe.
// libOSMesa is opened at run time: it drags in LLVM (over 100 MB), which a machine rendering
// through EGL on a GPU neither needs nor may have.
#include "renderer/context/gl_context.h"

#include "renderer/gl/gl_api.h"  // before osmesa.h, whose GL/gl.h include glad's header then guards

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <vector>

namespace ml {

namespace {

// The few OSMesa entry points we use, resolved from the shared library.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

const OsMesaApi& osMesaApi() {
    static const OsMesaApi api = [] {
        OsMesaApi a;
        void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
        if (!lib) return a;
        a.createContextAttribs = reinterpret_cast<decltype(a.createContextAttribs)>(dlsym(lib, "OSMesaCreateContextAttribs"));
        a.makeCurrent = reinterpret_cast<decltype(a.makeCurrent)>(dlsym(lib, "OSMesaMakeCurrent"));
        a.destroyContext = reinterpret_cast<decltype(a.destroyContext)>(dlsym(lib, "OSMesaDestroyContext"));
        a.getProcAddress = reinterpret_cast<decltype(a.getProcAddress)>(dlsym(lib, "OSMesaGetProcAddress"));
        return a;
    }();
    return api;
}

// glad calls this with GL function names; forwards to the dynamically loaded OSMesaGetProcAddress.
void (*osMesaProcAddress(const char* name))() { return reinterpret_cast<void (*)()>(osMesaApi().getProcAddress(name)); }

class OsMesaContext final : public GlContext {
public:
    explicit OsMesaContext(OSMesaContext context) : context_(context), buffer_(kSize * kSize * 4) { makeCurrent(); }
    ~OsMesaContext() override { osMesaApi().destroyContext(context_); }
    std::string platform() const override { return "OSMesa"; }
    void makeCurrent() override {
        // The default framebuffer is a small dummy: all rendering goes to framebuffer objects.
        if (!osMesaApi().makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize))
            throw ContextError("OSMesa: OSMesaMakeCurrent failed");
    }

private:
    static constexpr int kSize = 16;
    OSMesaContext context_;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(const ContextOptions&) {
    const OsMesaApi& api = osMesaApi();
    if (!api.createContextAttribs || !api.makeCurrent || !api.destroyContext || !api.getProcAddress)
        throw ContextError("OSMesa: libOSMesa.so.8 could not be loaded (Debian package libosmesa6)");
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4,
                           OSMESA_CONTEXT_MINOR_VERSION, 5,
                           0};
    OSMesaContext context = api.createContextAttribs(attribs, nullptr);
    if (!context) throw ContextError("OSMesa: could not create a GL 4.5 core context");
    auto result = std::make_unique<OsMesaContext>(context);
    loadGlFunctions(&osMesaProcAddress, "OSMesa");
    return result;
}

}  // namespace ml
