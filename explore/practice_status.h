// What the explorer shows of an assignment it was opened with
// (`m3055 explore --assignment`): the live grade of the scene being edited,
// as `m3055 grade` would give it. Plain data, no GL: practice.h computes it,
// panel_assignment.cpp shows it, script.cpp prints it.
#pragma once

#include "grading/rules.h"

#include <string>
#include <vector>

namespace m3055::explore {

struct PracticeStatus {
    bool active = false;      // opened with --assignment
    std::string title;        // the assignment's title
    std::string reference;    // the reference's file, as named by the assignment
    double pass_score = 0;

    bool graded = false;      // a grade below exists
    bool pending = false;     // the scene changed since: regraded once the edit settles
    double score = 0, max = 0;
    bool passed = false;
    std::vector<grading::Check> checks;  // the image comparison first, then the rules
    std::vector<std::string> reasons;    // Grade::reasons(): what `grade` writes
    double grade_ms = 0;      // the last grade: one render, readback, comparison and rules
    long grades = 0;          // grades computed so far

    bool print_requested = false;  // --script `print_grade`: answered once the grade is current
};

}  // namespace m3055::explore
