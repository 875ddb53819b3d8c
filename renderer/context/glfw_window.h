// A desktop window with a GL 4.5 core context (GLFW), used by `manylights view`.
#pragma once

#include <string>

#include "renderer/context/gl_context.h"

struct GLFWwindow;

namespace ml {

class GlfwWindow final : public GlContext {
public:
    // Throws ContextError when no display is present or the context cannot be made.
    GlfwWindow(const std::string& title, int width, int height, const ContextOptions& options);
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    std::string platform() const override { return "GLFW window"; }
    void makeCurrent() override;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void swapBuffers();
    void setVsync(bool on);
    // Framebuffer size in pixels (0 x 0 while minimised).
    void framebufferSize(int& width, int& height) const;

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace ml
