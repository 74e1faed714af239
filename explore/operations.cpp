// The document's commands (operations.h). Each builds the typed edit of the
// part it changes and records it (edits.h), which names the undo step.
#include "explore/operations.h"

#include "explore/edits.h"
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

bool valid_index(int index, std::size_t size) { return index >= 0 && static_cast<std::size_t>(index) < size; }

void clamp_light_selection(Explorer& e) {
    const int lights = static_cast<int>(e.doc.scene.lights.size());
    e.view.selected_light = std::clamp(e.view.selected_light, 0, std::max(0, lights - 1));
}

// The typed edits that take `before` to `after`, part by part (a script's
// `set PATH VALUE` names the field it set); a change of the object count or
// of the ambient colour replaces the whole document.
std::vector<EditValue> edits_between(const Explorer& e, const Scene& before, const Scene& after) {
    std::vector<EditValue> edits;
    if (before.objects.size() != after.objects.size() || before.ambient != after.ambient) {
        auto content = std::make_shared<DocumentContent>(*content_of(e.doc));
        content->scene = after;
        return {DocumentEdit{content_of(e.doc), std::move(content)}};
    }
    edits.push_back(DisplayEdit{before.display, after.display});
    edits.push_back(BackgroundEdit{before.background, after.background});
    edits.push_back(CameraEdit{before.camera, after.camera});
    if (before.lights.size() == after.lights.size()) {
        for (std::size_t i = 0; i < after.lights.size(); ++i)
            edits.push_back(LightEdit{int(i), before.lights[i], after.lights[i]});
    } else {
        edits.push_back(LightListEdit{before.lights, after.lights});
    }
    for (std::size_t i = 0; i < after.objects.size(); ++i)
        edits.push_back(ObjectEdit{int(i), before.objects[i], after.objects[i]});
    return edits;
}

}  // namespace

bool edit_document(Explorer& e, Edit edit) {
    if (!record_edit(e.doc, std::move(edit))) return false;
    e.session.messages.status.clear();  // the status line tells the last action: an edit replaces "redid ..."
    e.session.render_needed = true;
    return true;
}

bool commit_edits(Explorer& e) { return explore::commit_edits(e.doc); }

// ---- Materials --------------------------------------------------------------------------

bool apply(Explorer& e, const command::SetMaterial& c) {
    if (c.object == kMaterialB) {
        e.doc.b_edited = true;  // the user's choice of B: the split keeps it
        return edit_document(e, {MaterialEdit{kMaterialB, e.doc.material_b, c.value},
                                 c.action.empty() ? "" : "B " + c.action});
    }
    if (!valid_index(c.object, e.doc.scene.objects.size())) return false;
    const Object& object = e.doc.scene.objects[std::size_t(c.object)];
    if (c.group >= 0) {
        if (!valid_index(c.group, object.groups.size())) return false;
        return edit_document(e, {MaterialEdit{c.object, object.groups[std::size_t(c.group)].material, c.value, c.group},
                                 c.action});
    }
    return edit_document(e, {MaterialEdit{c.object, object.material, c.value}, c.action});
}

Material with_model_named(const Material& material, const std::string& name) {
    const ModelSpec* model = model_table().find(name);
    if (!model) throw std::runtime_error("unknown model '" + name + "'");
    return with_model(material, *model);
}

bool eq14_rescaled(const Material& material, Material* rescaled) {
    *rescaled = material;
    return rescale_to_eq14(*rescaled);
}

// ---- Lights -----------------------------------------------------------------------------

bool apply(Explorer& e, const command::SetLight& c) {
    if (!valid_index(c.index, e.doc.scene.lights.size())) return false;
    edit_document(e, {LightEdit{c.index, e.doc.scene.lights[std::size_t(c.index)], c.value}, ""});
    return true;
}

bool apply(Explorer& e, const command::ApplyLightPreset& c) {
    std::vector<Light> lights;
    try {
        lights = light_preset(c.preset);
    } catch (const std::runtime_error& error) {  // the studio preset without colord-data
        e.session.messages.error = error.what();
        return false;
    }
    edit_document(e, {LightListEdit{e.doc.scene.lights, std::move(lights)},
                      std::string("light preset ") + preset_name(c.preset)});  // as "figure preset fig05"
    e.view.selected_light = 0;
    return true;
}

bool apply(Explorer& e, const command::AddLight&) {
    std::vector<Light> lights = e.doc.scene.lights;
    if (static_cast<int>(lights.size()) >= kMaxExplorerLights) return false;
    lights.push_back(light_preset(LightPreset::single_key)[0]);
    edit_document(e, {LightListEdit{e.doc.scene.lights, std::move(lights)}, "add light"});
    e.view.selected_light = static_cast<int>(e.doc.scene.lights.size()) - 1;
    return true;
}

bool apply(Explorer& e, const command::RemoveLight& c) {
    std::vector<Light> lights = e.doc.scene.lights;
    if (!valid_index(c.index, lights.size())) return false;
    lights.erase(lights.begin() + c.index);
    edit_document(e, {LightListEdit{e.doc.scene.lights, std::move(lights)}, "remove light " + std::to_string(c.index)});
    clamp_light_selection(e);
    return true;
}

// ---- Objects ----------------------------------------------------------------------------

bool apply(Explorer& e, const command::SetObject& c) {
    if (!valid_index(c.index, e.doc.scene.objects.size())) return false;
    edit_document(e, {ObjectEdit{c.index, e.doc.scene.objects[std::size_t(c.index)], c.value}, ""});
    return true;
}

bool apply(Explorer& e, const command::AddObject& c) {
    const std::vector<Object>& objects = e.doc.scene.objects;
    Object added;
    if (const Material* material = selected_material(e)) added.material = *material;
    // Beside the right-most object (not counting floors), so the new one is
    // visible and does not overlap.
    double right = -1e300;
    for (const Object& o : objects)
        if (o.shape != Shape::plane) right = std::max(right, o.center.x + geometry::bounding_radius(o));
    if (right > -1e300) added.center = {right + 0.25 + added.radius, 0.0, 0.0};
    if (c.shape == Shape::plane) {  // a floor under everything
        double bottom = 0.0, reach = 1.0;
        for (const Object& o : objects) {
            if (o.shape == Shape::plane) continue;
            bottom = std::min(bottom, o.center.y - geometry::bounding_radius(o));
            reach = std::max(reach, std::abs(o.center.x) + geometry::bounding_radius(o));
        }
        added.center = {0.0, bottom, 0.0};
        added.shape = Shape::plane;
        added.size = 4.0 * reach;
    }
    set_shape(added, c.shape);
    const int index = static_cast<int>(objects.size());
    edit_document(e, {ObjectInsert{index, std::move(added)}, std::string("add ") + to_string(c.shape)});
    e.view.selected_object = index;
    return true;
}

bool apply(Explorer& e, const command::RemoveObject& c) {
    const auto& objects = e.doc.scene.objects;
    if (objects.size() <= 1 || !valid_index(c.index, objects.size())) return false;
    edit_document(e, {ObjectErase{c.index, objects[std::size_t(c.index)]}, "remove object " + std::to_string(c.index)});
    selected_material(e);  // clamps the selection
    return true;
}

// ---- Display and background -------------------------------------------------------------

bool apply(Explorer& e, const command::SetDisplay& c) {
    edit_document(e, {DisplayEdit{e.doc.scene.display, c.value}, c.action});
    return true;
}

bool apply(Explorer& e, const command::SetBackground& c) {
    edit_document(e, {BackgroundEdit{e.doc.scene.background, c.value}, ""});
    return true;
}

Display m3055_display(const Display& from) {
    Display d = from;
    d.width = 512;
    d.height = 320;
    d.bits = 5;
    d.view_transform = ViewTransform::none;  // the paper's display: levels of the linear value
    return d;
}

Display modern_display(const Display& from, int width, int height) {
    Display d = from;
    d.width = std::clamp(width, 1, kMaxDisplaySize);
    d.height = std::clamp(height, 1, kMaxDisplaySize);
    d.bits = 8;
    d.dither = false;
    return d;
}

// ---- A/B compare ------------------------------------------------------------------------

bool apply(Explorer& e, const command::SetCompare& c) {
    // A B nobody has set yet starts as A (a metal against a metal, not an unrelated highlight).
    const Material* a = selected_material(e);
    if (c.on && !e.view.compare && !e.doc.b_edited && a && !(e.doc.material_b == *a))
        edit_document(e, {MaterialEdit{kMaterialB, e.doc.material_b, *a}, "B = copy of A (split on)"});
    e.view.compare = c.on;
    e.session.render_needed = true;  // B is rendered (or not): no edit of the document
    return true;
}

bool apply(Explorer& e, const command::CopyAToB&) {
    const Material* a = selected_material(e);
    e.doc.b_edited = true;
    if (a) edit_document(e, {MaterialEdit{kMaterialB, e.doc.material_b, *a}, "B = copy of A"});
    return a != nullptr;
}

bool apply(Explorer& e, const command::CompareFresnel&) {
    const Material* selected = selected_material(e);
    if (!selected || selected->model().family != Family::metal || !selected->has("conductor")) return false;
    Material a = *selected;
    a.set_colour_spectrum(nullptr);  // a conductor is the colour now
    if (a.choice("conductor") == 0) a.set_choice("conductor", "gold");
    a.set_choice("fresnel", "normal");
    Material b = a;
    b.set_choice("fresnel", "full");
    // B and A in one step, named by the preset.
    e.doc.b_edited = true;
    edit_document(e, {MaterialEdit{kMaterialB, e.doc.material_b, b}, kFresnelPresetAction});
    edit_document(e, {MaterialEdit{e.view.selected_object, *selected, a}, kFresnelPresetAction});
    e.view.compare = true;
    e.session.render_needed = true;
    return true;
}

// ---- Any scene value --------------------------------------------------------------------

bool apply(Explorer& e, const command::SetSceneValue& c) {
    nlohmann::json doc = scene_to_json(e.doc.scene, PathWriting::absolute());
    apply_overrides(doc, {{c.path, c.value}}, "script");
    const Scene after = scene_from_json(doc, "script", LoadContext::trusted());
    for (EditValue& edit : edits_between(e, e.doc.scene, after)) edit_document(e, {std::move(edit), ""});
    selected_material(e);
    clamp_light_selection(e);
    return true;
}

// ---- Undo and redo ----------------------------------------------------------------------

namespace {
// After the document moved back or forward: selections within it, one render.
void after_history_move(Explorer& e) {
    selected_material(e);
    clamp_light_selection(e);
    e.session.render_needed = true;
}
}  // namespace

bool apply(Explorer& e, const command::Undo&) {
    explore::commit_edits(e.doc);
    if (!e.doc.history.can_undo()) return false;
    const std::string label = e.doc.history.undo_label();
    undo(e.doc);
    e.session.messages.status = "undid " + label;
    after_history_move(e);
    return true;
}

bool apply(Explorer& e, const command::Redo&) {
    explore::commit_edits(e.doc);
    if (!e.doc.history.can_redo()) return false;
    const std::string label = e.doc.history.redo_label();
    redo(e.doc);
    e.session.messages.status = "redid " + label;
    // An object added again is selected again, as when it was added.
    for (const Edit& edit : e.doc.history.undo_step().edits)
        if (const auto* insert = std::get_if<ObjectInsert>(&edit.value)) e.view.selected_object = insert->index;
    after_history_move(e);
    return true;
}

}  // namespace m3055::explore
