// Where `m3055 explore [--assignment A.json] [SCENE.json]` starts: the scene,
// the assignment to practise against, and the undo history's start.
#pragma once

#include "explore/explorer.h"
#include "grading/assignment.h"

#include <optional>
#include <string>

namespace m3055::explore {

// The starting scene: `scene_path`, or the spec example when none is given.
// With `assignment_path`: the assignment (explore/practice.h open_assignment:
// without a scene, a copy of its start scene); a named scene file that does
// not exist yet is a student's first practice: the start scene, and Ctrl+S
// writes the named file. The start counts as saved, with no history
// (start_history). Throws with the loader's one-line message on a bad scene
// or assignment.
std::optional<grading::Assignment> start_scene(Explorer& explorer, const std::string& scene_path,
                                               const std::string& assignment_path);

// Forgets the history: the document as it is is the start (and counts as saved).
void start_history(Explorer& explorer);

}  // namespace m3055::explore
