#include "explore/practice.h"

#include "explore/files.h"
#include "grading/grade.h"
#include "io/message_text.h"
#include "models/model_spec.h"
#include "scene/json_brdf.h"
#include "scene/referenced_file.h"
#include "scene/load.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <utility>

namespace m3055::explore {

namespace {

// The first object whose material comes from a .brdf file, or -1.
int first_brdf_object(const Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].material.model().family == Family::brdf) return int(i);
    return -1;
}

// The first object that is a model from a file, or -1.
int first_model_file_object(const Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].shape == Shape::mesh && !scene.objects[i].file.empty()) return int(i);
    return -1;
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// grade_one under the assignment's time budget, as grade_run.cpp runs it; a
// render over the budget scores 0 there, and here says so.
grading::Grade timed_grade(const grading::Assignment& assignment, const Scene& scene, Renderer& renderer,
                           const grading::LevelImage& reference) {
    if (assignment.time_budget_s > 0)
        renderer.set_deadline(std::chrono::steady_clock::now() +
                              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(assignment.time_budget_s)));
    try {
        grading::Grade grade = grading::grade_one(assignment, scene, renderer, reference);
        renderer.set_deadline(std::nullopt);
        return grade;
    } catch (const RenderTimeout&) {
        renderer.set_deadline(std::nullopt);
        return grading::broken_grade(assignment, "", "over its time budget: not drawn within " +
                                                         text::format_number(assignment.time_budget_s) +
                                                         " s (the assignment's time_budget)");
    }
}

}  // namespace

Practice::Practice(grading::Assignment assignment, Renderer* renderer, bool allow_brdf)
    : assignment_(std::move(assignment)), allow_brdf_(allow_brdf) {
    reference_ = grading::load_reference(assignment_, LoadContext::trusted(), renderer, &shown_);
}

PracticeStatus Practice::start_status() const {
    PracticeStatus status;
    status.active = true;
    status.title = assignment_.title;
    status.reference = std::filesystem::path(assignment_.reference).filename().string();
    status.pass_score = assignment_.pass_score;
    status.max = assignment_.max_score();
    status.pending = true;
    return status;
}

void Practice::scene_changed(PracticeStatus& status, double now) {
    status.pending = true;
    changed_at_ = now;
}

double Practice::settle_left(const PracticeStatus& status, double now) const {
    if (!status.pending) return -1.0;
    return std::max(0.0, changed_at_ + kSettleSeconds - now);
}

std::optional<grading::Grade> Practice::refusal(const Scene& scene, const std::string& scene_file) const {
    const int brdf_object = first_brdf_object(scene);
    if (brdf_object < 0) return model_file_refusal(scene, scene_file);
    const std::string field = "objects[" + std::to_string(brdf_object) + "].material.file: ";
    // grade without --allow-brdf refuses the file when it loads the scene: the same reason here.
    if (!allow_brdf_) return grading::broken_grade(assignment_, "", field + scene_json::brdf_not_allowed_reason());
    // With it, grade reads a .brdf only inside a folder submission NAME/ (its
    // scene.json beside the file); a single NAME.json is refused.
    if (std::filesystem::path(scene_file).filename() == "scene.json") return std::nullopt;
    return grading::broken_grade(assignment_, "",
                                 field + scene_json::brdf_without_folder_reason(scene_json::kFilesNeedAFolder));
}

// grade reads a model file only in a folder submission NAME/scene.json, as a .brdf.
std::optional<grading::Grade> Practice::model_file_refusal(const Scene& scene, const std::string& scene_file) const {
    const int object = first_model_file_object(scene);
    if (object < 0 || std::filesystem::path(scene_file).filename() == "scene.json") return std::nullopt;
    return grading::broken_grade(assignment_, "",
                                 "objects[" + std::to_string(object) + "].file: " +
                                     scene_json::without_folder_reason("a model file", scene_json::kFilesNeedAFolder));
}

void Practice::regrade(PracticeStatus& status, const Scene& scene, const std::string& scene_file,
                       Renderer& renderer) const {
    const auto start = std::chrono::steady_clock::now();
    grading::Grade grade;
    try {
        if (std::optional<grading::Grade> refused = refusal(scene, scene_file)) grade = std::move(*refused);
        else grade = timed_grade(assignment_, scene, renderer, reference_);
    } catch (const std::exception& e) {
        grade = grading::broken_grade(assignment_, "", text::one_line(e.what()));
    }
    status.graded = true;
    status.pending = false;
    status.score = grade.score;
    status.max = grade.max;
    status.passed = grade.passed;
    status.checks = grade.checks;
    status.reasons = grade.reasons();
    status.grade_ms = milliseconds_since(start);
    ++status.grades;
}

std::string Practice::reference_label() const {
    return "reference (" + std::filesystem::path(assignment_.reference).filename().string() + ")";
}

std::string grade_line(const PracticeStatus& status) {
    std::string line = "grade score=" + text::format_number(status.score) + " max=" +
                       text::format_number(status.max) + " passed=" + (status.passed ? "yes" : "no");
    for (const std::string& reason : status.reasons) line += "\t" + reason;
    return line;
}


grading::Assignment open_assignment(Explorer& e, const std::string& path, bool scene_given) {
    grading::Assignment assignment = grading::load_assignment(path);
    e.view.save_path = e.session.files.save_name = "submission.json";
    if (!scene_given && !assignment.start.empty()) {
        Scene start;
        try {
            start = load_scene_file(assignment.start, LoadContext::trusted());
        } catch (const std::exception& e) {  // the loader names the scene; say which field named it
            throw std::runtime_error(text::quote_name(path) + ": start: " + text::one_line(e.what()));
        }
        // A name and no file: Ctrl+S asks, the assignment's own file stays as it is.
        set_scene(e, start, std::filesystem::path(assignment.start).filename().string() + " (copy)");
    }
    return assignment;
}

}  // namespace m3055::explore
