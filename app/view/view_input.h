// The view's keyboard and mouse, read from GLFW once per frame: held keys and mouse drags become
// a CameraInput; shortcut keys (1/2/3, F1/H, F12, ...) arrive as one press each.
#pragma once

#include <string>
#include <vector>

#include "renderer/camera/camera_controller.h"

struct GLFWwindow;

namespace ml::app {

struct FrameInput {
    CameraInput camera;
    std::vector<int> pressedKeys;  // GLFW_KEY_* pressed since the last frame, in order
    std::vector<std::string> droppedPaths;  // files dropped on the window since the last frame
};

class ViewInput {
public:
    // Installs the window's key, scroll and drop callbacks; create it before ImGuiLayer, whose
    // callbacks call these after their own.
    explicit ViewInput(GLFWwindow* window);
    ViewInput(const ViewInput&) = delete;
    ViewInput& operator=(const ViewInput&) = delete;

    // What happened since the last call. Input the panel owns (panelHasMouse/Keyboard) is left
    // out. In fly mode the right button looks around; in orbit mode either button orbits.
    FrameInput collect(CameraMode mode, bool panelHasMouse, bool panelHasKeyboard);

    // GLFW's drop callback: files dropped on the window (a .gltf/.glb opens in place).
    static void onDrop(GLFWwindow* window, int count, const char** paths);

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double dx, double dy);

    GLFWwindow* window_;
    std::vector<int> pressed_;
    std::vector<std::string> dropped_;
    float scroll_ = 0.0f;
    bool dragging_ = false;
    double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace ml::app
