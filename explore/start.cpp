#include "explore/start.h"

#include "explore/edits.h"
#include "explore/files.h"
#include "explore/practice.h"
#include "scene/load.h"
#include "scene/presets.h"

#include <filesystem>

namespace m3055::explore {

void start_history(Explorer& e) {
    e.doc.history.clear();
    mark_saved(e.doc);
}

std::optional<grading::Assignment> start_scene(Explorer& e, const std::string& scene_path,
                                               const std::string& assignment_path) {
    // `explore --assignment A.json NEW.json` with no NEW.json yet: a student's
    // first practice; the assignment's start scene is the scene, saved as NEW.json.
    const bool new_submission =
        !assignment_path.empty() && !scene_path.empty() && !std::filesystem::exists(scene_path);
    if (scene_path.empty() || new_submission) {
        set_scene(e, default_scene(), "spec example");
    } else {
        set_scene(e, load_scene_file(scene_path, LoadContext::trusted()), scene_path, "", scene_path);
    }
    if (!scene_path.empty()) e.session.files.save_dir = std::filesystem::path(scene_path).parent_path().string();
    std::optional<grading::Assignment> assignment;
    if (!assignment_path.empty()) {
        assignment = open_assignment(e, assignment_path, !scene_path.empty() && !new_submission);
        if (new_submission) {  // Ctrl+S writes the named file: the one the student will submit
            e.doc.file = e.view.save_path = scene_path;
            e.session.messages.status = "new submission: the assignment's start scene; Ctrl+S writes " + scene_path;
        }
    }
    start_history(e);
    return assignment;
}

}  // namespace m3055::explore
