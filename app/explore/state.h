// Everything the explorer's UI edits, in one struct, plus the actions that the
// panels, the keyboard and --script all share (so a scripted change goes
// through the same code as a click). No ImGui and no GL in here.
#pragma once

#include "analysis/plane_curve.h"
#include "explore/history.h"
#include "explore/practice_status.h"
#include "scene/presets.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {
class BrdfViews;
class PlaneCurves;
}

namespace m3055::explore {

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
    RadialScale plot_scale = RadialScale::fixed;
    double plot_top = 1.0;    // fixed: the outer circle; log: the outer circle's value

    // A/B compare: the selected object rendered a second time with material_b.
    bool compare = false;
    Material material_b;
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

    std::string save_path = "m3055-scene.json";        // Save As's proposal
    std::string screenshot_path;  // set (script `screenshot PATH`): F12 writes exactly there once
    std::string screenshot_dir = ".";  // F12: the next free NAME-0001.png in this folder
    std::string load_path;             // the File panel's text field
    std::string load_error;            // the last failed load, shown beside the Load control
    bool show_load_error = false;      // and in a dialog (a drop, a key: wherever the user looks)

    // Undo/redo: the steps, and the name of the action whose edit the next
    // commit records ("" = named after the scene field that changed).
    History history;
    std::string pending_label;
    nlohmann::json clean_doc;  // the scene as last loaded or saved (the title's unsaved mark)
    std::string clean_file;

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
    // GLSL check (a GL compile; empty: none) and the polar plot's curves.
    std::string brdf_path;
    bool open_brdf_requested = false;
    std::string brdf_error;
    std::string brdf_error_path;  // the file brdf_error is about
    std::map<std::string, std::string> brdf_stamps;
    double brdf_next_poll = 0.0;
    std::function<std::string(const Material&)> brdf_compile_check;
    PlaneCurves* plane_curves = nullptr;
    // The "BRDF views" window (View menu): shown?, its slice's log colour, the
    // lobe's turn (radians), and the frame loop's cache of the views.
    bool show_brdf_views = false;
    bool views_log = true;
    float lobe_yaw = 0.6f, lobe_pitch = 0.5f;
    BrdfViews* brdf_views = nullptr;
    // --assignment: the live grade shown in the Assignment section (practice.h).
    PracticeStatus practice;

    // Set by every edit; the frame loop re-renders the scene once and clears it.
    bool scene_changed = true;
    void changed() { scene_changed = true; }
};

// ---- Undo/redo (history.h) ----
Snapshot snapshot(const ExplorerState& state);
void restore(ExplorerState& state, const Snapshot& snapshot);
// Forgets the history: `state` is the start (and counts as saved).
void start_history(ExplorerState& state);
// Records the edits since the last commit as one step (the frame loop calls it
// when no widget or drag is in progress). Returns whether there was one.
bool commit_edits(ExplorerState& state);
bool undo(ExplorerState& state);
bool redo(ExplorerState& state);
// Edits not saved to (or loaded from) the scene's file.
bool unsaved(const ExplorerState& state);
// "NAME *" for the title bar.
std::string title_name(const ExplorerState& state);

// Starts from `scene` (camera_home = its camera, selections reset, compare B =
// a copy of the first object's material).
void set_scene(ExplorerState& state, const Scene& scene, const std::string& name);

// Loads a JSON scene file; on failure keeps the current scene and puts the
// loader's one-line message into state.error. Returns success.
bool load_scene(ExplorerState& state, const std::string& path);

// The paper's figure presets (scenes/*.json embedded at build time), by file
// stem: "fig05" ... "fig13", "spec_example". Unknown name -> error, false.
bool load_figure(ExplorerState& state, const std::string& name);

// Writes the scene JSON (atomically); it becomes the scene's own file. Errors go to state.error.
bool save_scene(ExplorerState& state, const std::string& path);
// Ctrl+S: to the scene's own file, or (none yet) asks for one (save_as_requested).
void save_or_ask(ExplorerState& state);
// F12: the next free DIR/NAME-0001.png (NAME: the scene file's stem, or "m3055"),
// neither it nor its .json existing yet.
std::string next_screenshot_path(const ExplorerState& state);

// The selected object's material (the default scene always has one object).
Material* selected_material(ExplorerState& state);

// Every model of the model table, in its order (the model selector's list).
std::vector<const ModelSpec*> all_models();

// Switches a material's model (with_model, models/material.h: values with the
// same name and meaning are kept, the rest are the new model's defaults).
void set_model(Material& material, const ModelSpec& model);
// The same by name; std::runtime_error for a name not in the table.
void set_model(Material& material, const std::string& model_name);

// Replaces the lights with a preset.
void apply_light_preset(ExplorerState& state, LightPreset preset);

// A light's name as the scene format allows it (docs/spec.md#7-scene-files:
// 1 to 64 bytes of UTF-8 without control characters, or none): control
// characters dropped, cut to 64 bytes without splitting a character.
std::string valid_light_name(const std::string& typed);

// Lights: add (a copy of the single-key light, up to kMaxExplorerLights) / remove.
inline constexpr int kMaxExplorerLights = 8;
bool add_light(ExplorerState& state);
bool remove_light(ExplorerState& state, int index);

// Objects: add one beside the others (a sphere, or another shape as
// explore/shape_editor.h set_shape makes it; a plane is a floor under all) /
// remove one (at least one stays).
void add_object(ExplorerState& state, Shape shape = Shape::sphere);
bool remove_object(ExplorerState& state, int index);

// Display presets: the M3055 (512 x 320, 5 bits) and a "modern" display of the
// given size (the free area of the window) at 8 bits.
void set_display_m3055(ExplorerState& state);
void set_display_modern(ExplorerState& state, int width, int height);

// Camera: orbit around the target (drag, in pixels), zoom (wheel steps), reset.
void orbit_camera(ExplorerState& state, double dx_pixels, double dy_pixels);
void zoom_camera(ExplorerState& state, double wheel_steps);
void reset_camera(ExplorerState& state);

// Turns the A/B split on or off; B stays what it was (only "B = copy of A",
// copy_a_to_b, copies).
void set_compare(ExplorerState& state, bool on);
void copy_a_to_b(ExplorerState& state);

// The second scene of the A/B compare: the same scene, the selected object
// wearing material_b.
Scene compare_scene(const ExplorerState& state);

}  // namespace m3055::explore
