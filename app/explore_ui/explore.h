// The interactive explorer: a GLFW window with a GL 3.3 core context, Dear
// ImGui panels, and the same Renderer as `m3055 render` drawing the scene.
#pragma once

#include "grading/assignment.h"
#include "image/image.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace m3055 {

struct ExploreOptions {
    std::string scene_path;      // --scene: start with this scene (default: the spec example)
    std::string assignment_path;  // --assignment: practice against it (the reference beside, the live grade)
    std::string script_path;     // --script: UI actions to run, one per frame (see script.h)
    bool exit_after_script = false;  // --exit-after-script
    std::string capture_window;  // --capture-window: PNG of the whole window when the script
                                 // ends (or after the first frames without a script)
    std::string stats_path;      // --stats: JSON with frame counts, written at exit
    bool compile_at_once = false;  // --compile-at-once: no deferral (compile, then draw: to compare)
    bool allow_brdf = false;     // --allow-brdf: with --assignment, grade .brdf materials as grade --allow-brdf
    // 0 x 0: the monitor's whole work area (1920 x 1080 on such a screen: the
    // room for the display at 2x beside the panels); 1500 x 940 without one.
    int window_width = 0;
    int window_height = 0;
};

namespace explore {
struct Explorer;
}

// One running explorer for a frame loop that someone else owns: the desktop's
// run_explorer below, or the browser's animation frames (app/web/).
class ExplorerSession {
public:
    // The starting scene (and script), the window with its GL table, ImGui and
    // the renderers. nullptr, the reason printed (one line), when any fails.
    // `prepare` sees the explorer before the window opens (the page's platform hooks).
    static std::unique_ptr<ExplorerSession> open(const ExploreOptions& options,
                                                 const std::function<void(explore::Explorer&)>& prepare = {});
    ~ExplorerSession();
    ExplorerSession(const ExplorerSession&) = delete;
    ExplorerSession& operator=(const ExplorerSession&) = delete;

    // One turn of the loop: waits for work (the desktop sleeps until an event;
    // a browser returns at once) and draws a frame when one is due. False once done.
    bool step();
    // Nothing left to do until the next input: every queued key and click fed
    // to Dear ImGui, the frames owed after them drawn, the scene's change
    // rendered (the page's m3055.settled()).
    bool idle() const;
    // After a step: 0 when the loop must go on, else how long it would sleep
    // (< 0: until the next input; seconds: until a timed job, a deferred
    // compile, a settled grade). The page stops its animation frames so long.
    double asked_sleep() const;
    int finish();  // --stats; the exit status
    explore::Explorer& explorer();
    long renders() const;  // scene renders so far (a changed scene drawn once each)
    // The CPU time of each frame that rendered a changed scene (ms; --stats' render_frame_ms).
    const std::vector<double>& render_frame_ms() const;
    // The display as `m3055 render` writes it for the scene as it is now.
    Rgb8Image render_display_now();
    // Practice mode against an assignment (--assignment; the page's ?assignment=).
    bool practise(grading::Assignment assignment);
    // Practice mode's grade of the scene as it is now (graded at once when
    // stale), the line --script's print_grade prints; "" outside practice mode.
    std::string grade_now();

private:
    ExplorerSession();
    struct Parts;
    std::unique_ptr<Parts> parts_;
};

// Runs until the window closes, Esc, or the script ends with exit_after_script.
// Returns the process exit status: 0, or 1 when no window could be opened, the
// scene could not be loaded at start, or a script command failed.
int run_explorer(const ExploreOptions& options);

}  // namespace m3055
