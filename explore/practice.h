// `m3055 explore --assignment ASSIGNMENT.json`: the assignment, its reference
// (as levels, for grading, and as the image shown beside the student's
// display), and the live grade of the scene being edited, recomputed once an
// edit has settled. The grade is grading::grade_one, the function `m3055
// grade` runs for every student, on the explorer's own renderer: the same
// code, not a copy. No GL calls here: explore_ui shows the reference.
#pragma once

#include "explore/practice_status.h"
#include "explore/explorer.h"
#include "grading/assignment.h"
#include "grading/grade.h"
#include "grading/level_compare.h"
#include "frame/renderer.h"
#include "scene/scene.h"

#include <memory>
#include <optional>
#include <string>

namespace m3055::explore {

class Practice {
public:
    // Loads the reference (a scene reference is rendered once with `renderer`,
    // which the caller then re-renders its own scene on; an image reference
    // needs none: nullptr). Throws with the loader's one-line message.
    // `allow_brdf`: grade .brdf materials as `m3055 grade --allow-brdf` does
    // (without it a scene with one scores 0 with grade's reason).
    Practice(grading::Assignment assignment, Renderer* renderer, bool allow_brdf);

    const grading::Assignment& assignment() const { return assignment_; }

    // The scene changed at time `now` (seconds, any clock): the grade is stale.
    void scene_changed(PracticeStatus& status, double now);
    // Seconds until a stale grade may be recomputed (the edit has settled): 0
    // when it may be now, negative when there is nothing to recompute.
    double settle_left(const PracticeStatus& status, double now) const;

    // grade_one of `scene` with `renderer` (its display is left showing
    // `scene`), under the assignment's time budget as `grade` has it; the
    // result and its time into `status`.
    // `scene_file`: the file the scene was loaded from or saved to ("" for none).
    void regrade(PracticeStatus& status, const Scene& scene, const std::string& scene_file, Renderer& renderer) const;
    // The grade of a scene `grade` refuses before rendering it, 0 with
    // grade's reason: a .brdf material without allow_brdf; with it, a .brdf
    // material in a scene that is not a folder submission's NAME/scene.json
    // (a single NAME.json, or no file yet), which grade refuses too; a model
    // from a file in such a scene likewise. None otherwise.
    std::optional<grading::Grade> refusal(const Scene& scene, const std::string& scene_file) const;

    // The reference as shown beside the student's display (the PNG, the
    // render, a PFM's display; rows top to bottom), and its label.
    const Rgb8Image& reference_image() const { return shown_; }
    std::string reference_label() const;

    // The status shown before the first grade.
    PracticeStatus start_status() const;

private:
    std::optional<grading::Grade> model_file_refusal(const Scene& scene, const std::string& scene_file) const;

    grading::Assignment assignment_;
    grading::LevelImage reference_;
    Rgb8Image shown_;           // the reference as shown (the PNG, the render, a PFM's display)
    double changed_at_ = 0;
    bool allow_brdf_ = false;
};

// Seconds without a further change before the grade is recomputed: a slider
// drag or typing regrades once at its end, not on every step.
inline constexpr double kSettleSeconds = 0.3;

// The status line `print_grade` prints: "grade score=S max=M passed=yes|no<TAB>reason<TAB>...".
std::string grade_line(const PracticeStatus& status);


// --assignment PATH: loads the assignment (throws its one-line error). With
// no scene given, the student starts from a copy of the assignment's "start"
// scene, or the spec example when it names none: never the reference, which
// would score full marks untouched. The copy has no file of its own, so the
// first Ctrl+S asks where to save the submission (proposing submission.json).
grading::Assignment open_assignment(Explorer& explorer, const std::string& path, bool scene_given);

}  // namespace m3055::explore
