#include "explore/undo.h"

#include "scene/load.h"

#include <algorithm>

namespace m3055::explore {

Snapshot snapshot(const ExplorerState& state) {
    return {state.scene, scene_to_json(state.scene, PathWriting::absolute()), state.material_b,
            state.camera_home, state.scene_name, state.scene_file};
}

void restore(ExplorerState& state, const Snapshot& s) {
    state.scene = s.scene;
    state.material_b = s.material_b;
    state.camera_home = s.camera_home;
    state.scene_name = s.scene_name;
    state.scene_file = s.scene_file;
    selected_material(state);  // clamps the selection
    state.selected_light =
        std::clamp(state.selected_light, 0, std::max(0, static_cast<int>(state.scene.lights.size()) - 1));
    state.changed();
}

void start_history(ExplorerState& state) {
    state.history.reset(snapshot(state));
    state.pending.clear();
    mark_saved(state);
}

bool commit_edits(ExplorerState& state) {
    const bool added = state.history.commit(snapshot(state), state.pending.label());
    state.pending.clear();
    return added;
}

bool undo(ExplorerState& state) {
    commit_edits(state);  // an edit still in progress is a step of its own
    if (!state.history.can_undo()) return false;
    state.status = "undid " + state.history.undo_label();
    restore(state, state.history.undo());
    return true;
}

bool redo(ExplorerState& state) {
    commit_edits(state);
    if (!state.history.can_redo()) return false;
    state.status = "redid " + state.history.redo_label();
    restore(state, state.history.redo());
    return true;
}

namespace {
// A file by its path; a scene without one by its name (no path holds a newline).
std::string saved_key(const ExplorerState& state) {
    return state.scene_file.empty() ? "\n" + state.scene_name : state.scene_file;
}
}  // namespace

void mark_saved(ExplorerState& state) {
    state.saved_docs[saved_key(state)] = scene_to_json(state.scene, PathWriting::absolute());
}

bool unsaved(const ExplorerState& state) {
    const auto saved = state.saved_docs.find(saved_key(state));
    return saved == state.saved_docs.end() || scene_to_json(state.scene, PathWriting::absolute()) != saved->second;
}

std::string title_name(const ExplorerState& state) {
    return state.scene_name + (unsaved(state) ? " * (unsaved edits)" : "");
}

}  // namespace m3055::explore
