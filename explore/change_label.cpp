#include "explore/change_label.h"

#include "explore/history.h"
#include "io/message_text.h"
#include "scene/json_material.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>

namespace m3055::explore {

namespace {

// "objects[0].material.m" -> the JSON pointer "/objects/0/material/m".
nlohmann::json::json_pointer pointer_of(const std::string& path) {
    std::string text = "/";
    for (char c : path) {
        if (c == '.' || c == '[') text += '/';
        else if (c != ']') text += c;
    }
    return nlohmann::json::json_pointer(text);
}

// A value worth showing in a label: one number, text or flag ("" otherwise,
// e.g. a colour, a list of lobes, or a key one side lacks).
std::string value_text(const nlohmann::json& doc, const std::string& path) {
    const auto pointer = pointer_of(path);
    if (!doc.contains(pointer)) return "";
    const nlohmann::json& v = doc.at(pointer);
    if (v.is_number()) return text::format_number(v.get<double>());
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
    return "";
}

PendingEdit value_change(const nlohmann::json& before, const nlohmann::json& after, const std::string& path) {
    PendingEdit edit{path, value_text(before, path), value_text(after, path)};
    if (edit.from.empty() || edit.to.empty()) edit.from.clear(), edit.to.clear();
    return edit;
}

// "lights[2].intensity" -> "light key intensity" (or "light 2 intensity" for a light without a name).
void name_light(PendingEdit& edit, const Scene& after) {
    if (edit.what.rfind("lights[", 0) != 0) return;
    const auto close = edit.what.find(']');
    if (close == std::string::npos || close + 1 >= edit.what.size() || edit.what[close + 1] != '.') return;
    const std::size_t index = std::stoul(edit.what.substr(7, close - 7));
    if (index >= after.lights.size()) return;
    const std::string& name = after.lights[index].name;
    edit.what = "light " + (name.empty() ? std::to_string(index) : name) + " " + edit.what.substr(close + 2);
}

}  // namespace

PendingEdit describe_change(const Scene& before, const Scene& after) {
    // A model switch changes many values at once: name the switch, not the first of them.
    if (before.objects.size() == after.objects.size()) {
        for (std::size_t i = 0; i < after.objects.size(); ++i) {
            const Material &a = before.objects[i].material, &b = after.objects[i].material;
            if (&a.model() == &b.model()) continue;
            PendingEdit edit{"model", a.shown_name(), b.shown_name()};
            if (after.objects.size() > 1) edit.to += " (object " + std::to_string(i) + ")";
            return edit;
        }
    }
    const nlohmann::json a = scene_to_json(before, PathWriting::absolute()),
                         b = scene_to_json(after, PathWriting::absolute());
    const std::string path = first_difference(a, b);
    if (path.empty()) return {};
    PendingEdit edit = value_change(a, b, path);
    name_light(edit, after);
    return edit;
}

PendingEdit describe_change(const Material& before, const Material& after) {
    if (&before.model() != &after.model()) return {"B model", before.shown_name(), after.shown_name()};
    const nlohmann::json a = scene_json::material_json(before, PathWriting::absolute()),
                         b = scene_json::material_json(after, PathWriting::absolute());
    const std::string path = first_difference(a, b);
    if (path.empty()) return {};
    PendingEdit edit = value_change(a, b, path);
    edit.what = "B " + edit.what;
    return edit;
}

}  // namespace m3055::explore
