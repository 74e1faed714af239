// Dear ImGui on the explorer's window (GLFW platform, OpenGL 3 renderer),
// set up and torn down as one object; its callbacks chain to the window's.
#pragma once

struct GLFWwindow;

namespace m3055::explore {

class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void new_frame();  // the backends' and ImGui's NewFrame
    void render();     // ImGui::Render and the OpenGL backend's draw into the bound framebuffer
};

}  // namespace m3055::explore
