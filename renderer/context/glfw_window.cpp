#include "renderer/context/glfw_window.h"

#include "renderer/gl/gl_api.h"  // before glfw3.h, which must not include GL/gl.h itself

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ml {

namespace {
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}
}  // namespace

GlfwWindow::GlfwWindow(const std::string& title, int width, int height, const ContextOptions& options) {
    if (!glfwInit()) throw ContextError("GLFW: no display (" + lastGlfwError() + ")");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = lastGlfwError();
        glfwTerminate();
        throw ContextError("GLFW: could not open a GL 4.5 core window (" + why + ")");
    }
    glfwMakeContextCurrent(window_);
    loadGlFunctions(reinterpret_cast<GlProcLoader>(&glfwGetProcAddress), "GLFW window");
}

GlfwWindow::~GlfwWindow() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindow::makeCurrent() { glfwMakeContextCurrent(window_); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindow::setVsync(bool on) { glfwSwapInterval(on ? 1 : 0); }
void GlfwWindow::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

}  // namespace ml
