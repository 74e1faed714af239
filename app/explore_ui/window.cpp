#include "explore_ui/window.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>

namespace m3055::explore {

namespace {

WindowEvents& events_of(GLFWwindow* window) {
    return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window));
}

void wake(GLFWwindow* window) { events_of(window).frames_owed = kFramesAfterInput; }

}  // namespace

Window::Window(int width, int height, const char* title) {
    glfwSetErrorCallback([](int, const char* text) { std::fprintf(stderr, "GLFW: %s\n", text); });
    if (!glfwInit()) {
        error_ = "m3055 explore: cannot open a window (no display?); use `m3055 render` for headless images";
        return;
    }
    glfw_ready_ = true;
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    // Within the monitor's work area (without task bars), so nothing is off screen.
    // No size asked: the whole work area.
    int area_x = 0, area_y = 0, area_w = 0, area_h = 0;
#ifndef __EMSCRIPTEN__  // in a page the canvas is the window (app/web/): its size is asked for
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) glfwGetMonitorWorkarea(monitor, &area_x, &area_y, &area_w, &area_h);
#endif
    if (width <= 0 || height <= 0) {
        width = area_w > 0 ? area_w : 1500;
        height = area_h > 0 ? area_h : 940;
    }
    if (area_w > 0 && area_h > 0) {
        width = std::min(width, area_w);
        height = std::min(height, area_h);
    }
    window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!window_) {
        error_ = "m3055 explore: cannot create a window with an OpenGL 3.3 core context";
        return;
    }
    title_ = title;
    if (area_w > 0 && area_h > 0) glfwSetWindowPos(window_, area_x + (area_w - width) / 2, area_y + (area_h - height) / 2);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);  // vsync: a drag redraws at most once per refresh
    glfwSetWindowUserPointer(window_, &events_);
    install_callbacks();
}

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    if (glfw_ready_) glfwTerminate();
}

// Installed before ImGui's, which chain to them.
void Window::install_callbacks() {
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_PRESS) events_of(w).keys.push_back({key, mods});
        wake(w);
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) { wake(w); });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int, int, int) { wake(w); });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double, double) { wake(w); });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double) { wake(w); });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int) { wake(w); });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int) { wake(w); });
    glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) { wake(w); });
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { wake(w); });
    glfwSetDropCallback(window_, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i) events_of(w).dropped.emplace_back(paths[i]);
        wake(w);
    });
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }

void Window::cancel_close() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void Window::set_title(const std::string& title) {
    if (title == title_) return;
    title_ = title;
    glfwSetWindowTitle(window_, title_.c_str());
}

void Window::poll() {
    asked_sleep_ = 0.0;
    glfwPollEvents();
}

void Window::wait(double seconds) {
    asked_sleep_ = seconds;
#ifdef __EMSCRIPTEN__
    (void)seconds;  // a page cannot block: it sleeps between animation frames (ExplorerSession::asked_sleep)
#else
    if (seconds < 0.0) glfwWaitEvents();  // idle: no CPU until the next event
    else glfwWaitEventsTimeout(seconds);
#endif
}

double Window::time() const { return glfwGetTime(); }

#ifdef __EMSCRIPTEN__
extern "C" void* emscripten_webgl2_get_proc_address(const char* name);  // Emscripten's system/lib/gl/webgl2.c
#endif

void* Window::gl_proc_address(const char* name) {
#ifdef __EMSCRIPTEN__
    // Emscripten 3.1.6's glfwGetProcAddress answers "glGenQueries" (and the
    // other query functions) with WebGL 1's EXT_disjoint_timer_query, absent
    // on WebGL2: WebGL2's own functions are looked up first.
    if (void* function = emscripten_webgl2_get_proc_address(name)) return function;
#endif
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

void Window::framebuffer_size(int* width, int* height) const { glfwGetFramebufferSize(window_, width, height); }

void Window::swap() { glfwSwapBuffers(window_); }

}  // namespace m3055::explore
