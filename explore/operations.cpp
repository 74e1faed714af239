// The scene's edits (operations.h). Each one changes the state and calls
// note_edit, which names the undo step and asks for a render.
#include "explore/operations.h"

#include "explore/change_label.h"
#include "explore/shapes.h"
#include "geometry/mesh.h"
#include "models/model_table.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace m3055::explore {

namespace {

void note(ExplorerState& state, const PendingEdit& edit) {
    if (!edit.empty()) note_edit(state, edit.what, edit.from, edit.to);
}

const ModelSpec& model_named(const std::string& name) {
    const ModelSpec* model = model_table().find(name);
    if (!model) throw std::runtime_error("unknown model '" + name + "'");
    return *model;
}

// A scene that differs from the current one in one part: named after what
// differs, then taken.
void take_scene(ExplorerState& state, Scene edited) {
    note(state, describe_change(state.scene, edited));
    state.scene = std::move(edited);
}

}  // namespace

void note_edit(ExplorerState& state, const std::string& what, const std::string& from, const std::string& to) {
    state.status.clear();  // the status line tells the last action: an edit replaces "redid ...", "saved ..."
    PendingEdit& pending = state.pending;
    if (pending.what != what) {
        pending.what = what;
        pending.from = from;
    }
    pending.to = to;
    state.changed();
}

// ---- Materials --------------------------------------------------------------------------

void edit_material(ExplorerState& state, const Material& edited, const std::string& action) {
    if (!selected_material(state)) return;
    Material& material = state.scene.objects[std::size_t(state.selected_object)].material;
    if (!action.empty()) {
        material = edited;
        return note_edit(state, action);
    }
    Scene scene = state.scene;
    scene.objects[std::size_t(state.selected_object)].material = edited;
    take_scene(state, std::move(scene));
}

void edit_material_b(ExplorerState& state, const Material& edited, const std::string& action) {
    if (!action.empty()) note_edit(state, "B " + action);
    else note(state, describe_change(state.material_b, edited));
    state.material_b = edited;
    state.b_edited = true;
}

void set_model(ExplorerState& state, const std::string& model_name) {
    const ModelSpec& model = model_named(model_name);
    const Material* material = selected_material(state);
    if (!material) throw std::runtime_error("no object");
    edit_material(state, with_model(*material, model));
}

void set_model_b(ExplorerState& state, const std::string& model_name) {
    edit_material_b(state, with_model(state.material_b, model_named(model_name)));
}

bool rescale_weights_to_eq14(ExplorerState& state) {
    const Material* material = selected_material(state);
    if (!material) return false;
    Material rescaled = *material;
    if (!rescale_to_eq14(rescaled)) return false;
    edit_material(state, rescaled, kEq14Action);
    return true;
}

// ---- Lights -----------------------------------------------------------------------------

void edit_light(ExplorerState& state, int index, const Light& edited) {
    if (index < 0 || index >= static_cast<int>(state.scene.lights.size())) return;
    Scene scene = state.scene;
    scene.lights[std::size_t(index)] = edited;
    take_scene(state, std::move(scene));
}

void apply_light_preset(ExplorerState& state, LightPreset preset) {
    try {
        state.scene.lights = light_preset(preset);
    } catch (const std::runtime_error& e) {  // the studio preset without colord-data
        state.error = e.what();
        return;
    }
    note_edit(state, std::string("light preset ") + preset_name(preset));  // as "figure preset fig05"
    state.selected_light = 0;
}

bool add_light(ExplorerState& state) {
    if (static_cast<int>(state.scene.lights.size()) >= kMaxExplorerLights) return false;
    state.scene.lights.push_back(light_preset(LightPreset::single_key)[0]);
    note_edit(state, "add light");
    state.selected_light = static_cast<int>(state.scene.lights.size()) - 1;
    return true;
}

bool remove_light(ExplorerState& state, int index) {
    auto& lights = state.scene.lights;
    if (index < 0 || index >= static_cast<int>(lights.size())) return false;
    lights.erase(lights.begin() + index);
    note_edit(state, "remove light " + std::to_string(index));
    state.selected_light = std::clamp(state.selected_light, 0, std::max(0, static_cast<int>(lights.size()) - 1));
    return true;
}

// ---- Objects ----------------------------------------------------------------------------

void edit_object(ExplorerState& state, int index, const Object& edited) {
    if (index < 0 || index >= static_cast<int>(state.scene.objects.size())) return;
    Scene scene = state.scene;
    scene.objects[std::size_t(index)] = edited;
    take_scene(state, std::move(scene));
}

void add_object(ExplorerState& state, Shape shape) {
    Object sphere;
    if (Material* material = selected_material(state)) sphere.material = *material;
    // Beside the right-most object (not counting floors), so the new one is
    // visible and does not overlap.
    double right = -1e300;
    for (const Object& o : state.scene.objects)
        if (o.shape != Shape::plane) right = std::max(right, o.center.x + geometry::bounding_radius(o));
    if (right > -1e300) sphere.center = {right + 0.25 + sphere.radius, 0.0, 0.0};
    if (shape == Shape::plane) {  // a floor under everything
        double bottom = 0.0, reach = 1.0;
        for (const Object& o : state.scene.objects) {
            if (o.shape == Shape::plane) continue;
            bottom = std::min(bottom, o.center.y - geometry::bounding_radius(o));
            reach = std::max(reach, std::abs(o.center.x) + geometry::bounding_radius(o));
        }
        sphere.center = {0.0, bottom, 0.0};
        sphere.shape = Shape::plane;
        sphere.size = 4.0 * reach;
    }
    set_shape(sphere, shape);
    state.scene.objects.push_back(sphere);
    note_edit(state, std::string("add ") + to_string(shape));
    state.selected_object = static_cast<int>(state.scene.objects.size()) - 1;
}

bool remove_object(ExplorerState& state, int index) {
    auto& objects = state.scene.objects;
    if (objects.size() <= 1 || index < 0 || index >= static_cast<int>(objects.size())) return false;
    objects.erase(objects.begin() + index);
    note_edit(state, "remove object " + std::to_string(index));
    selected_material(state);  // clamps the selection
    return true;
}

// ---- Display and background -------------------------------------------------------------

void edit_display(ExplorerState& state, const Display& edited) {
    Scene scene = state.scene;
    scene.display = edited;
    take_scene(state, std::move(scene));
}

void set_background(ExplorerState& state, const dvec3& colour) {
    Scene scene = state.scene;
    scene.background = colour;
    take_scene(state, std::move(scene));
}

void set_display_m3055(ExplorerState& state) {
    state.scene.display.width = 512;
    state.scene.display.height = 320;
    state.scene.display.bits = 5;
    note_edit(state, "display M3055");
}

void set_display_modern(ExplorerState& state, int width, int height) {
    state.scene.display.width = std::clamp(width, 1, kMaxDisplaySize);
    state.scene.display.height = std::clamp(height, 1, kMaxDisplaySize);
    state.scene.display.bits = 8;
    state.scene.display.dither = false;
    note_edit(state, "display modern");
}

// ---- Camera (the moves: operations_camera.cpp) ------------------------------------------

void edit_camera(ExplorerState& state, const Camera& edited) {
    Scene scene = state.scene;
    scene.camera = edited;
    take_scene(state, std::move(scene));
}

// ---- A/B compare ------------------------------------------------------------------------

void set_compare(ExplorerState& state, bool on) {
    // A B nobody has set yet starts as A (a metal against a metal, not an unrelated highlight).
    const Material* a = selected_material(state);
    if (on && !state.compare && !state.b_edited && a && !(state.material_b == *a)) {
        state.material_b = *a;
        note_edit(state, "B = copy of A (split on)");
    }
    state.compare = on;
    state.changed();  // B is rendered (or not): no edit of the scene, no undo step
}

void copy_a_to_b(ExplorerState& state) {
    if (const Material* a = selected_material(state)) state.material_b = *a;
    state.b_edited = true;  // the user's choice of B: the split keeps it
    note_edit(state, "B = copy of A");
}

bool compare_fresnel(ExplorerState& state) {
    const Material* selected = selected_material(state);
    if (!selected || selected->model().family != Family::metal || !selected->has("conductor")) return false;
    Material a = *selected;
    a.set_colour_spectrum(nullptr);  // a conductor is the colour now
    if (a.choice("conductor") == 0) a.set_choice("conductor", "gold");
    a.set_choice("fresnel", "normal");
    Material b = a;
    b.set_choice("fresnel", "full");
    // B and A in one pending edit: one undo step, named by the preset.
    state.material_b = b;
    state.b_edited = true;
    edit_material(state, a, kFresnelPresetAction);
    set_compare(state, true);
    return true;
}

// ---- Any scene value --------------------------------------------------------------------

void set_scene_value(ExplorerState& state, const std::string& path, const std::string& value) {
    nlohmann::json doc = scene_to_json(state.scene, PathWriting::absolute());
    apply_overrides(doc, {{path, value}}, "script");
    take_scene(state, scene_from_json(doc, "script", LoadContext::trusted()));
}

}  // namespace m3055::explore
