// The interactive explorer: a GLFW window with a GL 3.3 core context, Dear
// ImGui panels, and the same Renderer as `m3055 render` drawing the scene.
#pragma once

#include <string>

namespace m3055 {

struct ExploreOptions {
    std::string scene_path;      // --scene: start with this scene (default: the spec example)
    std::string assignment_path;  // --assignment: practice against it (the reference beside, the live grade)
    std::string script_path;     // --script: UI actions to run, one per frame (see script.h)
    bool exit_after_script = false;  // --exit-after-script
    std::string capture_window;  // --capture-window: PNG of the whole window when the script
                                 // ends (or after the first frames without a script)
    std::string stats_path;      // --stats: JSON with frame counts, written at exit
    bool compile_at_once = false;  // --compile-at-once: no deferral (the stall before issue 12, to compare)
    bool allow_brdf = false;     // --allow-brdf: with --assignment, grade .brdf materials as grade --allow-brdf
    // 0 x 0: the monitor's whole work area (1920 x 1080 on such a screen: the
    // room for the display at 2x beside the panels); 1500 x 940 without one.
    int window_width = 0;
    int window_height = 0;
};

// Runs until the window closes, Esc, or the script ends with exit_after_script.
// Returns the process exit status: 0, or 1 when no window could be opened, the
// scene could not be loaded at start, or a script command failed.
int run_explorer(const ExploreOptions& options);

}  // namespace m3055
