// Grading one submitted scene against an assignment. grade_one is
// what `m3055 grade` runs for every student, and what the explorer can call
// with its own renderer to show a student the score and reasons `grade` would
// give, live: the same code, not a copy.
#pragma once

#include "grading/assignment.h"
#include "grading/level_compare.h"
#include "analysis/nonfinite.h"
#include "grading/rules.h"
#include "frame/renderer.h"
#include "scene/load_context.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace m3055::grading {

struct Grade {
    std::string student;
    double score = 0, max = 0;
    bool passed = false;
    std::string broken;         // why the submission could not be graded (then score 0), or ""
    std::vector<Check> checks;  // the image comparison first, then the rules in order
    std::optional<Comparison> comparison;
    std::string screenshot;     // the screenshot check's line when the student sent one, or ""
    bool screenshot_ok = true;
    bool missing = false;            // on the roster, nothing submitted
    std::vector<std::string> notes;  // information, no penalty (submissions.h: Submission::notes)
    // One line each: the broken reason, or the reason of each check that
    // failed and a mismatched screenshot; empty for a perfect submission.
    std::vector<std::string> reasons() const;
};

// The assignment's reference as levels: its image read (at 5 bits), or its
// scene, loaded as `context` allows, rendered with `renderer` (needed only
// then; no deadline). The image shown for it (the PNG, or the render) is left
// in *display when given.
LevelImage load_reference(const Assignment& assignment, const LoadContext& context, Renderer* renderer,
                          Rgb8Image* display = nullptr);

// Scores a scene whose render is `render` (levels_from_render of it).
// `nonfinite`: the render's pixels that are NaN or infinite (before the
// display quantized them); any fail the image check, with no image points.
Grade grade_scene(const Assignment& assignment, const Scene& scene, const LevelImage& reference,
                  const LevelImage& render, const NonFinite& nonfinite = {});

// Renders `scene` with `renderer` (the caller sets its deadline, if any),
// counts the render's non-finite pixels (its raw readback), then grade_scene. The render is left in *render_out when given, and the
// display as read back (what `m3055 render` writes) in *display_out.
Grade grade_one(const Assignment& assignment, const Scene& scene, Renderer& renderer, const LevelImage& reference,
                LevelImage* render_out = nullptr, Rgb8Image* display_out = nullptr);

// A submission that could not be graded: score 0 of the maximum, `reason`.
Grade broken_grade(const Assignment& assignment, const std::string& student, const std::string& reason);

// Checks the student's screenshot against the render of their scene: it must
// be exactly the render (every pixel on the same level).
void check_screenshot(Grade& grade, const LevelImage& screenshot, const LevelImage& render,
                      const std::string& screenshot_name);

}  // namespace m3055::grading
