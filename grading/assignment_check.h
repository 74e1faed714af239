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
    // One line each, "FILE: field: problem", each once: the file's structure
    // and ranges first (AssignmentRead::errors), then what they mean against
    // the reference.
    std::vector<std::string> errors;
    // Lines that go with the errors, said once after them: the model names a
    // rule may give, when one is unknown.
    std::vector<std::string> notes;
    // Rules with points the reference scene fails: "FILE: rules[2] (warmer): the reference fails it: REASON"
    // (never a rule with an error: that is said once, as the error).
    std::vector<std::string> reference_fails;
    bool reference_unreadable = false;  // the reference file could not be loaded (an error says why)
    bool reference_is_scene = false;  // false: an image (or unreadable), so the rules could not be checked against it
    double reference_score = 0;       // the points the reference earns from the rules (image: all of its points)
};

// Loads the reference (a scene as `context` allows, not rendered; an image,
// read) and the start scene, and checks the assignment `read` against them:
// every error at once, the read's own first. A reference or start file that
// cannot be loaded is an error naming its field.
AssignmentCheck check_assignment(const AssignmentRead& read, const LoadContext& context);

}  // namespace m3055::grading
