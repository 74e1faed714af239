// The edits of the explorer's scene and material B: every panel, key and
// --script command changes them through these functions, so what changed,
// the undo step it belongs to and its label are decided here, in one place
// (note_edit), not by field assignments followed by a "changed" flag.
//
// A panel edits a copy (a Material, a Light, ...) with its widgets and hands
// it to edit_*; the label names what differs ("objects[0].material.m 10 ->
// 40", "model metal -> half_lambert", "light key intensity 1 -> 0.5").
// Actions with a name of their own say it ("light preset three_point_warm", "add sphere",
// "B = copy of A"). Each call asks for one render (state.scene_changed); the
// frame loop makes the undo step when no widget or drag is in progress
// (explore/undo.h commit_edits), so a slider drag is one step.
#pragma once

#include "explore/state.h"
#include "scene/presets.h"

#include <string>

namespace m3055::explore {

// Names the current undo step: `what` with the values before and after
// (both "" when the edit is not one value). The same `what` again (a drag)
// keeps the step's first `from`; another `what` names the step anew. Asks
// for a render.
void note_edit(ExplorerState& state, const std::string& what, const std::string& from = "",
               const std::string& to = "");

// ---- Materials --------------------------------------------------------------------------
// The selected object's material becomes `edited` (a model switch is named
// "model X -> Y", one value "objects[I].material.NAME FROM -> TO"; `action`,
// when given, names it instead: a button's "rescale weights to eq. 14").
void edit_material(ExplorerState& state, const Material& edited, const std::string& action = "");
// The A/B compare's material B (labels start with "B ").
void edit_material_b(ExplorerState& state, const Material& edited, const std::string& action = "");
// The selected object's / B's model by name (values with the same name and
// meaning are kept: with_model); std::runtime_error for a name not in the table.
void set_model(ExplorerState& state, const std::string& model_name);
void set_model_b(ExplorerState& state, const std::string& model_name);
// The metal's "Rescale weights to eq. 14" on the selected object's material
// (kEq14Action); false (nothing changed) when not possible.
inline constexpr const char* kEq14Action = "rescale weights to eq. 14";
bool rescale_weights_to_eq14(ExplorerState& state);

// ---- Lights -----------------------------------------------------------------------------
void edit_light(ExplorerState& state, int index, const Light& edited);
// Replaces the lights with a preset.
void apply_light_preset(ExplorerState& state, LightPreset preset);
// Add (a copy of the single-key light, up to kMaxExplorerLights) / remove.
inline constexpr int kMaxExplorerLights = 8;
bool add_light(ExplorerState& state);
bool remove_light(ExplorerState& state, int index);

// ---- Objects ----------------------------------------------------------------------------
void edit_object(ExplorerState& state, int index, const Object& edited);
// Add one beside the others (a sphere, or another shape as explore/shapes.h
// set_shape makes it; a plane is a floor under all) / remove one (at least one stays).
void add_object(ExplorerState& state, Shape shape = Shape::sphere);
bool remove_object(ExplorerState& state, int index);

// ---- Display and background -------------------------------------------------------------
void edit_display(ExplorerState& state, const Display& edited);
void set_background(ExplorerState& state, const dvec3& colour);
// The M3055 (512 x 320, 5 bits) and a "modern" display of the given size
// (the free area of the window) at 8 bits.
void set_display_m3055(ExplorerState& state);
void set_display_modern(ExplorerState& state, int width, int height);

// ---- Camera -----------------------------------------------------------------------------
void edit_camera(ExplorerState& state, const Camera& edited);
// Orbit around the target (drag, in pixels), zoom (wheel steps), reset.
void orbit_camera(ExplorerState& state, double dx_pixels, double dy_pixels);
void zoom_camera(ExplorerState& state, double wheel_steps);
void reset_camera(ExplorerState& state);
// Shift+drag on the display: the selected object's centre moves in the plane
// through it facing the camera, so it follows the mouse: dx, dy window units
// dragged (y down), `shown_height` the display's height on screen in the same
// units (one undo step per drag: the edit is committed when the button is up).
void move_object_in_view(ExplorerState& state, double dx, double dy, double shown_height);

// ---- A/B compare ------------------------------------------------------------------------
// Turns the split on or off; B stays what it was once the user has set it
// (edit_material_b, copy_a_to_b); a B not set since the scene was loaded
// becomes a copy of A when the split is switched on (one undo step
// "B = copy of A (split on)" when that changes B).
void set_compare(ExplorerState& state, bool on);
void copy_a_to_b(ExplorerState& state);
// The A/B preset "paper's F(lambda, 0) vs full eq. 19" (docs/spec.md#72-measured-metals):
// the selected paper metal as a measured metal (its conductor, gold when it
// names none) with "fresnel": "normal" as A and "full" as B, and the split on;
// one undo step (kFresnelPresetAction). False, and nothing changed, when the
// selected object is not one of the paper's metals.
inline constexpr const char* kFresnelPresetAction = "A/B preset: F(lambda, 0) vs full eq. 19";
bool compare_fresnel(ExplorerState& state);

// ---- Any scene value (--script's `set PATH VALUE`, as m3055's --set) --------------------
// Validated like a load; std::runtime_error (SceneError) with the loader's message.
void set_scene_value(ExplorerState& state, const std::string& path, const std::string& value);

}  // namespace m3055::explore
