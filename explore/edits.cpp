#include "explore/edits.h"

#include "explore/edit_label.h"
#include "explore/overloaded.h"

#include <type_traits>
#include <utility>

namespace m3055::explore {

namespace {

// What an edit changes: nothing, when its value before is its value after.
FieldChange change_of(const EditValue& value) {
    return std::visit(
        Overloaded{
            [](const MaterialEdit& e) { return material_change(e.before, e.after); },
            [](const LightEdit& e) { return light_change(e.before, e.after, e.index); },
            [](const LightListEdit& e) {
                if (e.before.size() != e.after.size()) return FieldChange{"lights", "", ""};
                for (std::size_t i = 0; i < e.after.size(); ++i) {
                    FieldChange change = light_change(e.before[i], e.after[i], int(i));
                    if (!change.empty()) return change;
                }
                return FieldChange{};
            },
            [](const ObjectEdit& e) { return object_change(e.before, e.after, e.index); },
            [](const ObjectInsert& e) { return FieldChange{"add " + std::string(to_string(e.object.shape)), "", ""}; },
            [](const ObjectErase& e) { return FieldChange{"remove object " + std::to_string(e.index), "", ""}; },
            [](const CameraEdit& e) { return camera_change(e.before, e.after); },
            [](const DisplayEdit& e) { return display_change(e.before, e.after); },
            [](const BackgroundEdit& e) { return FieldChange{e.before != e.after ? "background" : "", "", ""}; },
            [](const DocumentEdit& e) { return FieldChange{"load " + e.after->name, "", ""}; },
        },
        value);
}

// Two edits of the same part: the later one's value after replaces the earlier one's.
bool merge_into(EditValue& earlier, const EditValue& later) {
    if (earlier.index() != later.index()) return false;
    return std::visit(
        [&later](auto& e) -> bool {
            using T = std::decay_t<decltype(e)>;
            const T& next = std::get<T>(later);
            if constexpr (std::is_same_v<T, MaterialEdit>) {
                if (e.object != next.object || e.group != next.group) return false;
                e.after = next.after;
            } else if constexpr (std::is_same_v<T, LightEdit> || std::is_same_v<T, ObjectEdit>) {
                if (e.index != next.index) return false;
                e.after = next.after;
            } else if constexpr (std::is_same_v<T, ObjectInsert> || std::is_same_v<T, ObjectErase>) {
                return false;  // each one an edit of its own
            } else {
                e.after = next.after;
            }
            return true;
        },
        earlier);
}

void set_material(Document& doc, const MaterialEdit& edit, const Material& material) {
    if (edit.object == kMaterialB) {
        doc.material_b = material;
        return;
    }
    Object& object = doc.scene.objects[std::size_t(edit.object)];
    if (edit.group < 0) {
        object.material = material;
        return;
    }
    GroupMaterial& group = object.groups[std::size_t(edit.group)];
    group.material = material;
    group.overridden = true;  // saved as the scene's "materials" entry of its name
    if (edit.group == 0) object.material = material;  // a mesh's `material` is its first group's
}

void set_content(Document& doc, const DocumentContent& content) {
    doc.scene = content.scene;
    doc.material_b = content.material_b;
    doc.b_edited = content.b_edited;
    doc.camera_home = content.camera_home;
    doc.name = content.name;
    doc.file = content.file;
}

// A load, an object added or removed always changes the document; any other
// edit only when a field differs between its values before and after.
bool changes_something(const Edit& edit) {
    const EditValue& v = edit.value;
    if (std::holds_alternative<DocumentEdit>(v) || std::holds_alternative<ObjectInsert>(v) ||
        std::holds_alternative<ObjectErase>(v))
        return true;
    return !change_of(v).empty();
}

}  // namespace

std::shared_ptr<const DocumentContent> content_of(const Document& doc) {
    return std::make_shared<const DocumentContent>(
        DocumentContent{doc.scene, doc.material_b, doc.b_edited, doc.camera_home, doc.name, doc.file});
}

void apply_edit(Document& doc, const Edit& edit, bool forward) {
    std::visit(Overloaded{
                   [&](const MaterialEdit& e) { set_material(doc, e, forward ? e.after : e.before); },
                   [&](const LightEdit& e) { doc.scene.lights[std::size_t(e.index)] = forward ? e.after : e.before; },
                   [&](const LightListEdit& e) { doc.scene.lights = forward ? e.after : e.before; },
                   [&](const ObjectEdit& e) { doc.scene.objects[std::size_t(e.index)] = forward ? e.after : e.before; },
                   [&](const ObjectInsert& e) {
                       auto& objects = doc.scene.objects;
                       if (forward) objects.insert(objects.begin() + e.index, e.object);
                       else objects.erase(objects.begin() + e.index);
                   },
                   [&](const ObjectErase& e) {
                       auto& objects = doc.scene.objects;
                       if (forward) objects.erase(objects.begin() + e.index);
                       else objects.insert(objects.begin() + e.index, e.object);
                   },
                   [&](const CameraEdit& e) { doc.scene.camera = forward ? e.after : e.before; },
                   [&](const DisplayEdit& e) { doc.scene.display = forward ? e.after : e.before; },
                   [&](const BackgroundEdit& e) { doc.scene.background = forward ? e.after : e.before; },
                   [&](const DocumentEdit& e) { set_content(doc, forward ? *e.after : *e.before); },
               },
               edit.value);
}

std::string edit_label(const Edit& edit, const Scene& scene) {
    if (!edit.action.empty()) return edit.action;
    FieldChange change = change_of(edit.value);
    if (const auto* material = std::get_if<MaterialEdit>(&edit.value)) {
        if (material->object == kMaterialB) {
            change.what = "B " + change.what;
        } else if (change.what == "model") {
            if (scene.objects.size() > 1) change.to += " (object " + std::to_string(material->object) + ")";
        } else if (material->group >= 0) {
            const Object& object = scene.objects[std::size_t(material->object)];
            change.what = "objects[" + std::to_string(material->object) + "].materials." +
                          object.groups[std::size_t(material->group)].name + "." + change.what;
        } else {
            change.what = "objects[" + std::to_string(material->object) + "].material." + change.what;
        }
    }
    return change.label();
}

bool record_edit(Document& doc, Edit edit) {
    if (!changes_something(edit)) return false;
    apply_edit(doc, edit, true);
    Step& step = doc.history.pending();
    if (step.edits.empty()) step.revision_before = doc.revision;
    Edit& last = step.edits.empty() ? edit : step.edits.back();
    if (step.edits.empty() || !merge_into(last.value, edit.value)) step.edits.push_back(std::move(edit));
    else if (!edit.action.empty()) last.action = edit.action;
    step.label = edit_label(step.edits.back(), doc.scene);
    doc.revision = ++doc.last_revision;
    return true;
}

bool commit_edits(Document& doc) {
    Step& step = doc.history.pending();
    if (step.edits.empty()) return false;
    // A drag that came back to where it started is no step (and nothing to save).
    std::vector<Edit> kept;
    for (Edit& edit : step.edits)
        if (changes_something(edit)) kept.push_back(std::move(edit));
    step.edits = std::move(kept);
    if (step.edits.empty()) {
        doc.revision = step.revision_before;
        step = Step{};
        return false;
    }
    step.revision_after = doc.revision;
    return doc.history.commit();
}

bool undo(Document& doc) {
    commit_edits(doc);  // an edit still in progress is a step of its own
    if (!doc.history.can_undo()) return false;
    const Step& step = doc.history.undo();
    for (auto edit = step.edits.rbegin(); edit != step.edits.rend(); ++edit) apply_edit(doc, *edit, false);
    doc.revision = step.revision_before;
    return true;
}

bool redo(Document& doc) {
    commit_edits(doc);
    if (!doc.history.can_redo()) return false;
    const Step& step = doc.history.redo();
    for (const Edit& edit : step.edits) apply_edit(doc, edit, true);
    doc.revision = step.revision_after;
    return true;
}

}  // namespace m3055::explore
