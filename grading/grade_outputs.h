// The outputs of `m3055 grade` (docs/grading.md#outputs): grades.csv,
// grades.json, report.html and the optional Gradescope results.json, all made
// from one GradeReport, so an unsharded run and a merge of shards (which
// reads the shards' grades.json back) write the same bytes. Nothing here
// holds a timestamp for that reason.
#pragma once

#include "grading/assignment.h"
#include "grading/grade.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace m3055::grading {

struct GradeReport {
    nlohmann::json assignment;             // title, max, pass, reference image name
    std::vector<nlohmann::json> students;  // in the class's order (bytewise by file name)
    // The whole class folder's, in every shard: "ignored" [{name, why}] and
    // "identical" [[student, ...], ...] (submissions.h: ClassFolder).
    nlohmann::json folder = {{"ignored", nlohmann::json::array()}, {"identical", nlohmann::json::array()}};
};

nlohmann::json assignment_json(const Assignment& assignment);
// `image_stem`: the student's images students/STEM.png and diffs/STEM.png
// were written (submissions.h: output_stem), or "" when none were.
nlohmann::json grade_json(const Grade& grade, const std::string& image_stem);

// What became of a student (a grade_json), one word meaning one thing in every
// output: "pass" and "fail" (graded: at least the pass score, or below it),
// "refused" (not graded: the submission could not be, and its reason says why;
// 0 points), "missing" (on the roster, nothing submitted).
std::string result_of(const nlohmann::json& student);

std::string grades_csv(const GradeReport& report);
std::string grades_json(const GradeReport& report);
std::string gradescope_json(const GradeReport& report);
// The size of an image of the output folder (its PNG header), by its name
// relative to the folder ("students/alice.png"), or nullopt when it is not there.
struct ImageSize {
    int width = 0, height = 0;
};
using ImageSizes = std::function<std::optional<ImageSize>(const std::string&)>;

// The class's page, beside its images: each student's render and difference
// image linked (students/, diffs/, reference.png), loaded lazily as they
// scroll into view, their sizes given (`image_size`) so the page's layout is
// known before any is; no network, no framework; a few lines of inline
// script sort, filter and search the table; readable printed.
std::string report_html(const GradeReport& report, const ImageSizes& image_size);

// OUT/feedback/NAME.html: one self-contained page to hand back to one
// student: their render, the reference, the difference, the score and every
// check's line (passed ones too); nothing of any other student.
std::string feedback_html(const GradeReport& report, const nlohmann::json& student,
                          const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes);

std::string base64(const std::vector<std::uint8_t>& bytes);

}  // namespace m3055::grading
