// The explorer's frame loop, top to bottom in the order of Dear ImGui's
// example_glfw_opengl3/main.cpp: window and context, GL table, ImGui, then
// a loop that sleeps until something happens (render on demand).
#include "explore/explore.h"

#include "explore/keys.h"
#include "explore/panels.h"
#include "explore/script.h"
#include "explore/state.h"
#include "gl/gl_api.h"
#include "image/image.h"
#include "renderer.h"
#include "scene/load.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace m3055 {

using namespace explore;

namespace {

// ---- Input events (GLFW callbacks) --------------------------------------------
// The callbacks only note that something happened; the frame loop acts on it.
// After any input ImGui needs a few frames to settle (hover, press, release).
constexpr int kFramesAfterInput = 3;

struct WindowEvents {
    int frames_owed = kFramesAfterInput;  // draw the first frames unconditionally
    std::vector<std::string> dropped;     // files dropped onto the window
    struct Key {
        int key, mods;
    };
    std::vector<Key> keys;
};

WindowEvents& events_of(GLFWwindow* window) {
    return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window));
}
void wake(GLFWwindow* window) { events_of(window).frames_owed = kFramesAfterInput; }

void install_event_callbacks(GLFWwindow* window) {
    // Installed before ImGui's, which chain to them.
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int mods) {
        if (action == GLFW_PRESS) events_of(w).keys.push_back({key, mods});
        wake(w);
    });
    glfwSetCharCallback(window, [](GLFWwindow* w, unsigned) { wake(w); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { wake(w); });
    glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { wake(w); });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { wake(w); });
    glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { wake(w); });
    glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { wake(w); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { wake(w); });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { wake(w); });
    glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
        for (int i = 0; i < count; ++i) events_of(w).dropped.emplace_back(paths[i]);
        wake(w);
    });
}

// ---- Layout -----------------------------------------------------------------------
struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
};
struct Layout {
    Rect side, bottom, display;
};
constexpr float kSideWidth = 440.0f;
constexpr float kBottomHeight = 270.0f;
constexpr float kCompareGap = 8.0f;  // between A and B

Layout layout_for(float width, float height, bool panels) {
    Layout l;
    if (!panels) {
        l.display = {0, 0, width, height};
        return l;
    }
    l.side = {0, 0, std::min(kSideWidth, width), height};
    const float right = std::max(0.0f, width - l.side.w);
    l.bottom = {l.side.w, std::max(0.0f, height - kBottomHeight), right, std::min(kBottomHeight, height)};
    l.display = {l.side.w, 0, right, l.bottom.y};
    return l;
}

// The largest whole-pixel magnification of a w x h image that fits `area`
// (framebuffer pixels); 0 when even 1:1 does not fit.
int whole_pixel_scale(int w, int h, float area_w, float area_h) {
    return static_cast<int>(std::min(std::floor(area_w / w), std::floor(area_h / h)));
}

// Draws the display texture(s) centred in `area`, magnified by whole pixels,
// nearest-neighbour (the renderer's texture is GL_NEAREST). Returns the scale.
int draw_display(const std::vector<unsigned>& textures, int w, int h, const Rect& area,
                 float fb_scale) {
    const int n = static_cast<int>(textures.size());
    const float gap = n > 1 ? kCompareGap : 0.0f;
    const float area_w = (area.w - gap * (n - 1)) * fb_scale / n, area_h = area.h * fb_scale;
    const int scale = whole_pixel_scale(w, h, area_w, area_h);
    // Too big even at 1:1: shrink to fit (no longer whole pixels; the panel says so).
    const float shown = scale >= 1 ? static_cast<float>(scale)
                                   : std::min(area_w / w, area_h / h);
    const float iw = w * shown / fb_scale, ih = h * shown / fb_scale;  // ImGui units
    const float total = iw * n + gap * (n - 1);
    // Snap the corner to a framebuffer pixel so every dot covers whole pixels.
    float x = std::floor((area.x + (area.w - total) * 0.5f) * fb_scale) / fb_scale;
    const float y = std::floor((area.y + (area.h - ih) * 0.5f) * fb_scale) / fb_scale;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const char* labels[2] = {"A: the scene (saved, screenshot)", "B: selected object in material B"};
    for (int i = 0; i < n; ++i) {
        // GL textures store row 0 at the bottom: flip v.
        draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(textures[i])),
                       ImVec2(x, y), ImVec2(x + iw, y + ih), ImVec2(0, 1), ImVec2(1, 0));
        // A thin frame shows the display's extent even where the scene is black.
        draw->AddRect(ImVec2(x - 1, y - 1), ImVec2(x + iw + 1, y + ih + 1), IM_COL32(90, 90, 100, 255));
        // Labels above the pictures, never on them: the display stays exactly the screenshot.
        if (n > 1) draw->AddText(ImVec2(x, y - ImGui::GetTextLineHeight() - 4), IM_COL32(255, 255, 255, 220), labels[i]);
        x += iw + gap;
    }
    return std::max(scale, 0);
}

// ---- Reading back ----------------------------------------------------------------
// The whole window as the user sees it (the back buffer, after ImGui has drawn).
Rgb8Image read_window(const GlApi& gl, int width, int height) {
    Rgb8Image image;
    image.width = width;
    image.height = height;
    image.pixels.resize(static_cast<std::size_t>(width) * height * 3);
    std::vector<std::uint8_t> rows(image.pixels.size());
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl.ReadBuffer(GL_BACK);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t stride = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y) {  // GL rows are bottom to top, PNG top to bottom
        std::copy_n(rows.data() + (height - 1 - y) * stride, stride, image.pixels.data() + y * stride);
    }
    return image;
}

std::string json_beside(const std::string& png_path) {
    const auto dot = png_path.find_last_of('.');
    const auto slash = png_path.find_last_of('/');
    const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_extension ? png_path.substr(0, dot) : png_path) + ".json";
}

// The screenshot: exactly what `m3055 render` writes for the saved scene (the
// same Renderer, the same read_display and write_png), and the scene beside it.
void take_screenshot(ExplorerState& state, Renderer& renderer) {
    const std::string& png = state.screenshot_path;
    try {
        renderer.render(state.scene);
        write_png(png, renderer.read_display());
        if (save_scene(state, json_beside(png))) state.status = "screenshot " + png + " + " + json_beside(png);
    } catch (const std::exception& e) {
        state.error = e.what();
    }
}

void write_stats(const std::string& path, long frames, long renders, const Script* script) {
    nlohmann::json stats = {{"frames", frames}, {"renders", renders}};
    stats["idle"] = nlohmann::json::array();
    if (script) {
        for (const IdleRecord& r : script->idle_records()) {
            stats["idle"].push_back({{"seconds", r.seconds}, {"frames", r.frames}});
        }
        stats["script_errors"] = script->errors();
    }
    const std::string text = stats.dump(2) + "\n";
    write_file_atomic(path, text.data(), text.size());
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int run_explorer(const ExploreOptions& options) {
    // ---- The starting scene and script (before any window, so errors are quick) ----
    ExplorerState state;
    if (options.scene_path.empty()) {
        set_scene(state, default_scene(), "SPEC example");
    } else {
        try {
            set_scene(state, load_scene_file(options.scene_path), options.scene_path);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return 1;
        }
    }
    std::optional<Script> script;
    if (!options.script_path.empty()) {
        try {
            script = Script::from_file(options.script_path);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return 1;
        }
    }

    // ---- Window with an OpenGL 3.3 core context ----
    glfwSetErrorCallback([](int, const char* text) { std::fprintf(stderr, "GLFW: %s\n", text); });
    if (!glfwInit()) {
        std::fprintf(stderr, "m3055 explore: cannot open a window (no display?); "
                             "use `m3055 render` for headless images\n");
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(options.window_width, options.window_height,
                                          "M3055 material explorer", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "m3055 explore: cannot create a window with an OpenGL 3.3 core context\n");
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(1);  // vsync: a drag redraws at most once per refresh

    // ---- The GL table, from this window's context ----
    GlApi gl;
    std::string missing;
    if (!load_gl_api(gl, [](const char* name, void*) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); },
                     nullptr, &missing)) {
        std::fprintf(stderr, "m3055 explore: the window's OpenGL lacks %s\n", missing.c_str());
        glfwDestroyWindow(window);
        glfwTerminate();
        return 1;
    }
    FrameInfo info;
    info.gl_renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    info.gl_version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
    info.window_system = glfwGetVersionString();

    // ---- Input callbacks, then Dear ImGui (its callbacks chain to ours) ----
    WindowEvents events;
    glfwSetWindowUserPointer(window, &events);
    install_event_callbacks(window);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // fixed layout: nothing to remember between runs
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    // A readable font where the system has one; ImGui's built-in one otherwise.
    if (FILE* f = std::fopen("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "rb")) {
        std::fclose(f);
        io.Fonts->AddFontFromFileTTF("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 15.0f);
    }
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330");

    int exit_status = 0;
    {
        // ---- The renderer: A, and B for the compare split ----
        std::unique_ptr<Renderer> renderer_a, renderer_b;
        try {
            renderer_a = std::make_unique<Renderer>(gl);
            renderer_b = std::make_unique<Renderer>(gl);
        } catch (const std::exception& e) {
            state.error = e.what();
        }
        std::string window_title;
        std::string pending_capture;  // write the window here after the next frame is drawn
        bool window_captured = false; // --capture-window is taken once
        {   // The free area before the first frame, for a script's `display modern`.
            const Layout start = layout_for(static_cast<float>(options.window_width),
                                            static_cast<float>(options.window_height), true);
            info.free_width = static_cast<int>(start.display.w);
            info.free_height = static_cast<int>(start.display.h);
        }

        // ---- Frame loop: sleep until something happens ----
        while (!glfwWindowShouldClose(window) && !state.quit) {
            // --exit-after-script: stop once the script and any capture are done.
            if (script && script->finished() && options.exit_after_script && pending_capture.empty() &&
                (options.capture_window.empty() || window_captured) && events.frames_owed == 0 &&
                !state.scene_changed && !state.screenshot_requested) {
                break;
            }
            const bool script_busy = script && !script->finished() && !script->idling();
            const bool work = events.frames_owed > 0 || state.scene_changed || script_busy ||
                              state.screenshot_requested || !pending_capture.empty();
            if (work) {
                glfwPollEvents();
            } else if (script && script->idling()) {
                glfwWaitEventsTimeout(std::max(0.0, script->idle_until() - glfwGetTime()));
            } else {
                glfwWaitEvents();  // idle: no CPU until the next event
            }
            if (script && !script->finished()) {
                const bool was_idle = script->idling();
                script->step(state, glfwGetTime(), info.frames, info.free_width, info.free_height);
                if (!script->idling() && !was_idle) events.frames_owed = std::max(events.frames_owed, 1);
                if (!script->capture_path.empty()) {
                    pending_capture = script->capture_path;
                    script->capture_path.clear();
                }
            }
            // Woken for nothing (an idle timeout, or an event GLFW does not report): no frame.
            if (events.frames_owed == 0 && !state.scene_changed && !state.screenshot_requested &&
                pending_capture.empty()) {
                continue;
            }
            const auto frame_start = std::chrono::steady_clock::now();

            for (const std::string& path : events.dropped) load_scene(state, path);
            events.dropped.clear();

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();

            // Shortcuts, unless the user is typing into a text field.
            for (const WindowEvents::Key& k : events.keys) {
                if (!io.WantTextInput) handle_shortcut(state, k.key, k.mods);
            }
            events.keys.clear();

            const Layout layout = layout_for(io.DisplaySize.x, io.DisplaySize.y, state.show_panels);
            const float fb_scale = io.DisplayFramebufferScale.x > 0 ? io.DisplayFramebufferScale.x : 1.0f;
            // Room for one display (two in compare, with the gap between them).
            info.free_width = static_cast<int>((layout.display.w - (state.compare ? kCompareGap : 0.0f)) * fb_scale) /
                              (state.compare ? 2 : 1);
            info.free_height = static_cast<int>(layout.display.h * fb_scale);

            // Orbit and zoom with the mouse over the display (not over a panel).
            if (!io.WantCaptureMouse) {
                if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) &&
                    (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
                    orbit_camera(state, io.MouseDelta.x, io.MouseDelta.y);
                }
                if (io.MouseWheel != 0.0f) zoom_camera(state, io.MouseWheel);
            }

            if (state.show_panels) {
                draw_side_panel(state, info, layout.side.x, layout.side.y, layout.side.w, layout.side.h);
                draw_bottom_strip(state, info, layout.bottom.x, layout.bottom.y, layout.bottom.w, layout.bottom.h);
            }

            // Render the scene only when something changed.
            if (state.scene_changed && renderer_a) {
                state.scene_changed = false;
                const auto render_start = std::chrono::steady_clock::now();
                try {
                    renderer_a->render(state.scene);
                    if (state.compare) renderer_b->render(compare_scene(state));
                    gl.Finish();
                    ++info.renders;
                } catch (const std::exception& e) {
                    state.error = e.what();
                }
                info.render_ms = milliseconds_since(render_start);
            }
            if (state.screenshot_requested && renderer_a) {
                state.screenshot_requested = false;
                take_screenshot(state, *renderer_a);
            }
            if (renderer_a) {
                std::vector<unsigned> textures = {renderer_a->display_texture()};
                if (state.compare) textures.push_back(renderer_b->display_texture());
                info.scale = draw_display(textures, renderer_a->width(), renderer_a->height(),
                                          layout.display, fb_scale);
            }
            if (!state.show_panels && !state.error.empty()) {
                ImGui::GetForegroundDrawList()->AddText(ImVec2(10, 10), IM_COL32(255, 110, 110, 255),
                                                        state.error.c_str());
            }

            const std::string title = "M3055 material explorer - " + state.scene_name;
            if (title != window_title) glfwSetWindowTitle(window, (window_title = title).c_str());

            // Draw: clear the window, then ImGui (the display is in its background list).
            ImGui::Render();
            int fb_w = 0, fb_h = 0;
            glfwGetFramebufferSize(window, &fb_w, &fb_h);
            gl.BindFramebuffer(GL_FRAMEBUFFER, 0);  // the renderer leaves its own bound
            gl.Viewport(0, 0, fb_w, fb_h);
            gl.ClearColor(0.11f, 0.11f, 0.13f, 1.0f);
            gl.Clear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

            if (!pending_capture.empty()) {
                try {
                    write_png(pending_capture, read_window(gl, fb_w, fb_h));
                } catch (const std::exception& e) {
                    state.error = e.what();
                }
                pending_capture.clear();
            }
            glfwSwapBuffers(window);
            ++info.frames;
            events.frames_owed = std::max(0, events.frames_owed - 1);
            info.frame_ms = milliseconds_since(frame_start);

            // --capture-window: once the script is done and the window has settled,
            // draw one more frame and capture it; with --exit-after-script, then stop.
            const bool script_done = !script || script->finished();
            const bool settled = events.frames_owed == 0 && !state.scene_changed;
            if (script_done && settled && !options.capture_window.empty() && !window_captured) {
                pending_capture = options.capture_window;
                window_captured = true;
                events.frames_owed = 1;
                continue;
            }
        }
        if (script && script->errors() > 0) exit_status = 1;
        if (!options.stats_path.empty()) {
            try {
                write_stats(options.stats_path, info.frames, info.renders, script ? &*script : nullptr);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "%s\n", e.what());
                exit_status = 1;
            }
        }
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        renderer_b.reset();
        renderer_a.reset();  // GL objects go while the context is still current
    }

    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return exit_status;
}

}  // namespace m3055
