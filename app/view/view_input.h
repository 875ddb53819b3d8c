// The view's keyboard and mouse, read from GLFW once per frame: held keys and mouse drags become
// a CameraInput; shortcut keys (1/2/3, F1/H, F12, ...) arrive as one press each.
#pragma once

#include <vector>

#include "renderer/camera/camera_controller.h"

struct GLFWwindow;

namespace ml::app {

struct FrameInput {
    CameraInput camera;
    std::vector<int> pressedKeys;  // GLFW_KEY_* pressed since the last frame, in order
};

class ViewInput {
public:
    // Installs the window's key and scroll callbacks; create it before ImGuiLayer, whose
    // callbacks call these after their own.
    explicit ViewInput(GLFWwindow* window);
    ViewInput(const ViewInput&) = delete;
    ViewInput& operator=(const ViewInput&) = delete;

    // What happened since the last call. Input the panel owns (panelHasMouse/Keyboard) is left
    // out. In fly mode the right button looks around; in orbit mode either button orbits.
    FrameInput collect(CameraMode mode, bool panelHasMouse, bool panelHasKeyboard);

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);

    GLFWwindow* window_;
    std::vector<int> pressed_;
    float scroll_ = 0.0f;
    bool dragging_ = false;
    double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace ml::app
