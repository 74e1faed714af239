#include "explore_ui/imgui_layer.h"

#include "explore_ui/clip_check.h"
#include "explore_ui/window.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <GLFW/glfw3.h>

#include <cfloat>
#include <cstdio>
#include <deque>
#include <iterator>

#ifdef __EMSCRIPTEN__
#include <emscripten/html5.h>
#endif

namespace m3055::explore {

namespace {
constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

WindowEvents& events_of(GLFWwindow* window) {
    return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window));
}

bool is_modifier(int key) {
    return (key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER) || key == GLFW_KEY_CAPS_LOCK;
}

// Queued instead of given to ImGui at once (Dear ImGui 1.86 would lose a
// press and release between two frames); the frame loop wakes.
void queue_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    InputEvent event;
    event.key = key;
    event.scancode = scancode;
    event.action = action;
    event.mods = mods;
    event.press = action == GLFW_PRESS;
    event.edit_key = key >= GLFW_KEY_ESCAPE && !is_modifier(key);  // GLFW: printable keys are below 256
    event.focus_key = key == GLFW_KEY_TAB && event.press;
    WindowEvents& events = events_of(window);
    events.input.push_back(event);
    events.frames_owed = kFramesAfterInput;
}

void queue_char(GLFWwindow* window, unsigned codepoint) {
    InputEvent event;
    event.kind = InputEvent::Kind::character;
    event.codepoint = codepoint;
    WindowEvents& events = events_of(window);
    events.input.push_back(event);
    events.frames_owed = kFramesAfterInput;
}

// A click waits in the same queue, behind the keys before it (a Ctrl press
// still queued must reach ImGui first), where the pointer was then: at the
// last move queued before it (the window system's pointer may be elsewhere by now).
void queue_mouse_button(GLFWwindow* window, int button, int action, int mods) {
    InputEvent event;
    event.kind = InputEvent::Kind::mouse_button;
    event.key = button;
    event.action = action;
    event.mods = mods;
    event.press = action == GLFW_PRESS;
    WindowEvents& events = events_of(window);
    if (button >= 0 && button < 32) events.buttons_held = (events.buttons_held & ~(1u << button)) | (unsigned(event.press) << button);
    if (events.pointer_known) event.x = events.pointer_x, event.y = events.pointer_y;
    else glfwGetCursorPos(window, &event.x, &event.y);
    events.input.push_back(event);
    events.frames_owed = kFramesAfterInput;
}

// The pointer's moves wait in the queue while a button is held or events
// wait before them, so a drag is fed as it was made; others (hovering, the
// window moving under a parked pointer) the backend reads as before.
void queue_pointer(GLFWwindow* window, double x, double y) {
    WindowEvents& events = events_of(window);
    events.pointer_known = true;
    events.pointer_x = x, events.pointer_y = y;
    events.frames_owed = kFramesAfterInput;
    if (events.buttons_held == 0 && events.input.empty()) return;
    InputEvent event;
    event.kind = InputEvent::Kind::pointer;
    event.x = x, event.y = y;
    events.input.push_back(event);
}

bool button_queued(const std::deque<InputEvent>& queue, int button) {
    for (const InputEvent& event : queue)
        if (event.kind == InputEvent::Kind::mouse_button && event.key == button) return true;
    return false;
}

#ifdef __EMSCRIPTEN__
// The page's mouse wheel. Emscripten 3.1.6's GLFW (library_glfw.js,
// onMouseWheel) hands the DOM wheel event's deltaX/deltaY to the scroll
// callback as they are: in pixels (100 a notch in Chromium) and with a page's
// sign (down positive), where GLFW's offsets are notches, up positive. Dear
// ImGui then scrolls 100 steps the wrong way: down at the top of the panel did
// nothing. Here the deltas become notches as Emscripten's own
// Browser.getMouseWheelDelta counts them (100 pixels, 3 lines, or 1/80 of a
// page a notch; a touchpad's fractions kept), sign flipped, and go to ImGui's
// scroll callback (which chains to the window's, waking the loop).
EM_BOOL on_wheel(int, const EmscriptenWheelEvent* wheel, void* window) {
    const double per_notch = wheel->deltaMode == DOM_DELTA_PIXEL ? 100.0 : wheel->deltaMode == DOM_DELTA_LINE ? 3.0 : 1.0 / 80.0;
    ImGui_ImplGlfw_ScrollCallback(static_cast<GLFWwindow*>(window), -wheel->deltaX / per_notch,
                                  -wheel->deltaY / per_notch);
    return EM_TRUE;  // handled: the page itself does not scroll
}
#endif

// A readable font where the system has one (ImGui's built-in one
// otherwise), rasterized at `scale` device pixels per ImGui unit and drawn at
// 1/scale, so that text is 15 units high and sharp on the device's pixels.
void load_font(float scale) {
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->Clear();
    io.FontGlobalScale = 1.0f / scale;
    if (std::FILE* f = std::fopen(kFont, "rb")) {
        std::fclose(f);
        // Latin and Greek (F(\u03bb, 0), \u03c3, \u03b1): DejaVu has both; ImGui 1.86 names no Greek range.
        static const ImWchar kLatinAndGreek[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0};
        io.Fonts->AddFontFromFileTTF(kFont, 15.0f * scale, nullptr, kLatinAndGreek);
    } else {
        ImFontConfig config;
        config.SizePixels = 13.0f * scale;
        io.Fonts->AddFontDefault(&config);
    }
}

}  // namespace

ImGuiLayer::ImGuiLayer(GLFWwindow* window) : window_(window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // fixed layout: nothing to remember between runs
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    load_font(1.0f);
    ImGui_ImplGlfw_InitForOpenGL(window, true);  // its key and char callbacks chain to the window's
    glfwSetKeyCallback(window, queue_key);       // ... and are called from the queue (new_frame)
    glfwSetCharCallback(window, queue_char);
    glfwSetMouseButtonCallback(window, queue_mouse_button);
    glfwSetCursorPosCallback(window, queue_pointer);
#ifdef __EMSCRIPTEN__
    glfwSetScrollCallback(window, nullptr);  // GLFW's wheel off (its units are wrong: on_wheel) ...
    emscripten_set_wheel_callback("#canvas", window, EM_TRUE, on_wheel);  // ... the page's on
    ImGui_ImplOpenGL3_Init("#version 300 es");  // WebGL2
#else
    ImGui_ImplOpenGL3_Init("#version 330");
#endif
}

ImGuiLayer::~ImGuiLayer() {
#ifdef __EMSCRIPTEN__
    emscripten_set_wheel_callback("#canvas", nullptr, EM_TRUE, nullptr);
#endif
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::new_frame() {
    std::deque<InputEvent>& queue = events_of(window_).input;
    bool pointer_fed = false, button_fed = false;
    for (std::size_t n = feed_.this_frame(queue); n > 0; --n) {
        const InputEvent event = queue.front();
        queue.pop_front();
        feed_.fed(event);
        if (event.kind == InputEvent::Kind::character) {
            ImGui_ImplGlfw_CharCallback(window_, event.codepoint);
        } else if (event.kind == InputEvent::Kind::pointer) {
            pointer_fed = pointer_known_ = true, pointer_x_ = event.x, pointer_y_ = event.y;
        } else if (event.kind == InputEvent::Kind::mouse_button) {
            ImGui_ImplGlfw_MouseButtonCallback(window_, event.key, event.action, event.mods);
            if (event.key >= 0 && event.key < int(std::size(buttons_down_))) buttons_down_[event.key] = event.press;
            button_fed = pointer_known_ = true, pointer_x_ = event.x, pointer_y_ = event.y;
        } else {
            ImGui_ImplGlfw_KeyCallback(window_, event.key, event.scancode, event.action, event.mods);
        }
    }
    if (!queue.empty()) events_of(window_).frames_owed = kFramesAfterInput;  // the rest: the next frames
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    // The buttons as fed, not as they are now (the backend polled those). A
    // button up now with nothing of it queued lost its release (released
    // outside a browser's canvas): up.
    ImGuiIO& io = ImGui::GetIO();
    for (int button = 0; button < int(std::size(buttons_down_)); ++button) {
        if (buttons_down_[button] && !button_queued(queue, button) &&
            glfwGetMouseButton(window_, button) != GLFW_PRESS)
            buttons_down_[button] = false;
        io.MouseDown[button] = buttons_down_[button];
    }
    // Where the fed events left the pointer, not where it is now (while events
    // wait, it is ahead of them): a click's place always; a move's only while
    // the backend says the pointer is the window's (it knows when the pointer
    // left, or was never in an unfocused window: no one hovers then).
    const bool pointer_in_window = io.MousePos.x > -FLT_MAX;
    if (button_fed || ((pointer_fed || !queue.empty()) && pointer_known_ && pointer_in_window))
        io.MousePos = ImVec2(float(pointer_x_), float(pointer_y_));
#ifdef __EMSCRIPTEN__
    apply_ui_scale(float(emscripten_get_device_pixel_ratio()));
#endif
    // Dear ImGui 1.86 asserts on a zero time step; two frames in one tick of
    // the clock happen in a browser (its timers are coarse on purpose).
    if (!(io.DeltaTime > 0.0f)) io.DeltaTime = 1e-4f;
    ImGui::NewFrame();
}

// The page's canvas is sized in device pixels (app/web/page.js): ImGui works in
// CSS pixels (devicePixelRatio, the browser's zoom included, device pixels
// each) and draws at the device's, as on a desktop's HiDPI screen, so the
// panels read at their size on any screen and at any zoom.
void ImGuiLayer::apply_ui_scale(float scale) {
    if (!(scale > 0.0f)) scale = 1.0f;
    ImGuiIO& io = ImGui::GetIO();
    if (scale != ui_scale_) {
        ui_scale_ = scale;
        load_font(scale);
        ImGui_ImplOpenGL3_DestroyFontsTexture();
        ImGui_ImplOpenGL3_CreateFontsTexture();
    }
    io.DisplaySize = ImVec2(io.DisplaySize.x / scale, io.DisplaySize.y / scale);
    io.DisplayFramebufferScale = ImVec2(scale, scale);
    if (io.MousePos.x > -FLT_MAX) io.MousePos = ImVec2(io.MousePos.x / scale, io.MousePos.y / scale);
}

void ImGuiLayer::render() {
    ImGui::Render();
    report_clipping();  // M3055_CHECK_CLIPPING (clip_check.h)
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace m3055::explore
