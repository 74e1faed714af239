// A whole grading run (`m3055 grade`): the reference rendered once, every
// submission of the (shard of the) folder graded in name order, each
// student's images written as soon as they are graded, and the tables and
// report written last, atomically together (renderer/image: write_files_atomic),
// so a run killed halfway leaves no grades.csv, grades.json or report.html.
#pragma once

#include "grading/assignment.h"
#include "grading/grade.h"
#include "grading/grade_outputs.h"
#include "grading/submissions.h"
#include "frame/renderer.h"

#include <functional>
#include <string>
#include <vector>

namespace m3055::grading {

// The file every --out folder of m3055 grade holds: a run writes into an
// empty or new folder, or one with this file (an earlier run's), and refuses
// any other, so that it never mixes its files into a folder of other work.
inline constexpr const char* kOutputMarker = ".m3055-grade";
inline constexpr const char* kOutputMarkerText =
    "This folder was written by m3055 grade (docs/grading.md#outputs): a later run may replace its files.\n";

struct GradeRunOptions {
    std::string out_dir;
    Shard shard;                                // 1/1: every submission
    std::string gradescope;                     // also write this results.json, or ""
    ClassOptions class_options;                 // --roster, --follow-symlinks
    bool allow_brdf = false;                    // --allow-brdf: .brdf materials (code) accepted
    std::function<void(const Grade&)> graded;  // after each submission (progress)
};

// Throws (one line) for what stops the run: the reference cannot be made,
// the output folder cannot be written. A broken submission never does:
// it scores 0 with its reason. A renderer is asked for only when a scene is
// drawn (`renderer()` makes it on first use). Returns the report written.
GradeReport run_grading(const Assignment& assignment, const std::string& submissions_dir,
                        const std::function<Renderer&()>& renderer, const GradeRunOptions& options);

// `m3055 grade --merge DIR... --out OUT`: the shards' grades.json read back,
// checked to be shards 1..N of one run of one assignment, and the same
// outputs written into OUT as one unsharded run writes (images copied).
GradeReport merge_grading(const std::vector<std::string>& shard_dirs, const std::string& out_dir,
                          const std::string& gradescope);

}  // namespace m3055::grading
