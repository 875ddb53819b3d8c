// OSMesa: Mesa's off-screen GL, the fallback where EGL is missing. GL 4.5 core via llvmpipe.
#include "renderer/context/gl_context.h"

#include "renderer/gl/gl.h"  // before osmesa.h, whose GL/gl.h include glad's header then guards

#include <GL/osmesa.h>

#include <vector>

namespace ml {

namespace {

class OsMesaContext final : public GlContext {
public:
    explicit OsMesaContext(OSMesaContext context) : context_(context), buffer_(kSize * kSize * 4) { makeCurrent(); }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }
    std::string platform() const override { return "OSMesa"; }
    void makeCurrent() override {
        // The default framebuffer is a small dummy: all rendering goes to framebuffer objects.
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize))
            throw ContextError("OSMesa: OSMesaMakeCurrent failed");
    }

private:
    static constexpr int kSize = 16;
    OSMesaContext context_;
    std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(const ContextOptions&) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 4,
                           OSMESA_CONTEXT_MINOR_VERSION, 5,
                           0};
    OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context) throw ContextError("OSMesa: could not create a GL 4.5 core context");
    auto result = std::make_unique<OsMesaContext>(context);
    loadGlFunctions(reinterpret_cast<GlProcLoader>(&OSMesaGetProcAddress), "OSMesa");
    return result;
}

}  // namespace ml
