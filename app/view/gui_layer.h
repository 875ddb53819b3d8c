// Dear ImGui over the view's GLFW window: the ImGui context and its GLFW and OpenGL3 backends,
// created and destroyed together (RAII instead of three init/shutdown pairs).
#pragma once

struct GLFWwindow;

namespace ml::app {

class ImGuiLayer {
public:
    // Install the window's own GLFW callbacks first: ImGui's callbacks call them after their own.
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void beginFrame();
    // Draws the frame's widgets into the bound framebuffer (the window's).
    void endFrame();
    // Ends the frame without drawing: a window that sizes itself to its contents is laid out
    // in its first frame and shown from the second, so a scripted single frame lays out first.
    void discardFrame();

    // The panel has the mouse or keyboard (a drag over it, typing into a field): the camera
    // and the shortcut keys leave that input alone.
    bool wantsMouse() const;
    bool wantsKeyboard() const;
};

}  // namespace ml::app
