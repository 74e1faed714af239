// `m3055 grade ASSIGNMENT.json SUBMISSIONS/ --out DIR` (docs/grading.md):
// every submission rendered once, compared with the assignment's reference,
// its rules checked, and grades.csv, grades.json, report.html written. `--shard K/N` grades a deterministic share;
// `--merge DIR...` joins the shards' outputs. The grading is grading/.
// Exit 0: the run finished (whatever the scores); 1: it could not (bad
// assignment, unusable reference or output folder); 2: usage.
#include "commands.h"
#include "headless_context.h"
#include "capture/capture.h"
#include "gl/program.h"
#include "gl/shader_cache.h"
#include "scene/load_context.h"
#include "interrupt.h"
#include "progress.h"

#include "grading/assignment_check.h"
#include "grading/grade_run.h"
#include "io/message_text.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <iostream>
#include <map>
#include <memory>

namespace m3055 {

namespace {

struct GradeOptions {
    std::string assignment, submissions, out, shard = "1/1", gradescope, backend = "auto";
    std::vector<std::string> merge;
    std::string roster;
    bool allow_brdf = false, follow_symlinks = false, check = false;
};

void print_grade(const grading::Grade& grade) {
    const std::vector<std::string> reasons = grade.reasons();
    // The student as every output shows the name (grading/submissions.h: shown_name:
    // one line of valid UTF-8, at most 4 x 255 bytes), and the result's one word
    // (grade_outputs.h: result_of).
    const char* result = grade.missing ? "missing" : !grade.broken.empty() ? "refused" : grade.passed ? "pass" : "fail";
    std::fprintf(stderr, "m3055: %s: %s / %s %s%s%s\n", grade.student.c_str(),
                 text::format_number(grade.score).c_str(), text::format_number(grade.max).c_str(), result,
                 reasons.empty() ? "" : ": ", reasons.empty() ? "" : text::one_line(reasons.front(), 200).c_str());
    for (std::size_t i = 1; i < reasons.size(); ++i)  // every reason a teacher reads in grades.csv
        std::fprintf(stderr, "  also: %s\n", text::one_line(reasons[i], 200).c_str());
    for (const std::string& note : grade.notes)
        std::fprintf(stderr, "  note: %s\n", text::one_line(note).c_str());
}

// What the folder held that was not graded, and the identical submissions: one line each.
void print_folder(const nlohmann::json& folder) {
    const std::size_t ignored = folder["ignored"].size();
    if (ignored)
        std::fprintf(stderr, "m3055: not graded: %zu entr%s of the folder\n", ignored, ignored == 1 ? "y" : "ies");
    for (const auto& entry : folder["ignored"])
        std::fprintf(stderr, "  %s: %s\n", entry["name"].get<std::string>().c_str(),
                     entry["why"].get<std::string>().c_str());
    for (const auto& group : folder["identical"]) {
        std::string names;
        for (const auto& name : group) names += (names.empty() ? "" : ", ") + name.get<std::string>();
        std::fprintf(stderr, "m3055: byte-identical submissions: %s\n", text::one_line(names, 1000).c_str());
    }
}

// Every error of the assignment, one line each, then the lines that go with them.
void print_errors(const grading::AssignmentCheck& check) {
    for (const std::string& line : check.errors) std::cerr << error_line(line) << "\n";
    for (const std::string& line : check.notes) std::cerr << error_line(line) << "\n";
}

// `grade --check ASSIGNMENT.json`: exit 0 when the assignment has no error and
// its reference earns every point of its rules, 1 otherwise.
bool run_check(const GradeOptions& options) {
    const grading::AssignmentRead read = grading::read_assignment(options.assignment);
    const grading::Assignment& assignment = read.assignment;
    // A .brdf file is code: the reference runs it only when the teacher asks.
    const grading::AssignmentCheck check = grading::check_assignment(read, LoadContext::for_class(options.allow_brdf));
    print_errors(check);
    for (const std::string& line : check.reference_fails) std::cerr << error_line(line) << "\n";
    const std::string name = text::quote_name(options.assignment);
    std::string summary = name + ": " + std::to_string(check.errors.size()) +
                          (check.errors.size() == 1 ? " error" : " errors");
    if (read.has_error_at("") || assignment.reference.empty() || check.reference_unreadable)
        summary += "; the rules could not be checked against the reference";
    else if (check.reference_is_scene)
        summary += "; the reference scores " + text::format_number(check.reference_score) + " of " +
                   text::format_number(assignment.max_score()) + " points";
    else
        summary += "; the reference is an image: the rules could not be checked against a scene";
    std::cerr << "m3055: " << text::one_line(summary) << "\n";
    return check.errors.empty() && check.reference_fails.empty();
}

void run_grade(const GradeOptions& options) {
    if (!options.merge.empty()) {
        const auto report = grading::merge_grading(options.merge, options.out, options.gradescope);
        std::fprintf(stderr, "m3055: merged %zu shard%s, %zu submission%s into %s\n", options.merge.size(),
                     options.merge.size() == 1 ? "" : "s", report.students.size(),
                     report.students.size() == 1 ? "" : "s", text::quote_name(options.out).c_str());
        return;
    }
    const grading::AssignmentRead read = grading::read_assignment(options.assignment);
    const grading::Assignment& assignment = read.assignment;
    // The assignment against its own reference: any error stops the run
    // before anything is written; rules the reference fails are said.
    // A .brdf file is code: the reference runs it only when the teacher asks.
    const grading::AssignmentCheck check = grading::check_assignment(read, LoadContext::for_class(options.allow_brdf));
    print_errors(check);
    if (!check.errors.empty())
        throw std::runtime_error(text::quote_name(options.assignment) + ": " + std::to_string(check.errors.size()) +
                                 (check.errors.size() == 1 ? " error" : " errors") +
                                 " in the assignment (m3055 grade --check): nothing graded");
    for (const std::string& line : check.reference_fails) std::cerr << error_line("warning: " + line) << "\n";
    grading::GradeRunOptions run;
    run.out_dir = options.out;
    run.shard = grading::parse_shard(options.shard);
    run.gradescope = options.gradescope;
    run.graded = print_grade;
    run.class_options.roster = options.roster;
    run.class_options.follow_symlinks = options.follow_symlinks;
    run.allow_brdf = options.allow_brdf;
    // Mesa's shader cache in --out, not the teacher's home: a .brdf is a student's code.
    keep_shader_cache_in((std::filesystem::absolute(options.out) / kShaderCacheFolder).string());
    std::unique_ptr<Capture> capture;  // made when the first scene is drawn
    const Backend backend = parse_backend(options.backend);
    const auto report = grading::run_grading(
        assignment, options.submissions,
        [&]() -> Renderer& {
            if (!capture) capture = std::make_unique<Capture>(make_headless_context(backend));
            return capture->renderer();
        },
        run);
    print_folder(report.folder);
    std::map<std::string, std::size_t> results;  // pass, fail, refused, missing
    for (const auto& s : report.students) ++results[grading::result_of(s)];
    const std::size_t submitted = report.students.size() - results["missing"];
    std::string line = "m3055: " + std::to_string(submitted) + (submitted == 1 ? " submission" : " submissions");
    if (options.shard != "1/1") line += " of shard " + options.shard;
    line += ": " + std::to_string(results["pass"]) + " passed, " + std::to_string(results["fail"]) + " failed, " +
            std::to_string(results["refused"]) + " refused (not graded)";
    if (results["missing"]) line += "; " + std::to_string(results["missing"]) + " on the roster with no submission";
    std::fprintf(stderr, "%s; wrote %s\n", line.c_str(), text::quote_name(options.out + "/report.html").c_str());
}

}  // namespace

void add_grade_command(CLI::App& app) {
    auto options = std::make_shared<GradeOptions>();
    CLI::App* command = app.add_subcommand(
        "grade", "Grade a folder of submitted scenes against an assignment: grades.csv, grades.json, report.html");
    command->add_option("assignment", options->assignment, "Assignment JSON (docs/grading.md)");
    command->add_option("submissions", options->submissions, "Folder of NAME.json or NAME/scene.json submissions, or one NAME.json");
    command->add_option("--out", options->out, "Output folder (required, except with --check)");
    command->add_flag("--check", options->check,
                      "Check ASSIGNMENT.json against its reference (model names, paths, objects, lights, thresholds) "
                      "and grade the reference against the rules; exit 1 on a problem");
    command->add_option("--shard", options->shard, "Grade only shard K of N (sorted names), e.g. 2/4")
        ->capture_default_str();
    command->add_option("--merge", options->merge, "Merge the outputs of shard runs (their --out folders)")
        ->expected(1, -1);
    command->add_option("--gradescope", options->gradescope, "Also write a Gradescope-style results.json here");
    command->add_option("--backend", options->backend, "GL context: auto (EGL, then OSMesa), egl or osmesa")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command->add_option("--roster", options->roster,
                        "File of the class's names, one a line: a name with no submission gets a row (no submission), "
                        "a submission not on it a note");
    command->add_flag("--follow-symlinks", options->follow_symlinks,
                      "Grade submissions that are symbolic links staying inside the folder (refused otherwise)");
    command->add_flag("--allow-brdf", options->allow_brdf,
                      "Accept materials from .brdf files (their shader code runs; off: such a submission scores 0)");
    command->callback([options, command]() {
        // SIGINT, SIGTERM, SIGHUP: temporaries removed, images already graded kept,
        // no tables (they are written last), one line.
        const InterruptGuard interrupt([](int signal) {
            return error_line("interrupted by " + signal_name(signal) + ": grades.csv, grades.json and report.html not written");
        });
        // Bare `m3055 grade`: what it takes.
        if (options->assignment.empty() && options->merge.empty() && !options->check) {
            std::cerr << command->help() << "\nm3055: grade: give ASSIGNMENT.json SUBMISSIONS/ --out DIR "
                                            "(or --check ASSIGNMENT.json, or --merge DIR... --out DIR)\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        // Usage errors (docs/grading.md: exit 2), before anything is read or written.
        try {
            // A path that is not there at all is a slip of the command line, not a bad file.
            for (const std::string* path : {&options->assignment, &options->submissions}) {
                std::error_code error;
                if (!path->empty() && !std::filesystem::exists(std::filesystem::symlink_status(*path, error)))
                    throw std::invalid_argument("grade: " + text::quote_name(*path) + ": no such file or folder");
            }
            if (options->check && (options->assignment.empty() || !options->submissions.empty() ||
                                   !options->merge.empty() || !options->out.empty()))
                throw std::invalid_argument("grade --check takes ASSIGNMENT.json alone");
            if (!options->check && options->out.empty()) throw std::invalid_argument("grade: --out is required");
            if (!options->check && options->merge.empty() && (options->assignment.empty() || options->submissions.empty()))
                throw std::invalid_argument("grade: ASSIGNMENT.json and SUBMISSIONS/ are required (or --merge DIR...)");
            if (!options->merge.empty() && !options->assignment.empty())
                throw std::invalid_argument("grade: --merge takes the shards' folders, not ASSIGNMENT.json and SUBMISSIONS/");
            grading::parse_shard(options->shard);
        } catch (const std::invalid_argument& error) {
            std::cerr << error_line(error.what()) << "\n";
            throw CLI::RuntimeError(kExitUsage);
        }
        bool ok = true;
        try {
            if (options->check) ok = run_check(*options);
            else run_grade(*options);
        } catch (const std::exception& error) {
            std::cerr << error_text(error) << "\n";
            ok = false;
        }
        if (!ok) throw CLI::RuntimeError(kExitFailure);
    });
}

}  // namespace m3055
