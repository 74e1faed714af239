// `m3055 grade --check ASSIGNMENT.json`: an assignment
// checked against its own reference before any student meets it. Structural
// errors (a model name that does not exist, a path that does not resolve in
// the reference scene, an object index or light name that is not there, an
// image tolerance every render meets) make every student lose those points,
// so `grade` refuses an assignment that has any; rules with points that the
// reference itself fails are reported too (the teacher's own answer would not
// get full marks).
#pragma once

#include "grading/assignment.h"
#include "scene/load_context.h"

#include <string>
#include <vector>

namespace m3055::grading {

struct AssignmentCheck {
    // One line each, "FILE: field: problem", in the file's order.
    std::vector<std::string> errors;
    // Rules with points the reference scene fails: "FILE: rules[2] (warmer): the reference fails it: REASON".
    std::vector<std::string> reference_fails;
    bool reference_is_scene = false;  // false: an image, so the rules could not be checked against it
    double reference_score = 0;       // the points the reference earns from the rules (image: all of its points)
};

// Loads the reference scene (when the reference is one; no rendering) as
// `context` allows and checks `assignment` against it. Throws (one line) when
// the reference cannot be read.
AssignmentCheck check_assignment(const Assignment& assignment, const LoadContext& context);

}  // namespace m3055::grading
