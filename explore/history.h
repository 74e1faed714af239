// Undo/redo for the explorer: snapshots of what the user edits (the scene, the
// A/B compare's material B, the scene's name and file), taken when an edit is
// finished (a slider released, a drag on the display ended, a load or preset
// applied), so one slider drag is one step. No ImGui and no GL in here.
#pragma once

#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <deque>
#include <string>

namespace m3055::explore {

// What one undo step restores.
struct Snapshot {
    Scene scene;
    nlohmann::json doc;   // scene_to_json(scene): what makes two snapshots differ
    Material material_b;  // A/B compare's B
    Camera camera_home;
    std::string scene_name, scene_file;
};

class History {
public:
    static constexpr std::size_t kMaxSteps = 500;  // the issue asks for at least 200

    // Forgets every step; `base` is the state before any edit.
    void reset(Snapshot base);
    // When `now` differs from the last snapshot, makes that an undo step named
    // `label` (or, when empty, after the first scene field that changed) and
    // forgets the redo steps. Returns whether a step was added.
    bool commit(Snapshot now, const std::string& label);

    // A save gives the scene a (new) name and file: no step of its own.
    void set_head_file(const std::string& name, const std::string& file);

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }
    const std::string& undo_label() const { return undo_.back().label; }
    const std::string& redo_label() const { return redo_.back().label; }
    std::size_t undo_steps() const { return undo_.size(); }
    // Moves one step back / forward; returns the snapshot to restore.
    const Snapshot& undo();
    const Snapshot& redo();
    const Snapshot& head() const { return head_; }

private:
    struct Step {
        Snapshot other;  // undo_: the state before the step; redo_: after it
        std::string label;
    };
    Snapshot head_;
    std::deque<Step> undo_, redo_;
};

// The JSON path of the first value that differs between two scene documents
// ("objects[1].material.m", "camera.position"), "" when they are equal.
std::string first_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& prefix = "");

}  // namespace m3055::explore
