#include "explore/history.h"

#include <utility>

namespace m3055::explore {

void History::reset(Snapshot base) {
    head_ = std::move(base);
    undo_.clear();
    redo_.clear();
}

bool History::commit(Snapshot now, const std::string& label) {
    // The name and file alone (a save) are no step: set_head_file follows them.
    if (now.doc == head_.doc && now.material_b == head_.material_b) return false;
    std::string name = label;
    if (name.empty()) {
        name = first_difference(head_.doc, now.doc);
        if (name.empty()) name = "material B";  // only B (compare) changed
    }
    undo_.push_back({std::move(head_), name});
    if (undo_.size() > kMaxSteps) undo_.pop_front();
    redo_.clear();
    head_ = std::move(now);
    return true;
}

void History::set_head_file(const std::string& name, const std::string& file) {
    head_.scene_name = name;
    head_.scene_file = file;
}

const Snapshot& History::undo() {
    Step step = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back({std::move(head_), step.label});
    head_ = std::move(step.other);
    return head_;
}

const Snapshot& History::redo() {
    Step step = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back({std::move(head_), step.label});
    head_ = std::move(step.other);
    return head_;
}

std::string first_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& prefix) {
    if (a == b) return "";
    if (a.is_object() && b.is_object()) {
        for (const auto& [key, value] : a.items()) {
            const std::string path = prefix.empty() ? key : prefix + "." + key;
            if (!b.contains(key)) return path;
            const std::string inner = first_difference(value, b[key], path);
            if (!inner.empty()) return inner;
        }
        for (const auto& [key, value] : b.items())
            if (!a.contains(key)) return prefix.empty() ? key : prefix + "." + key;
    }
    // Arrays of numbers (colours, positions) are one value; arrays of
    // objects (objects, lights, lobes) name the element.
    if (a.is_array() && b.is_array() && a.size() == b.size() && !a.empty() && a[0].is_object()) {
        for (std::size_t i = 0; i < a.size(); ++i) {
            const std::string inner = first_difference(a[i], b[i], prefix + "[" + std::to_string(i) + "]");
            if (!inner.empty()) return inner;
        }
    }
    return prefix.empty() ? "scene" : prefix;
}

}  // namespace m3055::explore
