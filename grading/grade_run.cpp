#include "grading/grade_run.h"

#include "grading/diff_image.h"
#include "grading/image_input.h"
#include "frame/render_error.h"
#include "image/image.h"
#include "io/input_file.h"
#include "io/message_text.h"
#include "scene/json_brdf.h"
#include "scene/json_parse.h"
#include "scene/load.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <chrono>
#include <deque>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <set>

namespace m3055::grading {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string join_path(const std::string& dir, const std::string& name) { return (fs::path(dir) / name).string(); }

constexpr const char* kTables[] = {"grades.csv", "grades.json", "report.html"};
// The students' own files, each in a folder of its kind, named after the
// student alone (submissions.h: output_stem), so no student's name can clash
// with an output of the run or with another student's file.
constexpr const char* kStudentFolders[] = {"students", "diffs", "feedback"};

// Refuses an --out folder that holds what m3055 grade did not write: a run
// replaces its own files (grade_run.h: kOutputMarker) and nothing else, but a
// teacher's folder of other work would get grades.csv and students/ mixed in.
void check_out_dir(const std::string& out_dir) {
    std::error_code error;
    if (!fs::exists(fs::symlink_status(out_dir, error))) return;
    if (!fs::is_directory(out_dir, error))
        throw std::runtime_error(text::quote_name(out_dir) + ": --out: not a folder");
    if (fs::exists(fs::symlink_status(fs::path(out_dir) / kOutputMarker, error))) return;
    const fs::directory_iterator first(out_dir, error);
    if (error)
        throw std::runtime_error(text::quote_name(out_dir) + ": --out: cannot read the folder: " + error.message());
    if (first != fs::directory_iterator())
        throw std::runtime_error(text::quote_name(out_dir) + ": --out: not empty, and not written by m3055 grade (no " +
                                 kOutputMarker + " in it): grade into a new or empty folder");
}

void prepare_out_dir(const std::string& out_dir) {
    check_out_dir(out_dir);
    std::error_code error;
    fs::create_directories(out_dir, error);
    if (!fs::is_directory(out_dir, error))
        throw std::runtime_error(text::quote_name(out_dir) + ": --out: cannot make the output folder: " +
                                 (error ? error.message() : "not a folder"));
    for (const char* folder : kStudentFolders) {
        fs::create_directories(fs::path(out_dir) / folder, error);
        if (!fs::is_directory(fs::path(out_dir) / folder, error))
            throw std::runtime_error(text::quote_name(join_path(out_dir, folder)) +
                                     ": --out: cannot make the output folder: " + (error ? error.message() : "not a folder"));
    }
    if (!fs::exists(fs::path(out_dir) / kOutputMarker, error))
        write_file_atomic(join_path(out_dir, kOutputMarker), kOutputMarkerText, std::strlen(kOutputMarkerText));
    // Tables of an earlier run go first: after a run that was stopped there
    // are none, rather than old ones beside new images.
    for (const char* table : kTables) fs::remove(fs::path(out_dir) / table, error);
}

std::string join(const std::string& dir, const std::string& name) { return join_path(dir, name); }

// Whether `path` (which need not exist) is `folder` or inside it, after every link.
bool inside(const std::string& path, const std::string& folder) {
    const auto parts = [](const std::string& p) {
        std::error_code error;
        std::vector<std::string> out;
        for (const fs::path& part : fs::weakly_canonical(p, error))
            if (!part.empty()) out.push_back(part.string());  // "subs/" ends in an empty part
        return error ? std::vector<std::string>{} : out;
    };
    const std::vector<std::string> base = parts(folder), target = parts(path);
    return !base.empty() && target.size() >= base.size() && std::equal(base.begin(), base.end(), target.begin());
}

// The folder holds one run's output: the students' files of an earlier run
// whose students are not in this one go (only .png files in students/ and
// diffs/ and .html in feedback/, the run's own folders: nothing else of
// --out is touched).
void remove_stale_images(const std::string& out_dir, const std::set<std::string>& written) {
    for (const char* folder : kStudentFolders) {
        std::error_code error;
        for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(out_dir) / folder, error)) {
            const std::string name = std::string(folder) + "/" + entry.path().filename().string();
            std::error_code type_error;
            const bool ours = entry.path().extension() == (std::string(folder) == "feedback" ? ".html" : ".png");
            if (ours && entry.is_regular_file(type_error) && !written.count(name))
                fs::remove(entry.path(), type_error);
        }
    }
}

std::vector<std::uint8_t> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An image a shard's grades.json names: missing means the shard is incomplete.
std::vector<std::uint8_t> read_shard_image(const std::string& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error))
        throw std::runtime_error(text::quote_name(path) + ": missing: its shard's grades.json names it");
    return read_bytes(path);
}

// A graded submission and the job that writes its images (run on a
// writer thread while the next submission renders, as batch's encoders do).
struct Graded {
    Grade grade;
    std::function<void()> write_images;
    std::size_t bytes = 0;  // what write_images holds until it has run
};

Graded grade_submission_alone(const Assignment& assignment, const Submission& s,
                              const std::function<Renderer&()>& renderer, const LevelImage& reference,
                              const std::string& out_dir, const std::string& class_dir, const LoadContext& scenes);

// Grades one submission: score 0 and its one-line reason for whatever is
// wrong with it; its notes (roster, links, identical files) carried over.
Graded grade_submission(const Assignment& assignment, const Submission& s, const std::function<Renderer&()>& renderer,
                        const LevelImage& reference, const std::string& out_dir, const std::string& class_dir,
                        const LoadContext& scenes) {
    Graded graded = grade_submission_alone(assignment, s, renderer, reference, out_dir, class_dir, scenes);
    graded.grade.missing = s.missing;
    graded.grade.notes = s.notes;
    return graded;
}

std::string relative_to(const std::string& path, const std::string& folder) {
    return path.empty() ? path : fs::path(path).lexically_relative(folder).string();
}

Graded grade_submission_alone(const Assignment& assignment, const Submission& s,
                              const std::function<Renderer&()>& renderer, const LevelImage& reference,
                              const std::string& out_dir, const std::string& class_dir, const LoadContext& scenes) {
    if (!s.problem.empty()) return {broken_grade(assignment, s.student, s.problem), {}};
    // Every message names the submission's files relative to the class folder
    // ("alice/scene.json"), never with the path the teacher typed: the same
    // reasons on every node of a cluster, however each spells the path.
    const std::string scene_path = relative_to(s.scene, class_dir);
    LoadContext submission = scenes;
    submission.folder = class_dir;
    // Nothing outside the submission is read: its .brdf files are its own.
    submission.confinement = Confinement{relative_to(s.folder, class_dir), scene_json::kFilesNeedAFolder};
    try {
        const auto start = std::chrono::steady_clock::now();
        const Scene scene = load_scene_file(scene_path, submission);
        std::optional<LevelImage> screenshot;
        std::string screenshot_error;
        if (!s.screenshot.empty()) try {
                screenshot = read_level_image(io::InputPath::in_folder(class_dir, relative_to(s.screenshot, class_dir)),
                                              scene.display.bits);
            } catch (const std::exception& e) {
                screenshot_error = e.what();
            }
        Renderer& r = renderer();
        if (assignment.time_budget_s > 0)
            r.set_deadline(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(assignment.time_budget_s)));
        auto render = std::make_shared<LevelImage>();
        auto display = std::make_shared<Rgb8Image>();
        Grade grade;
        try {
            grade = grade_one(assignment, scene, r, reference, render.get(), display.get());  // what the explorer calls too
        } catch (const RenderTimeout&) {
            r.set_deadline(std::nullopt);
            return {broken_grade(assignment, s.student,
                                 text::quote_name(scene_path) + ": over its time budget: not drawn within " +
                                     text::format_number(assignment.time_budget_s) +
                                     " s (the assignment's time_budget)"),
                    {}};
        }
        r.set_deadline(std::nullopt);
        grade.student = s.student;
        if (!s.screenshot.empty()) {
            const std::string shown = text::quote_name(s.name + "/screenshot.png");
            if (screenshot) {
                check_screenshot(grade, *screenshot, *render, shown);
            } else {
                grade.screenshot_ok = false;
                grade.screenshot = screenshot_error;
            }
        }
        const bool diff = grade.comparison.has_value();  // same size and depth as the reference
        const std::string png = join(out_dir, "students/" + s.file_stem + ".png"),
                          diff_png = join(out_dir, "diffs/" + s.file_stem + ".png");
        const std::size_t bytes = render->levels.size() * 3;  // levels, display and diff while encoding
        return {std::move(grade),
                [render, display, diff, png, diff_png, &reference]() {
                    // The display as read back, as `m3055 render` writes it.
                    std::vector<FileContents> files = {{png, encode_png(*display)}};
                    if (diff) files.push_back({diff_png, encode_png(difference_image(reference, *render))});
                    write_files_atomic(files);
                },
                bytes};
    } catch (const ShaderError&) {
        throw;  // a broken build fails every scene: not the student's fault
    } catch (const std::exception& e) {
        return {broken_grade(assignment, s.student, text::one_line(e.what())), {}};
    }
}

// Each student's feedback page (each holds three images), made and written
// by a few threads: every file is synced (image/atomic_file.cpp), and one at a
// time the run would mostly wait for the disk. `image_bytes` only reads files.
void write_feedback(const std::string& out_dir, const GradeReport& report,
                    const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes) {
    constexpr std::size_t kWriters = 4;
    std::vector<std::future<void>> writers;
    for (std::size_t t = 0; t < kWriters; ++t)
        writers.push_back(std::async(std::launch::async, [&, t]() {
            for (std::size_t i = t; i < report.students.size(); i += kWriters) {
                const json& s = report.students[i];
                if (!s.contains("feedback")) continue;
                const std::string page = feedback_html(report, s, image_bytes);
                write_file_atomic(join(out_dir, s["feedback"].get<std::string>()), page.data(), page.size());
            }
        }));
    for (auto& writer : writers) writer.get();
}

// A PNG's width and height from its header (the IHDR chunk, bytes 16 to 23),
// without reading the rest; nullopt when the file is not there or not a PNG.
std::optional<ImageSize> png_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char header[24] = {};
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (std::memcmp(header, signature, 8) != 0 || std::memcmp(header + 12, "IHDR", 4) != 0) return std::nullopt;
    const auto big_endian = [&](int at) {
        return int((std::uint32_t(header[at]) << 24) | (std::uint32_t(header[at + 1]) << 16) |
                   (std::uint32_t(header[at + 2]) << 8) | std::uint32_t(header[at + 3]));
    };
    return ImageSize{big_endian(16), big_endian(20)};
}

void write_tables(const std::string& out_dir, const GradeReport& report, const std::string& gradescope,
                  const std::function<std::vector<std::uint8_t>(const std::string&)>& image_bytes) {
    write_feedback(out_dir, report, image_bytes);
    const ImageSizes image_size = [&](const std::string& name) { return png_size(join(out_dir, name)); };
    const auto bytes = [](const std::string& text) { return std::vector<std::uint8_t>(text.begin(), text.end()); };
    std::vector<FileContents> files = {{join(out_dir, "grades.csv"), bytes(grades_csv(report))},
                                       {join(out_dir, "grades.json"), bytes(grades_json(report))},
                                       {join(out_dir, "report.html"), bytes(report_html(report, image_size))}};
    if (!gradescope.empty()) files.push_back({gradescope, bytes(gradescope_json(report))});
    write_files_atomic(files);
}

}  // namespace

GradeReport run_grading(const Assignment& assignment, const std::string& submissions_dir,
                        const std::function<Renderer&()>& renderer, const GradeRunOptions& given) {
    // Output paths absolute, as the messages about them name them.
    GradeRunOptions options = given;
    options.out_dir = fs::absolute(given.out_dir).string();
    if (!given.gradescope.empty()) options.gradescope = fs::absolute(given.gradescope).string();
    std::error_code error;
    const std::string class_dir = fs::is_directory(submissions_dir, error)
                                      ? submissions_dir
                                      : (fs::path(submissions_dir).parent_path().empty()
                                             ? std::string(".")
                                             : fs::path(submissions_dir).parent_path().string());
    // Grades inside the class folder would be a student's folder to the next run.
    if (fs::is_directory(submissions_dir, error) && inside(options.out_dir, submissions_dir))
        throw std::runtime_error(text::quote_name(options.out_dir) + ": --out: " +
                                 (fs::equivalent(submissions_dir, options.out_dir, error)
                                      ? "is the submissions folder " + text::quote_name(submissions_dir)
                                      : "is inside the submissions folder " + text::quote_name(submissions_dir) +
                                            ", where the next run would take it for a student's") +
                                 ": write the grades elsewhere");
    check_out_dir(options.out_dir);
    ClassFolder folder = read_class(submissions_dir, options.class_options);
    const std::vector<Submission> mine = take_shard(folder.submissions, options.shard);
    prepare_out_dir(options.out_dir);
    // The teacher's reference and the students' scenes: a .brdf file is code.
    const LoadContext scenes = LoadContext::for_class(options.allow_brdf);
    Rgb8Image reference_display;
    // Made only for a scene reference: a folder of broken submissions graded
    // against a PNG never needs a GL context.
    const LevelImage reference =
        input_kind(assignment.reference) == InputKind::scene
            ? load_reference(assignment, scenes, &renderer(), &reference_display)
            : load_reference(assignment, scenes, nullptr, &reference_display);
    write_png(join(options.out_dir, "reference.png"), reference_display);

    GradeReport report;
    report.assignment = assignment_json(assignment);
    for (const Ignored& entry : folder.ignored) report.folder["ignored"].push_back({{"name", entry.name}, {"why", entry.why}});
    report.folder["identical"] = folder.identical;
    report.folder["fingerprint"] = folder.fingerprint;
    // The assignment as graded: its file and its reference's bytes.
    report.assignment["digest"] =
        content_digest(io::read_input_file(assignment.path) + '\0' +
                       [&] {
                           std::ifstream in(assignment.reference, std::ios::binary);
                           return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
                       }());
    if (options.shard.n > 1)
        report.assignment["shard"] = std::to_string(options.shard.k) + "/" + std::to_string(options.shard.n);
    // A few writer jobs in flight: images are encoded and written (each file
    // synced, image/atomic_file.cpp) while the next submissions render. Their
    // memory is bounded by count and by bytes (an 8192 x 8192 display holds
    // 400 MB until written), as batch bounds its encoders. A write that fails
    // (disk full) stops the run.
    constexpr std::size_t kWritersInFlight = 4;
    constexpr std::size_t kBytesInFlight = std::size_t(512) << 20;
    struct Writing {
        std::future<void> done;
        std::size_t bytes;
    };
    std::deque<Writing> writing;
    std::size_t bytes_in_flight = 0;
    for (const Submission& s : mine) {
        Graded graded = grade_submission(assignment, s, renderer, reference, options.out_dir, class_dir, scenes);
        const Grade& grade = graded.grade;
        json entry = grade_json(grade, grade.broken.empty() ? s.file_stem : "");
        entry["feedback"] = "feedback/" + s.file_stem + ".html";
        if (grade.broken.empty() && !grade.comparison) entry["images"]["diff"] = "";
        report.students.push_back(std::move(entry));
        while (!writing.empty() &&
               (writing.size() >= kWritersInFlight || bytes_in_flight + graded.bytes > kBytesInFlight)) {
            writing.front().done.get();
            bytes_in_flight -= writing.front().bytes;
            writing.pop_front();
        }
        if (graded.write_images) {
            bytes_in_flight += graded.bytes;
            writing.push_back({std::async(std::launch::async, std::move(graded.write_images)), graded.bytes});
        }
        if (options.graded) options.graded(grade);
    }
    for (auto& job : writing) job.done.get();
    std::set<std::string> written;
    for (const json& student : report.students)
        if (student["images"].is_object())
            for (const char* key : {"render", "diff"})
                if (!student["images"][key].get<std::string>().empty()) written.insert(student["images"][key].get<std::string>());
    for (const json& student : report.students) written.insert(student["feedback"].get<std::string>());
    remove_stale_images(options.out_dir, written);
    write_tables(options.out_dir, report, options.gradescope,
                 [&](const std::string& name) { return name.empty() ? std::vector<std::uint8_t>{} : read_bytes(join(options.out_dir, name)); });
    return report;
}

namespace {

json read_shard(const std::string& dir) {
    const std::string path = join(dir, "grades.json");
    const json doc = scene_json::parse_document(io::read_input_file(path, std::size_t(256) << 20), text::quote_name(path));
    if (!doc.is_object() || !doc.contains("assignment") || !doc.contains("students") || !doc["students"].is_array() ||
        !doc["assignment"].is_object())
        throw std::runtime_error(text::quote_name(path) + ": not the grades.json of m3055 grade");
    return doc;
}

// Which shards are there: every K of one N, each once; a missing shard would
// silently drop students from the class's grades. Returns, for K = 1..N, the
// index in `docs` of shard K.
std::vector<std::size_t> check_shards(const std::vector<json>& docs, const std::vector<std::string>& dirs) {
    std::map<int, std::size_t> seen;
    int n = 0;
    for (std::size_t i = 0; i < docs.size(); ++i) {
        const json& a = docs[i]["assignment"];
        const std::string shard = a.contains("shard") && a["shard"].is_string() ? a["shard"].get<std::string>() : "1/1";
        const Shard parsed = parse_shard(shard);
        if (n && parsed.n != n)
            throw std::runtime_error(text::quote_name(dirs[i]) + ": shard " + shard + " is not of the same " +
                                     std::to_string(n) + (n == 1 ? " shard" : " shards") + " as the others");
        n = parsed.n;
        if (!seen.emplace(parsed.k, i).second)
            throw std::runtime_error(text::quote_name(dirs[i]) + ": shard " + shard + " given twice");
        json plain = a;
        plain.erase("shard");
        json first = docs[0]["assignment"];
        first.erase("shard");
        if (plain != first)
            throw std::runtime_error(text::quote_name(dirs[i]) + ": graded another assignment than " +
                                     text::quote_name(dirs[0]) + " (its title, points or digest differ)");
        if (docs[i].value("folder", json()) != docs[0].value("folder", json()))
            throw std::runtime_error(text::quote_name(dirs[i]) + ": graded another class folder than " +
                                     text::quote_name(dirs[0]) + " (its fingerprint differs: other names or file contents)");
    }
    std::vector<std::size_t> order;
    for (int k = 1; k <= n; ++k) {
        if (!seen.count(k))
            throw std::runtime_error("--merge: shard " + std::to_string(k) + "/" + std::to_string(n) + " is missing");
        order.push_back(seen[k]);
    }
    // Shard K holds the students whose index i in the class's sorted list has
    // i % N == K - 1, so the shards' sizes follow from the class's size.
    std::size_t total = 0;
    for (const json& doc : docs) total += doc["students"].size();
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::size_t expected = total / order.size() + (k < total % order.size() ? 1 : 0);
        const std::size_t held = docs[order[k]]["students"].size();
        if (held != expected)
            throw std::runtime_error(text::quote_name(dirs[order[k]]) + ": shard " + std::to_string(k + 1) + "/" +
                                     std::to_string(n) + " holds " + std::to_string(held) + " submission" +
                                     (held == 1 ? "" : "s") + ", not " + std::to_string(expected) +
                                     " as a shard of these " + std::to_string(total) + " would: shards of different classes?");
    }
    return order;
}

}  // namespace

GradeReport merge_grading(const std::vector<std::string>& shard_dirs, const std::string& out_dir,
                          const std::string& gradescope) {
    std::vector<json> docs;
    for (const std::string& dir : shard_dirs) docs.push_back(read_shard(dir));
    const std::vector<std::size_t> order = check_shards(docs, shard_dirs);
    GradeReport report;
    report.assignment = docs[0]["assignment"];
    report.assignment.erase("shard");
    if (docs[0].contains("folder")) report.folder = docs[0]["folder"];
    std::map<std::string, std::string> image_dir;  // image file name -> the shard folder holding it
    image_dir["reference.png"] = shard_dirs[0];
    // Back in the class's order (bytewise by file name, which grades.json
    // shows escaped): student i is number i / N of shard i % N + 1.
    std::size_t total = 0;
    for (const json& doc : docs) total += doc["students"].size();
    std::set<std::string> names;
    for (std::size_t i = 0; i < total; ++i) {
        const std::size_t shard = order[i % order.size()];
        const json& s = docs[shard]["students"][i / order.size()];
        if (!names.insert(s["student"].get<std::string>()).second)
            throw std::runtime_error("--merge: " + text::quote_name(s["student"].get<std::string>()) +
                                     " is graded in two shards");
        if (s.contains("feedback")) {
            // A page of feedback/, never a path out of it.
            const std::string name = s["feedback"].get<std::string>();
            const std::string file = name.compare(0, 9, "feedback/") == 0 ? name.substr(9) : "";
            if (file.empty() || file.find('/') != std::string::npos || file == "." || file == "..")
                throw std::runtime_error(text::quote_name(shard_dirs[shard] + "/grades.json") +
                                         ": feedback: not a file name: " + text::quote(name));
        }
        report.students.push_back(s);
        if (s["images"].is_object())
            for (const char* key : {"render", "diff"})
                if (const std::string name = s["images"][key].get<std::string>(); !name.empty()) {
                    // A file of the shard's students/ or diffs/, never a path out of them.
                    const std::string folder = std::string(key) == "render" ? "students/" : "diffs/";
                    const std::string file = name.compare(0, folder.size(), folder) == 0 ? name.substr(folder.size()) : "";
                    if (file.empty() || file.find('/') != std::string::npos || file == "." || file == "..")
                        throw std::runtime_error(text::quote_name(shard_dirs[shard] + "/grades.json") +
                                                 ": images." + key + ": not a file name: " + text::quote(name));
                    image_dir[name] = shard_dirs[shard];
                }
    }
    prepare_out_dir(out_dir);
    std::error_code error;
    // Copied by a few threads: each file is synced (image/atomic_file.cpp),
    // and one at a time the merge would mostly wait for the disk.
    std::vector<std::pair<std::string, std::string>> copies;  // from, to
    for (const auto& [name, dir] : image_dir) {
        if (fs::exists(join(out_dir, name), error) && fs::equivalent(join(out_dir, name), join(dir, name), error))
            continue;  // merging into one of the shards' own folders
        copies.emplace_back(join(dir, name), join(out_dir, name));
    }
    constexpr std::size_t kCopiers = 4;
    std::vector<std::future<void>> copiers;
    for (std::size_t t = 0; t < kCopiers; ++t)
        copiers.push_back(std::async(std::launch::async, [&copies, t]() {
            for (std::size_t i = t; i < copies.size(); i += kCopiers) {
                const std::vector<std::uint8_t> bytes = read_shard_image(copies[i].first);
                write_file_atomic(copies[i].second, bytes.data(), bytes.size());
            }
        }));
    for (auto& copier : copiers) copier.get();
    std::set<std::string> written;
    for (const auto& [name, dir] : image_dir) written.insert(name);
    for (const json& student : report.students) {
        if (!student.contains("feedback")) continue;
        written.insert(student["feedback"].get<std::string>());
    }
    remove_stale_images(out_dir, written);
    write_tables(out_dir, report, gradescope, [&](const std::string& name) {
        return name.empty() ? std::vector<std::uint8_t>{} : read_bytes(join(out_dir, name));
    });
    return report;
}

}  // namespace m3055::grading
