// Everything the explorer's UI shows and edits, in one struct. The scene, B
// and the scene's file change only through explore/operations.h and
// explore/files.h (so what changed and its undo step are decided in one
// place); view settings (selections, the plot's scale, the panes) are plain
// fields. No ImGui and no GL in here.
#pragma once

#include "analysis/plane_curve.h"
#include "explore/history.h"
#include "explore/pending_edit.h"
#include "explore/practice_status.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace m3055::explore {

// The title of the plots' window (polar plot, profile, statistics).
inline constexpr const char* kPlotsTitle = "Plane of incidence";

struct ExplorerState {
    Scene scene;             // what is rendered and saved
    Camera camera_home;      // R / "Reset" goes back to this (the loaded scene's camera)
    std::string scene_name = "default";  // shown in the title bar
    std::string scene_file;  // the file the scene came from or was saved to ("" for presets): Ctrl+S

    int selected_object = 0;  // whose material the Material panel edits
    int selected_light = 0;   // the light last edited in the Lights panel
    int plotted_light = 0;    // the polar plot's light: picked in the plot's own header only

    // The polar plot's radial scale: chosen by the user and kept (model_max is
    // recomputed only when the plotted material's model or the light changes).
    RadialScale plot_scale = RadialScale::lobe;  // issue 20 item 7: the lobe fills the plot
    double plot_top = 1.0;    // fixed: the outer circle; log: the outer circle's value

    // A/B compare: the selected object rendered a second time with material_b.
    bool compare = false;
    Material material_b;
    bool b_edited = false;      // B set by the user (an edit, "B = copy of A") since the scene: the split keeps it
    bool compare_diff = false;  // a third pane: |A - B| per channel, scaled
    int diff_scale = 0;         // its whole scale, 1 ... 255; 0: automatic (grading/ab_compare.h)

    // The scanline profile's row: the last display row hovered on A (-1: none yet).
    int profile_row = -1;

    bool show_panels = true;  // F1
    bool screenshot_requested = false;  // button / F12: the frame loop owns the renderer
    bool quit = false;        // the frame loop ends
    bool quit_requested = false;  // Esc / window close: asks first when there are unsaved edits
    bool save_as_requested = false;  // Ctrl+S without a file of its own: the Save As dialog
    bool quit_after_save = false;    // the unsaved-edits dialog's Save went to Save As

    std::string save_path = "m3055-scene.json";        // Save As's field (request_save_as proposes it)
    std::string save_name = "m3055-scene.json";  // Save As's proposal for a scene without a file (practice: submission.json)
    std::string save_dir;  // the folder of the last scene file loaded or saved: Save As proposes it
    std::string screenshot_path;  // set (script `screenshot PATH`): F12 writes exactly there once
    std::string screenshot_dir = ".";  // F12: the next free NAME-0001.png in this folder
    std::string load_path;             // the File panel's text field
    std::string load_error;            // the last failed load, shown beside the Load control
    bool show_load_error = false;      // and in a dialog (a drop, a key: wherever the user looks)

    // Undo/redo: the steps, and what the edits since the last step did (the
    // next step's label, set by explore/operations.cpp note_edit).
    History history;
    PendingEdit pending;
    // What each file held when last loaded or saved here (key: the path), and
    // for a scene without a file what it started as (key: "\n" + its name, e.g.
    // a figure preset): "unsaved" is whether the scene differs from that
    // (explore/undo.h), so undoing back to the saved scene is clean again.
    std::map<std::string, nlohmann::json> saved_docs;
    // The Save As dialog's overwrite check: the existing file the user was
    // warned about (a second Save writes it).
    std::string overwrite_warned;

    std::string status;  // last message (saved ..., loaded ...)
    std::string error;   // last error, shown in red until dismissed

    // --script's `probe X Y` / `click X Y` (display pixels): the frame loop
    // answers them once the scene is rendered.
    std::vector<std::pair<int, int>> probe_requests, pick_requests;
    // --script's `print_compare`, `print_profile` and `save_difference PATH`:
    // answered the same way, each a line ("compare", "profile", "save_difference PATH").
    std::vector<std::string> readout_requests;
    // --script's `section NAME open|closed`: the side panel's headers, next frame.
    std::map<std::string, bool> section_requests;

    // .brdf files (explore/brdf_files.h): File > Open BRDF's path field, the
    // last parse or GLSL error (shown in the Material section), each watched
    // file's "mtime size" and the next poll time. The frame loop sets the
    // GLSL check (a GL compile; empty: none).
    std::string brdf_path;
    bool open_brdf_requested = false;
    std::string brdf_error;
    std::string brdf_error_path;  // the file brdf_error is about
    std::map<std::string, std::string> brdf_stamps;
    double brdf_next_poll = 0.0;
    // Changed .brdf files found by the last poll, reloaded by the next one
    // (after a frame has shown "reloading FILE...": busy_line in explore/busy.h).
    std::vector<std::string> brdf_reload_pending;
    std::string busy;  // this frame's busy_line (explore/busy.h), beside the menu
    std::function<std::string(const Material&)> brdf_compile_check;
    // The "BRDF views" window (View menu): shown?, its slice's log colour and
    // the lobe's turn (radians).
    bool show_brdf_views = false;
    bool views_log = true;
    // The plots under the side panel (explore/layout.h, plots_under_side)
    // folded to their title bar, the side panel taking the column: the
    // title bar's arrow, or --script's `section Plane of incidence closed`.
    bool plots_folded = false;
    float lobe_yaw = 0.6f, lobe_pitch = 0.5f;
    // --assignment: the live grade shown in the Assignment section (practice.h).
    PracticeStatus practice;

    // Where the explorer runs. In a browser page (app/web/) nothing quits the
    // page, a file the explorer writes (a saved scene, a screenshot) is also
    // offered as a download, and File > Open is the browser's file chooser:
    // the page sets these; the desktop window leaves them as they are.
    struct Platform {
        bool can_quit = true;
        std::function<void(const std::string& path)> file_written;
        std::function<void()> pick_file;
        // Where saved files name a .brdf by a relative path (PathWriting::relative_to):
        // the page's work folder, whose files leave as downloads side by side. "" (the
        // desktop): absolute paths.
        std::string brdf_paths_relative_to;
    } platform;

    // Set by every edit (operations.h); the frame loop re-renders the scene once and clears it.
    bool scene_changed = true;
    void changed() { scene_changed = true; }
};

// The selected object's material (nullptr with no object); clamps the selection.
Material* selected_material(ExplorerState& state);

// Every model of the model table, in its order (the model selector's list).
std::vector<const ModelSpec*> all_models();

// A light's name as the scene format allows it (docs/spec.md#7-scene-files:
// 1 to 64 bytes of UTF-8 without control characters, or none): control
// characters dropped, cut to 64 bytes without splitting a character.
std::string valid_light_name(const std::string& typed);

// The second scene of the A/B compare: the same scene, the selected object
// wearing material_b.
Scene compare_scene(const ExplorerState& state);

}  // namespace m3055::explore
