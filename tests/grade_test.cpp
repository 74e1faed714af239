// `m3055 grade` as a teacher runs it: the worked assignment's
// scores, every kind of broken submission scoring 0 with its reason without
// stopping the run, a run killed halfway leaving no tables, report.html in
// headless Chromium, and 4 shards under GNU parallel merged to the same bytes.
#include "grading/grade_outputs.h"
#include "test_paths.h"
#include "image/image.h"
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <thread>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kAssignment = source_path("assignments/three-point/assignment.json");
const std::string kSubmissions = source_path("assignments/three-point/submissions");

json read_json(const std::string& path) { return json::parse(read_text(path)); }

std::map<std::string, json> by_student(const json& grades) {
    std::map<std::string, json> out;
    for (const json& s : grades["students"]) out[s["student"]] = s;
    return out;
}

bool have_program(const std::string& name) {
    return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0;
}

// NAME/scene.json whose first object's material is the project's own Lambert .brdf.
void write_brdf_submission(const std::string& folder) {
    fs::create_directories(folder);
    fs::copy_file(source_path("tests/data/brdf/lambert.brdf"), folder + "/lambert.brdf");
    json scene = read_json(kSubmissions + "/alice.json");
    scene["objects"][0]["material"] = {{"model", "brdf"}, {"file", "lambert.brdf"}};
    write_text(folder + "/scene.json", scene.dump());
}

TEST(Grade, BrdfSubmissionsAreGradedOnlyWithAllowBrdf) {
    TempDir dir;
    write_brdf_submission(dir.file("subs/zoe"));
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out"), "--allow-brdf"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    ASSERT_TRUE(s.count("zoe"));
    EXPECT_TRUE(s.at("zoe")["broken"].get<std::string>().empty()) << s.at("zoe")["broken"];
    EXPECT_TRUE(file_exists(dir.file("out/students/zoe.png")));
}

// The students' files are named relative to the class folder, however the
// teacher spells its path: the same reasons on every machine.
// The paths a trace of open/openat/creat (strace -o) shows opened, with
// whether each was opened for writing; failed opens are left out.
std::vector<std::pair<std::string, bool>> opened_paths(const std::string& trace) {
    std::vector<std::pair<std::string, bool>> out;
    std::istringstream lines(read_text(trace));
    for (std::string line; std::getline(lines, line);) {
        const std::size_t open = line.find('"'), close = line.find('"', open + 1);
        if (open == std::string::npos || close == std::string::npos || line.find(" = -1 ") != std::string::npos) continue;
        const std::string flags = line.substr(close);
        const bool writing = flags.find("O_WRONLY") != std::string::npos || flags.find("O_RDWR") != std::string::npos ||
                             flags.find("O_CREAT") != std::string::npos || line.find("creat(") != std::string::npos;
        out.emplace_back(line.substr(open + 1, close - open - 1), writing);
    }
    return out;
}

// A student's .brdf is code: Mesa's cache of the shaders compiled from it is
// kept in --out, not the teacher's home, and the run opens nothing of the
// home (gnuplot's ~/.gnuplot included) and writes nothing outside --out.
TEST(Grade, NothingOfTheClassIsWrittenOrOpenedOutsideItAndOut) {
    TempDir dir;
    write_brdf_submission(dir.file("subs/zoe"));
    fs::copy_file(kSubmissions + "/alice.json", dir.file("subs/alice.json"));
    fs::create_directories(dir.file("home"));
    write_text(dir.file("home/.gnuplot"), "# the teacher's own gnuplot settings\n");
    const auto home = snapshot(dir.file("home"));
    // strace may be missing, or ptrace not allowed (some containers): then only the home is checked.
    const bool traced = std::system("strace -qq -o /dev/null true >/dev/null 2>&1") == 0;
    // LeakSanitizer cannot run under ptrace (the sanitizer tree): leaks are checked untraced elsewhere.
    const std::string command = "env -u XDG_CACHE_HOME -u MESA_SHADER_CACHE_DIR -u MESA_GLSL_CACHE_DIR "
                                "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" HOME=" +
                                dir.file("home") + " " +
                                (traced ? "strace -f -qq -e trace=open,openat,creat -o " + dir.file("trace") + " " : "") +
                                M3055_BINARY + " grade " + kAssignment + " " + dir.file("subs") + " --out " +
                                dir.file("out") + " --allow-brdf 2>" + dir.file("err");
    ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir.file("err"));
    ASSERT_TRUE(by_student(read_json(dir.file("out/grades.json"))).at("zoe")["broken"].get<std::string>().empty());
    EXPECT_EQ(snapshot(dir.file("home")), home) << "something was written to the teacher's home";
    EXPECT_TRUE(fs::is_directory(dir.file("out/.shader-cache/mesa_shader_cache"))) << "the cache is in --out";
    if (!traced) GTEST_SKIP() << "strace cannot run here: what the run opened is not checked";
    const std::vector<std::pair<std::string, bool>> opened = opened_paths(dir.file("trace"));
    ASSERT_GT(opened.size(), 10u);
    for (const auto& [path, writing] : opened) {
        EXPECT_NE(path.rfind(dir.file("home"), 0), 0u) << "opened in the home: " << path;
        // Written: --out's files, by path or (the atomic temporaries) relative to its folders; devices.
        if (writing)
            EXPECT_TRUE(path.rfind(dir.file("out/"), 0) == 0 || path.rfind("/dev/", 0) == 0 ||
                        (path[0] == '.' && path.find(".tmp-") != std::string::npos))
                << "written outside --out: " << path;
    }
}

TEST(Grade, SubmissionFilesAreNamedRelativeToTheClassFolder) {
    TempDir dir;
    fs::create_directories(dir.file("subs/zoe"));
    fs::copy_file(kSubmissions + "/alice.json", dir.file("subs/zoe/scene.json"));
    write_text(dir.file("subs/zoe/screenshot.png"), "not a PNG");
    write_brdf_submission(dir.file("subs/yves"));
    fs::remove(dir.file("subs/yves/lambert.brdf"));
    for (const std::string& spelled : {dir.file("subs"), dir.file("subs/../subs/")}) {
        SCOPED_TRACE(spelled);
        const RunResult run =
            run_m3055({"grade", kAssignment, spelled, "--out", dir.file("out"), "--allow-brdf"});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const auto s = by_student(read_json(dir.file("out/grades.json")));
        const std::string screenshot = s.at("zoe")["screenshot"], broken = s.at("yves")["broken"];
        EXPECT_EQ(screenshot.rfind("zoe/screenshot.png: cannot read PNG: ", 0), 0u) << screenshot;
        EXPECT_EQ(broken.rfind("yves/scene.json: objects[0].material.file: yves/lambert.brdf: cannot read file: ", 0),
                  0u)
            << broken;
    }
}

// A student checks the one file they will submit: the same grade as in the class's folder.
TEST(Grade, OneSceneFileIsGradedAsInTheFolder) {
    TempDir dir;
    const RunResult one = run_m3055({"grade", kAssignment, kSubmissions + "/dave.json", "--out", dir.file("one")});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_NE(one.err.find("m3055: 1 submission: 0 passed, 1 failed, 0 refused (not graded)"), std::string::npos)
        << one.err;
    const RunResult all = run_m3055({"grade", kAssignment, kSubmissions, "--out", dir.file("all")});
    ASSERT_EQ(all.exit_code, 0) << all.err;
    const auto alone = by_student(read_json(dir.file("one/grades.json")));
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_EQ(alone.at("dave"), by_student(read_json(dir.file("all/grades.json"))).at("dave"));
    EXPECT_EQ(read_text(dir.file("one/diffs/dave.png")), read_text(dir.file("all/diffs/dave.png")));
    write_text(dir.file("notes.txt"), "not a scene");
    const RunResult text = run_m3055({"grade", kAssignment, dir.file("notes.txt"), "--out", dir.file("bad")});
    EXPECT_EQ(text.exit_code, 1);
    EXPECT_NE(text.err.find("notes.txt: not a submissions folder nor a .json scene file"), std::string::npos) << text.err;
    EXPECT_FALSE(file_exists(dir.file("bad/grades.csv")));
}

TEST(Grade, WorkedAssignmentScores) {
    TempDir out;
    const RunResult run = run_m3055({"grade", kAssignment, kSubmissions, "--out", out.path(), "--gradescope",
                                     out.file("results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(out.file("grades.json")));
    const std::map<std::string, double> expected = {{"alice", 100}, {"bob", 100}, {"carol", 50},
                                                    {"dave", 50},   {"erin", 50}, {"frank", 0}};
    ASSERT_EQ(s.size(), expected.size());
    for (const auto& [name, score] : expected) EXPECT_EQ(s.at(name)["score"], score) << name;
    EXPECT_EQ(s.at("alice")["comparison"]["same_pixels"], s.at("alice")["comparison"]["pixels"]);
    EXPECT_EQ(s.at("carol")["screenshot"], "carol/screenshot.png: is the render of the scene");
    EXPECT_NE(s.at("dave")["reasons"][1].get<std::string>().find("is metal_blinn, not metal"), std::string::npos);
    // The terminal gives every reason too, the first on the student's line, the others under it.
    EXPECT_NE(run.err.find("m3055: dave: 50 / 100 fail: image: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("\n  also: rules[0] (model): objects[0] is metal_blinn, not metal\n"), std::string::npos)
        << run.err;
    EXPECT_NE(s.at("frank")["broken"].get<std::string>().find("lobes[0].m: must be in [0.001, 2], got 5"),
              std::string::npos);
    // alice.png is byte for byte what `m3055 render` writes for her scene.
    const RunResult render = run_m3055({"render", "--scene", kSubmissions + "/alice.json", "--out", out.file("r.png")});
    ASSERT_EQ(render.exit_code, 0);
    EXPECT_EQ(read_text(out.file("r.png")), read_text(out.file("students/alice.png")));
    const std::string csv = read_text(out.file("grades.csv"));
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "student,score,max,result,reasons,notes");
    EXPECT_NE(csv.find("\nalice,100,100,pass,,\n"), std::string::npos) << csv;
    EXPECT_EQ(read_json(out.file("results.json"))["tests"].size(), 5u * 7u + 1u);  // frank: one line
}

// The second worked assignment: three-point lighting on the repository's vase
// under a shadowed rect softbox. Each student misses what the rules name: a
// fill behind the subject (ben), a hard directional key (cleo), a key that
// casts no shadows (dan), a model file not handed in (eve), a model in a
// one-file submission (fay).
TEST(Grade, WorkedModelAssignmentScores) {
    const std::string folder = source_path("assignments/vase-softbox");
    TempDir out;
    const RunResult run = run_m3055({"grade", folder + "/assignment.json", folder + "/submissions", "--out", out.path()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(out.file("grades.json")));
    const std::map<std::string, double> expected = {{"ada", 100}, {"ben", 50}, {"cleo", 50},
                                                    {"dan", 50},  {"eve", 0},  {"fay", 0}};
    ASSERT_EQ(s.size(), expected.size());
    for (const auto& [name, score] : expected) EXPECT_EQ(s.at(name)["score"], score) << name;
    EXPECT_EQ(s.at("ada")["comparison"]["same_pixels"], s.at("ada")["comparison"]["pixels"]);
    // The one failed rule of each graded student, after the image.
    const std::map<std::string, std::string> failed = {
        {"ben", "key to fill: the fill light gives no light at the subject facing the camera"},
        {"cleo", "softbox key: 0 rect lights enabled, not 1"},
        {"dan", "key shadow: \"key\" casts no shadows (its \"shadow\" is false)"}};
    for (const auto& [name, reason] : failed) {
        ASSERT_EQ(s.at(name)["reasons"].size(), 2u) << name;
        EXPECT_EQ(s.at(name)["reasons"][1], reason) << name;
    }
    EXPECT_EQ(s.at("eve")["result"], "refused");
    EXPECT_EQ(s.at("eve")["broken"],
              "eve/scene.json: objects[1].file: eve/vase.obj: cannot read file: No such file or directory");
    EXPECT_NE(s.at("fay")["broken"].get<std::string>().find("objects[1].file: a model file is not accepted here"),
              std::string::npos);
}

// "fail": graded, below the pass score; "refused": not graded (frank's scene
// is out of range). The same word for the same student in every output.
TEST(Grade, RefusedAndFailMeanOneThingInEveryOutput) {
    TempDir out;
    const RunResult run = run_m3055({"grade", kAssignment, kSubmissions, "--out", out.path()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::map<std::string, std::string> expected = {{"alice", "pass"}, {"carol", "fail"}, {"frank", "refused"}};
    const std::string csv = read_text(out.file("grades.csv"));
    const auto s = by_student(read_json(out.file("grades.json")));
    const std::string report = read_text(out.file("report.html"));
    for (const auto& [name, result] : expected) {
        SCOPED_TRACE(name);
        EXPECT_NE(csv.find("\n" + name + ","), std::string::npos);
        const std::string row = csv.substr(csv.find("\n" + name + ",") + 1);
        EXPECT_EQ(row.substr(0, row.find('\n')).find(",100," + result + ","), row.find(',', name.size() + 1)) << row;
        EXPECT_EQ(s.at(name)["result"], result);
        EXPECT_NE(run.err.find("m3055: " + name + ": "), std::string::npos);
        const std::string line = run.err.substr(run.err.find("m3055: " + name + ": "));
        EXPECT_NE(line.substr(0, line.find('\n')).find(" / 100 " + result), std::string::npos) << line;
        EXPECT_NE(report.find("data-status=\"" + result + "\" data-student=\"" + name + "\""), std::string::npos);
        EXPECT_NE(report.find("<td data-sort=\"" + result + "\" class=\"result " + result + "\">" + result + "</td>"),
                  std::string::npos);
    }
    EXPECT_NE(run.err.find("m3055: 6 submissions: 2 passed, 3 failed, 1 refused (not graded)"), std::string::npos) << run.err;
    EXPECT_NE(report.find("id=\"count-failed\">3<"), std::string::npos);
    EXPECT_NE(report.find("id=\"count-refused\">1<"), std::string::npos);
    EXPECT_NE(read_text(out.file("feedback/frank.html")).find("0 of 100 points: refused (not graded"), std::string::npos);
    EXPECT_NE(read_text(out.file("feedback/carol.html")).find("50 of 100 points: failed"), std::string::npos);
}

TEST(Grade, BrokenSubmissionsScoreZeroAndNeverStopTheRun) {
    TempDir dir;
    const std::string subs = dir.file("subs");
    fs::create_directories(subs + "/nofile");
    fs::create_directories(subs + "/ok");
    fs::copy_file(kSubmissions + "/alice.json", subs + "/ok/scene.json");
    write_text(subs + "/badjson.json", "{\"display\": ");
    json range = read_json(kSubmissions + "/alice.json");
    range["lights"][0]["intensity"] = 11;
    write_text(subs + "/range.json", range.dump());
    write_text(subs + "/large.json", "");
    fs::resize_file(subs + "/large.json", std::uintmax_t(17) << 20);  // over the 16 MiB limit
    ASSERT_EQ(mkfifo((subs + "/fifo.json").c_str(), 0600), 0);
    write_stalling_scene(subs + "/slow.json");  // minutes of drawing: over the 2 s budget
    write_brdf_submission(subs + "/brdfcode");      // code, and grade was not given --allow-brdf
    json assignment = read_json(kAssignment);
    assignment["reference"] = kAssignment.substr(0, kAssignment.rfind('/')) + "/reference.json";
    assignment.erase("start");  // beside the worked assignment, not this copy
    assignment["time_budget"] = 2;
    write_text(dir.file("a.json"), assignment.dump());
    const RunResult run = run_m3055({"grade", dir.file("a.json"), subs, "--out", dir.file("out")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    const std::map<std::string, std::string> reasons = {
        {"badjson", "invalid JSON"},
        {"range", "lights[0].intensity: must be in [0, 10], got 11"},
        {"large", "too large"},
        {"fifo", "a FIFO"},
        {"nofile", "nofile/scene.json: missing"},
        {"slow", "over its time budget"},
        {"brdfcode", "a .brdf file is code: m3055 batch and grade run it only with --allow-brdf"},
    };
    for (const auto& [name, reason] : reasons) {
        ASSERT_TRUE(s.count(name)) << name;
        EXPECT_EQ(s.at(name)["score"], 0) << name;
        EXPECT_NE(s.at(name)["broken"].get<std::string>().find(reason), std::string::npos)
            << name << ": " << s.at(name)["broken"];
        EXPECT_FALSE(file_exists(dir.file("out/students/" + name + ".png"))) << name;
    }
    EXPECT_TRUE(s.at("ok")["broken"].get<std::string>().empty()) << s.at("ok")["broken"];
}

TEST(Grade, KilledHalfwayLeavesNoTables) {
    TempDir dir;
    const std::string subs = dir.file("subs");
    fs::create_directories(subs);
    for (int i = 0; i < 150; ++i) fs::copy_file(kSubmissions + "/bob.json", subs + "/s" + std::to_string(1000 + i) + ".json");
    Running grade({"grade", kAssignment, subs, "--out", dir.file("out")});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (!file_exists(dir.file("out/students/s1003.png")) && !grade.finished() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    grade.signal(SIGTERM);
    const RunResult run = grade.wait();
    ASSERT_EQ(run.killed_by, SIGTERM) << "the run ended before the signal: " << run.err;
    for (const char* table : {"grades.csv", "grades.json", "report.html"})
        EXPECT_FALSE(file_exists(dir.file(std::string("out/") + table))) << table;
    for (const auto& entry : fs::recursive_directory_iterator(dir.file("out"))) {
        const std::string name = fs::relative(entry.path(), dir.file("out")).string();
        EXPECT_TRUE(std::regex_match(name, std::regex(R"(((students|diffs)/s\d{4}|reference)\.png|students|diffs|feedback|\.m3055-grade|\.shader-cache(/.*)?)")))
            << "left behind: " << name;
    }
}

TEST(Grade, ReportOpensInHeadlessChromium) {
    if (!have_program("chromium")) GTEST_SKIP() << "chromium is not installed (scripts/setup --for-tests installs it)";
    TempDir out;
    ASSERT_EQ(run_m3055({"grade", kAssignment, kSubmissions, "--out", out.path()}).exit_code, 0);
    // The page as shipped, plus a probe that loads every image (they load
    // lazily, as they near the view) and counts those that did not decode.
    std::string page = read_text(out.file("report.html"));
    EXPECT_EQ(page.find("http"), std::string::npos) << "no network";
    const std::string probe = "<script>window.addEventListener('load',function(){var left=0,n=0;"
                              "var all=[].filter.call(document.images,function(i){return i.id!=='viewer-img';});"
                              "function done(){if(--left===0)document.body.setAttribute('data-broken',n);}"
                              "left=all.length;all.forEach(function(i){i.loading='eager';"
                              "if(i.complete&&i.naturalWidth>0){done();return;}"
                              "i.addEventListener('load',done);i.addEventListener('error',function(){n++;done();});});});"
                              "</script>";
    write_text(out.file("probe.html"), page.replace(page.rfind("</body>"), 7, probe + "</body>"));
    const std::string dom = out.file("dom.html");
    const std::string command = "chromium --headless --no-sandbox --disable-gpu --user-data-dir=" + out.file("profile") +
                                " --virtual-time-budget=5000 --dump-dom file://" + out.file("probe.html") + " > " +
                                dom + " 2>/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    const std::string text = read_text(dom);
    EXPECT_NE(text.find("data-broken=\"0\""), std::string::npos) << "a broken image, or the probe did not run";
    // The grades table's rows (the class summary's tables come before it).
    const std::string body = text.substr(text.find("<table id=\"grades\""));
    std::size_t rows = 0;
    for (std::size_t at = body.find("<tr data-status"); at != std::string::npos; at = body.find("<tr data-status", at + 1))
        ++rows;
    EXPECT_EQ(rows, 6u);
    // Five renders and five difference images (frank's scene is broken), the reference, and the
    // magnifier's (empty until a picture is clicked).
    std::size_t images = 0;
    for (std::size_t at = text.find("<img"); at != std::string::npos; at = text.find("<img", at + 1)) ++images;
    EXPECT_EQ(images, 12u);
}

TEST(Grade, FourShardsUnderParallelMergeToTheSameBytes) {
    if (!have_program("parallel")) GTEST_SKIP() << "GNU parallel is not installed (scripts/setup --for-tests installs it)";
    TempDir dir;
    const std::string subs = dir.file("subs");
    fs::create_directories(subs);
    for (const auto& entry : fs::directory_iterator(kSubmissions))
        fs::copy(entry.path(), subs + "/" + entry.path().filename().string(), fs::copy_options::recursive);
    for (int i = 0; i < 5; ++i) fs::copy_file(kSubmissions + "/bob.json", subs + "/extra" + std::to_string(i) + ".json");
    ASSERT_EQ(run_m3055({"grade", kAssignment, subs, "--out", dir.file("one")}).exit_code, 0);
    const std::string command = "parallel --will-cite -j 4 '" + std::string(M3055_BINARY) + " grade " + kAssignment + " " + subs +
                                " --out " + dir.path() + "/shard{} --shard {}/4 2>/dev/null' ::: 1 2 3 4";
    ASSERT_EQ(std::system(command.c_str()), 0);
    // Shards in any order on the command line.
    const RunResult merge = run_m3055({"grade", "--merge", dir.file("shard3"), dir.file("shard1"), dir.file("shard4"),
                                       dir.file("shard2"), "--out", dir.file("merged")});
    ASSERT_EQ(merge.exit_code, 0) << merge.err;
    // Every file of the unsharded run but its shader cache, byte for byte.
    EXPECT_EQ(snapshot(dir.file("merged")), snapshot(dir.file("one"), ".shader-cache"));
    // A missing shard is an error, not a smaller class.
    const RunResult partial = run_m3055({"grade", "--merge", dir.file("shard1"), dir.file("shard2"), "--out", dir.file("p")});
    EXPECT_EQ(partial.exit_code, 1);
    EXPECT_NE(partial.err.find("is missing"), std::string::npos) << partial.err;
}

}  // namespace
}  // namespace m3055::test

namespace m3055::test {
namespace {

// grades/ inside the submissions folder would be a student's folder to the
// next run: refused before anything is written, as the folder itself is.
TEST(Grade, AnOutputFolderInsideTheSubmissionsIsRefused) {
    TempDir dir;
    const std::string subs = dir.file("subs");
    fs::create_directories(subs);
    fs::copy_file(kSubmissions + "/alice.json", subs + "/alice.json");
    const auto before = snapshot(subs);
    for (const std::string& out : {subs + "/grades", subs + "/../subs/deeper/grades", subs, subs + "/"}) {
        SCOPED_TRACE(out);
        const RunResult run = run_m3055({"grade", kAssignment, subs, "--out", out});
        EXPECT_EQ(run.exit_code, 1) << run.err;
        EXPECT_NE(run.err.find("--out: is"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("the submissions folder"), std::string::npos) << run.err;
        EXPECT_EQ(snapshot(subs), before) << "nothing written";
    }
    // A student's own file, checked alone, may have its grades beside it.
    const RunResult one = run_m3055({"grade", kAssignment, subs + "/alice.json", "--out", subs + "/check"});
    EXPECT_EQ(one.exit_code, 0) << one.err;
}

// --out is a new folder, an empty one or one m3055 grade wrote (its marker
// file): a folder of other work is refused untouched, by grade and by --merge.
TEST(Grade, AnOutputFolderOfOtherFilesIsRefusedUnlessEmpty) {
    TempDir dir;
    fs::create_directories(dir.file("work"));
    write_text(dir.file("work/thesis.tex"), "the teacher's");
    const auto before = snapshot(dir.file("work"));
    const RunResult other = run_m3055({"grade", kAssignment, kSubmissions, "--out", dir.file("work")});
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.err.find("work: --out: not empty, and not written by m3055 grade (no .m3055-grade in it)"),
              std::string::npos) << other.err;
    EXPECT_EQ(snapshot(dir.file("work")), before);
    fs::create_directories(dir.file("empty"));
    ASSERT_EQ(run_m3055({"grade", kAssignment, kSubmissions, "--out", dir.file("empty")}).exit_code, 0);
    EXPECT_TRUE(file_exists(dir.file("empty/.m3055-grade")));
    // Its own folder again: the teacher's notes in it are left alone.
    write_text(dir.file("empty/notes.txt"), "the teacher's");
    EXPECT_EQ(run_m3055({"grade", kAssignment, kSubmissions, "--out", dir.file("empty")}).exit_code, 0);
    EXPECT_EQ(read_text(dir.file("empty/notes.txt")), "the teacher's");
    const RunResult merge = run_m3055({"grade", "--merge", dir.file("empty"), "--out", dir.file("work")});
    EXPECT_EQ(merge.exit_code, 1);
    EXPECT_NE(merge.err.find("not written by m3055 grade"), std::string::npos) << merge.err;
    EXPECT_EQ(snapshot(dir.file("work")), before);
}

}  // namespace
}  // namespace m3055::test

namespace m3055::test {
namespace {

// The reference may be an image instead of a scene: the render's PNG, or its
// PFM, grade the worked submissions exactly as the scene does.
TEST(Grade, ImageReferencesGradeAsTheSceneDoes) {
    TempDir dir;
    const std::string scene = kAssignment.substr(0, kAssignment.rfind('/')) + "/reference.json";
    ASSERT_EQ(run_m3055({"render", "--scene", scene, "--out", dir.file("ref.png"), "--raw", dir.file("ref.pfm")}).exit_code, 0);
    ASSERT_EQ(run_m3055({"grade", kAssignment, kSubmissions, "--out", dir.file("scene")}).exit_code, 0);
    const std::string expected = read_text(dir.file("scene/grades.csv"));
    for (const std::string reference : {"ref.png", "ref.pfm"}) {
        json assignment = read_json(kAssignment);
        assignment["reference"] = reference;
        assignment.erase("start");  // beside the worked assignment, not this copy
        write_text(dir.file("a.json"), assignment.dump());
        const std::string out = dir.file("out-" + reference);
        const RunResult run = run_m3055({"grade", dir.file("a.json"), kSubmissions, "--out", out});
        ASSERT_EQ(run.exit_code, 0) << run.err;
        EXPECT_EQ(read_text(out + "/grades.csv"), expected) << reference;
        EXPECT_EQ(read_text(out + "/reference.png"), read_text(dir.file("ref.png"))) << reference;
    }
}

}  // namespace
}  // namespace m3055::test
