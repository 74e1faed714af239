// The explorer's window: GLFW with an OpenGL 3.3 core context, made and
// destroyed as one object, and the input events its callbacks note for the
// frame loop (which acts on them; the callbacks only record and wake it).
#pragma once

#include "explore/input_queue.h"

#include <deque>
#include <string>
#include <vector>

struct GLFWwindow;

namespace m3055::explore {

// After any input ImGui needs a few frames to settle (hover, press, release).
inline constexpr int kFramesAfterInput = 3;

struct WindowEvents {
    int frames_owed = kFramesAfterInput;  // frames to draw whatever happens (the first ones too)
    std::vector<std::string> dropped;     // files dropped onto the window
    struct Key {
        int key, mods;
    };
    std::vector<Key> keys;  // key presses, in order (as fed to ImGui)
    std::deque<InputEvent> input;  // key, character, button and pointer events not yet fed to ImGui (imgui_layer.cpp)
    // The pointer at its last move (a button's press or release happened there),
    // and the buttons held, as the window system reported them (bit i: button i).
    bool pointer_known = false;
    double pointer_x = 0.0, pointer_y = 0.0;
    unsigned buttons_held = 0;
};

class Window {
public:
    // Initializes GLFW and opens a window; ok() says whether it worked, and
    // error() why not (one line).
    Window(int width, int height, const char* title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    bool ok() const { return window_ != nullptr; }
    const std::string& error() const { return error_; }
    GLFWwindow* handle() const { return window_; }
    WindowEvents& events() { return events_; }

    bool should_close() const;
    void cancel_close();  // the close button was pressed, but the user is asked first
    void set_title(const std::string& title);  // only touches GLFW when it changes
    void poll();                                // handle pending events, don't wait
    void wait(double seconds);                  // sleep until an event or `seconds` (< 0: forever)
    // What the last poll or wait asked: 0 (go on), or the sleep (< 0: until an
    // event). A page cannot block: it stops its animation frames for as long.
    double asked_sleep() const { return asked_sleep_; }
    double time() const;                        // glfwGetTime()
    // A GL function of the window's context, by name (for load_gl_api).
    static void* gl_proc_address(const char* name);
    void framebuffer_size(int* width, int* height) const;
    void swap();

private:
    void install_callbacks();
    GLFWwindow* window_ = nullptr;
    bool glfw_ready_ = false;
    std::string error_, title_;
    WindowEvents events_;
    double asked_sleep_ = 0.0;
};

}  // namespace m3055::explore
