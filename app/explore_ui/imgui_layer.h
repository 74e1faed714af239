// Dear ImGui on the explorer's window (GLFW platform, OpenGL 3 renderer),
// set up and torn down as one object; its callbacks chain to the window's.
// Key, character and mouse-button events wait in the window's queue
// (WindowEvents::input) and reach ImGui at most one transition per key or
// button per frame (explore/input_queue.h): a key pressed and released between
// two frames is not lost, and a click keeps its place among the keys.
#pragma once

#include "explore/input_queue.h"

struct GLFWwindow;

namespace m3055::explore {

class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void new_frame();  // this frame's queued keys, then the backends' and ImGui's NewFrame
    void render();     // ImGui::Render and the OpenGL backend's draw into the bound framebuffer

private:
    void apply_ui_scale(float scale);  // ImGui units to device pixels (the page's devicePixelRatio)
    GLFWwindow* window_;
    float ui_scale_ = 1.0f;
    // Each button as the queue has fed it (ImGui 1.86's GLFW backend reads the
    // buttons' live state at NewFrame, which may be ahead of the queue).
    bool buttons_down_[5] = {};
    bool pointer_known_ = false;  // the queue has fed a move or a click
    double pointer_x_ = 0.0, pointer_y_ = 0.0;  // the pointer as the queue has fed it
    InputFeed feed_;  // which queued events go to ImGui each frame (explore/input_queue.h)
};

}  // namespace m3055::explore
