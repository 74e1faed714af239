#include "explore/start.h"

#include "explore/files.h"
#include "explore/practice.h"
#include "explore/undo.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <filesystem>

namespace m3055::explore {

std::optional<grading::Assignment> start_scene(ExplorerState& state, const std::string& scene_path,
                                               const std::string& assignment_path) {
    // `explore --assignment A.json NEW.json` with no NEW.json yet: a student's
    // first practice; the assignment's start scene is the scene, saved as NEW.json.
    const bool new_submission =
        !assignment_path.empty() && !scene_path.empty() && !std::filesystem::exists(scene_path);
    if (scene_path.empty() || new_submission) {
        set_scene(state, default_scene(), "spec example");
    } else {
        set_scene(state, load_scene_file(scene_path, LoadContext::trusted()), scene_path);
        state.scene_file = scene_path;
    }
    if (!scene_path.empty()) state.save_dir = std::filesystem::path(scene_path).parent_path().string();
    std::optional<grading::Assignment> assignment;
    if (!assignment_path.empty()) {
        assignment = open_assignment(state, assignment_path, !scene_path.empty() && !new_submission);
        if (new_submission) {  // Ctrl+S writes the named file: the one the student will submit
            state.scene_file = state.save_path = scene_path;
            state.status = "new submission: the assignment's start scene; Ctrl+S writes " + scene_path;
        }
    }
    start_history(state);
    return assignment;
}

}  // namespace m3055::explore
