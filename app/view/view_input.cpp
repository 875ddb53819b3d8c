#include "app/view/view_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ml::app {

ViewInput::ViewInput(GLFWwindow* window) : window_(window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetKeyCallback(window, &ViewInput::onKey);
    glfwSetScrollCallback(window, &ViewInput::onScroll);
    glfwSetDropCallback(window, &ViewInput::onDrop);
}

void ViewInput::onDrop(GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<ViewInput*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
}

void ViewInput::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
    if (action != GLFW_PRESS) return;
    static_cast<ViewInput*>(glfwGetWindowUserPointer(window))->pressed_.push_back(key);
}

void ViewInput::onScroll(GLFWwindow* window, double /*dx*/, double dy) {
    static_cast<ViewInput*>(glfwGetWindowUserPointer(window))->scroll_ += static_cast<float>(dy);
}

FrameInput ViewInput::collect(CameraMode mode, bool panelHasMouse, bool panelHasKeyboard) {
    FrameInput in;
    in.droppedPaths = std::move(dropped_);
    dropped_.clear();
    if (!panelHasKeyboard) {
        in.pressedKeys = std::move(pressed_);
        auto held = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
        in.camera.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
                          held(GLFW_KEY_W) - held(GLFW_KEY_S)};
        in.camera.fast = held(GLFW_KEY_LEFT_SHIFT) > 0.0f || held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
    }
    pressed_.clear();

    const bool right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool button = mode == CameraMode::Fly ? right : (left || right);
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    // A drag belongs to the camera only if it started outside the panel.
    if (button && !dragging_ && !panelHasMouse) {
        dragging_ = true;
        // Fly: hide and free the cursor so looking around is not stopped by the screen's edge.
        if (mode == CameraMode::Fly) glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        glfwGetCursorPos(window_, &x, &y);
    } else if (dragging_ && button) {
        in.camera.drag = {static_cast<float>(x - lastX_), static_cast<float>(y - lastY_)};
    } else if (dragging_ && !button) {
        dragging_ = false;
        glfwSetInputMode(window_, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
    }
    lastX_ = x;
    lastY_ = y;

    if (!panelHasMouse) in.camera.scroll = scroll_;
    scroll_ = 0.0f;
    return in;
}

}  // namespace ml::app
