// `m3055 grade` on what a real class hands in: class folders built
// here, from code, with the names, links and files a teacher meets: Latin-1
// bytes from Windows zip files, spaces, newlines, 240-character names, names
// differing only by case.
#include "grading/submissions.h"
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <map>
#include <set>

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

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// alice's full-marks scene and dave's metal_blinn one, under other names.
std::string good_scene() { return read_text(kSubmissions + "/alice.json"); }
std::string weaker_scene() { return read_text(kSubmissions + "/dave.json"); }
// alice's scene with another fill intensity: a file of its own, still full marks.
std::string good_scene_variant(int i) {
    json scene = json::parse(good_scene());
    scene["lights"][1]["intensity"] = scene["lights"][1]["intensity"].get<double>() + 0.001 * (i + 1);
    return scene.dump();
}

// Odd names students give their files, as bytes, with the text every output shows for them.
struct OddName {
    std::string bytes, shown;
};
std::vector<OddName> odd_names() {
    const std::string long_name(240, 'x');
    return {{"caf\xE9 latin1", "caf\\xE9 latin1"},
            {"new\nline", "new\\nline"},
            {"with space", "with space"},
            {"back\\slash", "back\\\\slash"},
            {"zo\xC3\xAB", "zo\xC3\xAB"},  // valid UTF-8: shown as it is
            {long_name, long_name},
            {"Alice", "Alice"},
            {"alice", "alice"}};
}

TEST(GradeClass, EveryFileNameGetsItsRowEscapedTheSameInEveryOutput) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    for (const OddName& n : odd_names()) write_text(dir.file("subs/" + n.bytes + ".json"), good_scene());
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out"), "--gradescope",
                                     dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const json grades = read_json(dir.file("out/grades.json"));
    const auto s = by_student(grades);
    ASSERT_EQ(s.size(), odd_names().size());
    const std::string csv = read_text(dir.file("out/grades.csv"));
    const std::string html = read_text(dir.file("out/report.html"));
    const std::string results = read_text(dir.file("out/results.json"));
    std::set<std::string> images;
    for (const OddName& n : odd_names()) {
        ASSERT_TRUE(s.count(n.shown)) << n.shown;
        const json& student = s.at(n.shown);
        EXPECT_EQ(student["score"], 100) << n.shown << ": " << student["broken"];
        EXPECT_NE(csv.find("\n" + n.shown + ",100,100,pass,"), std::string::npos) << n.shown << "\n" << csv;
        EXPECT_NE(html.find(">" + n.shown + "</td>"), std::string::npos) << n.shown;
        const std::string quoted = json(n.shown).dump();  // "name", JSON-escaped
        EXPECT_NE(results.find(quoted.substr(0, quoted.size() - 1) + ": image"), std::string::npos) << n.shown;
        EXPECT_NE(("\n" + run.err).find("\nm3055: " + n.shown + ": 100 / 100 pass"), std::string::npos) << n.shown << "\n" << run.err;
        // Its images exist, under a name of its own that any disk can hold.
        const std::string render = student["images"]["render"], diff = student["images"]["diff"];
        EXPECT_TRUE(file_exists(dir.file("out/" + render))) << render;
        EXPECT_TRUE(file_exists(dir.file("out/" + diff))) << diff;
        ASSERT_EQ(render.compare(0, 9, "students/"), 0) << render;
        ASSERT_EQ(diff.compare(0, 6, "diffs/"), 0) << diff;
        const std::string file = render.substr(9);
        EXPECT_EQ(diff.substr(6), file);
        EXPECT_LE(file.size(), 255u);
        // No newline, backslash, slash or percent; a space only inside, as in the name.
        EXPECT_EQ(file.find_first_of("\n\\/%"), std::string::npos) << file;
        EXPECT_NE(file.front(), ' ');
        std::string folded = file;
        for (char& c : folded) c = char(std::tolower(static_cast<unsigned char>(c)));
        EXPECT_TRUE(images.insert(folded).second) << "two students' images differ only by case: " << render;
    }
    // The render is the student's own: byte-identical to `m3055 render` of the scene.
    ASSERT_EQ(run_m3055({"render", "--scene", dir.file("subs/caf\xE9 latin1.json"), "--out", dir.file("r.png")}).exit_code, 0);
    EXPECT_EQ(read_text(dir.file("r.png")), read_text(dir.file("out/" + s.at("caf\\xE9 latin1")["images"]["render"].get<std::string>())));
}

TEST(GradeClass, OneOddNameNeverCostsTheOthersTheirTables) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/bob.json"), weaker_scene());
    write_text(dir.file("subs/caf\xE9.json"), "{ not json");
    write_text(dir.file("subs/\xFF\xFE.json"), good_scene());
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s.at("bob")["score"], 50);  // dave's scene
    EXPECT_EQ(s.at("caf\\xE9")["score"], 0);
    // Its reason names the file, escaped as everywhere else.
    EXPECT_NE(s.at("caf\\xE9")["broken"].get<std::string>().find("caf\\xE9.json"), std::string::npos)
        << s.at("caf\\xE9")["broken"];
    EXPECT_EQ(s.at("\\xFF\\xFE")["score"], 100);
    EXPECT_TRUE(file_exists(dir.file("out/grades.csv")));
    EXPECT_TRUE(file_exists(dir.file("out/report.html")));
}

TEST(GradeClass, OneFileWithALatin1NameIsGradedAsInTheFolder) {
    TempDir dir;
    write_text(dir.file("caf\xE9.json"), good_scene());
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("caf\xE9.json"), "--out", dir.file("out"),
                                     "--gradescope", dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_EQ(s.at("caf\\xE9")["score"], 100);
    EXPECT_EQ(read_json(dir.file("out/results.json"))["score"], 100);
}

TEST(GradeClass, ShardsOfOddNamesMergeToTheUnshardedBytes) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    for (const OddName& n : odd_names()) write_text(dir.file("subs/" + n.bytes + ".json"), weaker_scene());
    // Bytewise order and escaped order differ here: '\xE9' sorts after 'z', its escape before.
    write_text(dir.file("subs/b\xE9.json"), good_scene());
    write_text(dir.file("subs/b\\y.json"), good_scene());
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("whole")}).exit_code, 0);
    std::vector<std::string> shards;
    for (int k = 1; k <= 3; ++k) {
        shards.push_back(dir.file("shard" + std::to_string(k)));
        const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", shards.back(), "--shard",
                                         std::to_string(k) + "/3"});
        ASSERT_EQ(run.exit_code, 0) << run.err;
    }
    std::vector<std::string> merge = {"grade", "--merge", shards[2], shards[0], shards[1], "--out", dir.file("merged")};
    const RunResult merged = run_m3055(merge);
    ASSERT_EQ(merged.exit_code, 0) << merged.err;
    for (const char* table : {"grades.csv", "grades.json", "report.html"})
        EXPECT_EQ(read_text(dir.file(std::string("merged/") + table)), read_text(dir.file(std::string("whole/") + table)))
            << table;
    EXPECT_EQ(snapshot(dir.file("merged")), snapshot(dir.file("whole"), ".shader-cache"));
}

std::string write_assignment(TempDir& dir, const std::string& name, const std::function<void(json&)>& change);

// Runs m3055 from `cwd` through the shell; the exit status.
int run_in(const std::string& cwd, const std::string& args) {
    return std::system(("cd '" + cwd + "' && " + std::string(M3055_BINARY) + " " + args + " 2>/dev/null").c_str());
}

TEST(GradeClass, ShardsRunFromDifferentFoldersMergeToTheUnshardedBytes) {
    TempDir dir;
    fs::create_directories(dir.file("class/subs"));
    fs::create_directories(dir.file("elsewhere/deeper"));
    for (int i = 0; i < 5; ++i)
        write_text(dir.file("class/subs/s" + std::to_string(i) + ".json"), i == 3 ? "{ broken" : good_scene_variant(i));
    fs::create_directories(dir.file("class/subs/f"));  // a folder without scene.json: its reason names the file
    ASSERT_EQ(run_in(dir.path(), "grade " + kAssignment + " class/subs --out whole"), 0);
    // The same class spelled three ways, from three working folders.
    ASSERT_EQ(run_in(dir.file("class"), "grade " + kAssignment + " subs/ --out ../s1 --shard 1/3"), 0);
    ASSERT_EQ(run_in(dir.file("elsewhere/deeper"), "grade " + kAssignment + " ../../class/subs --out ../../s2 --shard 2/3"), 0);
    ASSERT_EQ(run_in(dir.file("class/subs"), "grade " + kAssignment + " " + dir.file("class/subs") + " --out ../../s3 --shard 3/3"), 0);
    ASSERT_EQ(run_in(dir.path(), "grade --merge s2 s3 s1 --out merged"), 0);
    EXPECT_EQ(snapshot(dir.file("merged")), snapshot(dir.file("whole"), ".shader-cache"));
    const std::string csv = read_text(dir.file("whole/grades.csv"));
    EXPECT_NE(csv.find("s3,0,100,refused,\"s3.json: invalid JSON"), std::string::npos) << csv;
    EXPECT_NE(csv.find("f,0,100,refused,f/scene.json: missing"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("subs"), std::string::npos) << "no path the teacher typed: " << csv;
}

TEST(GradeClass, MergeRefusesAShardOfAnotherClassOrAnotherReferenceNamingIt) {
    TempDir dir;
    for (const char* cls : {"a", "b"}) {
        fs::create_directories(dir.file(std::string(cls)));
        for (int i = 0; i < 4; ++i)
            write_text(dir.file(std::string(cls) + "/s" + std::to_string(i) + ".json"),
                       good_scene_variant(i + (cls[0] == 'b' && i == 2 ? 10 : 0)));  // b: one file differs
    }
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("a"), "--out", dir.file("a1"), "--shard", "1/2"}).exit_code, 0);
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("b"), "--out", dir.file("b2"), "--shard", "2/2"}).exit_code, 0);
    const RunResult other_class = run_m3055({"grade", "--merge", dir.file("a1"), dir.file("b2"), "--out", dir.file("m")});
    EXPECT_EQ(other_class.exit_code, 1);
    EXPECT_NE(other_class.err.find("b2: graded another class folder than"), std::string::npos) << other_class.err;
    // The same assignment file, its reference edited in between: another assignment.
    TempDir copy;
    const std::string a = write_assignment(copy, "a.json", [](json&) {});
    ASSERT_EQ(run_m3055({"grade", a, dir.file("a"), "--out", dir.file("x1"), "--shard", "1/2"}).exit_code, 0);
    json reference = read_json(copy.file("reference.json"));
    reference["background"] = {0.2, 0.1, 0.1};
    write_text(copy.file("reference.json"), reference.dump());
    ASSERT_EQ(run_m3055({"grade", a, dir.file("a"), "--out", dir.file("x2"), "--shard", "2/2"}).exit_code, 0);
    const RunResult other_reference = run_m3055({"grade", "--merge", dir.file("x1"), dir.file("x2"), "--out", dir.file("m")});
    EXPECT_EQ(other_reference.exit_code, 1);
    EXPECT_NE(other_reference.err.find("x2: graded another assignment than"), std::string::npos) << other_reference.err;
    EXPECT_FALSE(fs::exists(dir.file("m/grades.json")));
}

TEST(GradeClass, MergeRefusesShardsOfClassesOfOtherSizes) {
    TempDir dir;
    fs::create_directories(dir.file("big"));
    fs::create_directories(dir.file("small"));
    for (int i = 0; i < 6; ++i) write_text(dir.file("big/" + std::string(1, char('a' + i)) + ".json"), good_scene_variant(i));
    for (int i = 0; i < 2; ++i) write_text(dir.file("small/" + std::string(1, char('a' + i)) + ".json"), good_scene_variant(i));
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("big"), "--out", dir.file("s1"), "--shard", "1/2"}).exit_code, 0);
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("small"), "--out", dir.file("s2"), "--shard", "2/2"}).exit_code, 0);
    const RunResult merged = run_m3055({"grade", "--merge", dir.file("s1"), dir.file("s2"), "--out", dir.file("m")});
    EXPECT_EQ(merged.exit_code, 1);
    // The class fingerprints differ (other names and files), which the merge says first.
    EXPECT_NE(merged.err.find("s2: graded another class folder than"), std::string::npos) << merged.err;
    EXPECT_FALSE(file_exists(dir.file("m/grades.json")));
}

TEST(GradeClass, BatchReportIsWrittenForALatin1SceneName) {
    TempDir dir;
    fs::create_directories(dir.file("class"));
    write_text(dir.file("class/caf\xE9.json"), good_scene());
    write_text(dir.file("class/plain.json"), good_scene());
    const RunResult run = run_m3055(
        {"batch", dir.file("class"), "--out", dir.file("renders"), "--report", dir.file("report.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const json report = read_json(dir.file("report.json"));
    ASSERT_EQ(report.size(), 2u);
    EXPECT_EQ(report[0]["scene"], grading::shown_name(dir.file("class/caf\xE9.json")));
    EXPECT_EQ(report[0]["status"], "ok");
    EXPECT_TRUE(file_exists(dir.file("renders/caf\xE9.png")));
}

// A folder submission NAME/ whose first object's material is the .brdf at `file`.
void write_brdf_scene(const std::string& folder, const std::string& file) {
    fs::create_directories(folder);
    json scene = json::parse(good_scene());
    scene["objects"][0]["material"] = {{"model", "brdf"}, {"file", file}};
    write_text(folder + "/scene.json", scene.dump());
}

TEST(GradeClass, BrdfFilesOutsideTheSubmissionAreRefusedUnreadNamingTheField) {
    TempDir dir;
    const std::string subs = dir.file("subs");
    // Files a hostile scene would like to show: one outside the class, one a classmate's.
    write_text(dir.file("secret.brdf"), "TOPSECRET outside the class\n");
    fs::create_directories(subs + "/victim");
    write_text(subs + "/victim/victim.brdf", "TOPSECRET of a classmate\n");
    write_text(subs + "/victim/scene.json", good_scene());
    write_brdf_scene(subs + "/absolute", "/etc/passwd");
    write_brdf_scene(subs + "/absolute2", dir.file("secret.brdf"));
    write_brdf_scene(subs + "/dotdot", "../victim/victim.brdf");
    write_brdf_scene(subs + "/inner_dotdot", "sub/../../victim/victim.brdf");
    write_brdf_scene(subs + "/link_out", "evil.brdf");
    fs::create_symlink(dir.file("secret.brdf"), subs + "/link_out/evil.brdf");
    write_brdf_scene(subs + "/folder_link", "d/victim.brdf");
    fs::create_directory_symlink(subs + "/victim", subs + "/folder_link/d");
    write_text(subs + "/flat.json", [] {
        json scene = json::parse(good_scene());
        scene["objects"][0]["material"] = {{"model", "brdf"}, {"file", "victim/victim.brdf"}};
        return scene.dump();
    }());
    // Its own .brdf, in a folder of its own folder: graded.
    write_brdf_scene(subs + "/own", "shaders/lambert.brdf");
    fs::create_directories(subs + "/own/shaders");
    fs::copy_file(source_path("tests/data/brdf/lambert.brdf"), subs + "/own/shaders/lambert.brdf");

    const RunResult run = run_m3055({"grade", kAssignment, subs, "--out", dir.file("out"), "--allow-brdf", "--gradescope",
                                     dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    const std::map<std::string, std::string> refused = {
        {"absolute", "objects[0].material.file: must be a path inside the submission's folder, not an absolute path"},
        {"absolute2", "objects[0].material.file: must be a path inside the submission's folder, not an absolute path"},
        {"dotdot", "objects[0].material.file: must be a path inside the submission's folder, without \"..\""},
        {"inner_dotdot", "objects[0].material.file: must be a path inside the submission's folder, without \"..\""},
        {"link_out", "objects[0].material.file: leads out of the submission's folder (a symbolic link)"},
        {"folder_link", "objects[0].material.file: leads out of the submission's folder (a symbolic link)"},
        {"flat", "objects[0].material.file: a .brdf file is not accepted here: a submission that names a file (a "
                 ".brdf material, a model) is a folder NAME/ holding scene.json and the file"},
    };
    for (const auto& [name, reason] : refused) {
        ASSERT_TRUE(s.count(name)) << name;
        EXPECT_EQ(s.at(name)["score"], 0) << name;
        EXPECT_NE(s.at(name)["broken"].get<std::string>().find(reason), std::string::npos)
            << name << ": " << s.at(name)["broken"];
    }
    EXPECT_EQ(s.at("own")["broken"], "");
    // Not a byte of those files in any output, nor on the console.
    for (const std::string& text : {read_text(dir.file("out/grades.csv")), read_text(dir.file("out/grades.json")),
                                    read_text(dir.file("out/report.html")), read_text(dir.file("out/results.json")),
                                    run.err, run.out}) {
        EXPECT_EQ(text.find("TOPSECRET"), std::string::npos);
        EXPECT_EQ(text.find("root:"), std::string::npos);
    }
}

// Copies `brdf` (of tests/data/brdf/) into `folder` and writes a scene.json using it.
void write_brdf_folder(const std::string& folder, const std::string& brdf) {
    write_brdf_scene(folder, brdf);
    fs::copy_file(source_path("tests/data/brdf/" + brdf), folder + "/" + brdf);
}

// The number N of "N pixels are NaN" in `text`, or -1.
long nan_pixels_in(const std::string& text) {
    const std::size_t at = text.find(" pixels are NaN");
    if (at == std::string::npos) return -1;
    std::size_t start = at;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(text[start - 1]))) --start;
    return start == at ? -1 : std::stol(text.substr(start, at - start));
}

TEST(GradeClass, NonFinitePixelsFailTheImageCheckEvenWhenTheyMatchTheReference) {
    TempDir dir;
    // The reference is the NaN scene itself: its levels match, byte for byte,
    // so only the NaN check can take the image points away.
    write_brdf_folder(dir.file("ref"), "broken_sqrt.brdf");
    write_text(dir.file("a.json"), json{{"title", "NaN"},
                                        {"reference", "ref/scene.json"},
                                        {"image", {{"points", 40}, {"fail_levels", 1}, {"fail_percent", 1}}},
                                        {"rules", json::array({{{"rule", "light_count"}, {"equals", 3}, {"points", 10}}})}}
                                       .dump());
    write_brdf_folder(dir.file("subs/nan"), "broken_sqrt.brdf");
    write_brdf_folder(dir.file("subs/fine"), "lambert.brdf");
    const RunResult run =
        run_m3055({"grade", dir.file("a.json"), dir.file("subs"), "--out", dir.file("out"), "--allow-brdf"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    const json& nan = s.at("nan");
    EXPECT_EQ(nan["comparison"]["same_pixels"], nan["comparison"]["pixels"]) << "the levels match the reference";
    EXPECT_EQ(nan["checks"][0]["ok"], false);
    EXPECT_EQ(nan["checks"][0]["earned"], 0);
    EXPECT_EQ(nan["score"], 10);
    const std::string reason = nan["checks"][0]["reason"];
    const long count = nan_pixels_in(reason);
    EXPECT_GT(count, 100) << reason;
    EXPECT_NE(reason.find("in the render (a material gives values that are not numbers): no image points"),
              std::string::npos)
        << reason;
    EXPECT_EQ(s.at("fine")["checks"][0]["reason"].get<std::string>().find("NaN"), std::string::npos);

    // render and batch warn with the same count, write the image and exit 0.
    const RunResult render = run_m3055({"render", "--scene", dir.file("subs/nan/scene.json"), "--out", dir.file("r.png")});
    EXPECT_EQ(render.exit_code, 0) << render.err;
    EXPECT_TRUE(file_exists(dir.file("r.png")));
    EXPECT_NE(render.err.find("m3055: warning: "), std::string::npos) << render.err;
    EXPECT_EQ(nan_pixels_in(render.err), count) << render.err;
    const RunResult fine = run_m3055({"render", "--scene", dir.file("subs/fine/scene.json"), "--out", dir.file("f.png")});
    EXPECT_EQ(fine.exit_code, 0) << fine.err;
    EXPECT_EQ(fine.err.find("warning"), std::string::npos) << fine.err;
    fs::copy_file(dir.file("subs/nan/scene.json"), dir.file("subs/nan/nan.json"));
    fs::copy_file(dir.file("subs/fine/scene.json"), dir.file("subs/fine/fine.json"));
    const RunResult batch = run_m3055({"batch", dir.file("subs/nan/nan.json"), dir.file("subs/fine/fine.json"),
                                       "--out", dir.file("b"), "--report", dir.file("b.json"), "--allow-brdf"});
    EXPECT_EQ(batch.exit_code, 0) << batch.err;
    EXPECT_EQ(nan_pixels_in(batch.err), count) << batch.err;
    const json report = read_json(dir.file("b.json"));
    ASSERT_EQ(report.size(), 2u);
    for (const json& entry : report) {
        EXPECT_EQ(entry["status"], "ok");
        const bool is_nan = entry["scene"].get<std::string>().find("/nan/") != std::string::npos;
        EXPECT_EQ(nan_pixels_in(entry["warning"]), is_nan ? count : -1) << entry;
    }
}

// A class folder with what a real class hands in beside its scenes.
struct StrayClass {
    TempDir dir;
    std::string subs = dir.file("subs");
    StrayClass() {
        fs::create_directories(subs);
        fs::create_directories(dir.file("outside"));
        write_text(subs + "/alice.json", good_scene());
        write_text(subs + "/copycat.json", good_scene());       // alice's file, byte for byte
        write_text(subs + "/Upper.JSON", weaker_scene());       // from Windows: graded as "Upper"
        write_text(subs + "/notes.json.txt", good_scene());     // not a .json
        write_text(subs + "/trailing.json ", good_scene());     // a space after .json
        write_text(subs + "/.DS_Store", "junk");
        write_text(dir.file("outside/o.json"), good_scene());
        fs::create_symlink("../outside/o.json", subs + "/linkout.json");
        fs::create_symlink("alice.json", subs + "/linkin.json");
        fs::create_symlink("nowhere", subs + "/dangling");
        fs::create_directories(subs + "/folderlink");
        fs::create_symlink("../../outside/o.json", subs + "/folderlink/scene.json");
        fs::create_directories(subs + "/pat");
        write_text(subs + "/pat/scene.json", good_scene());
        write_text(subs + "/pat.json", good_scene());
    }
};

TEST(GradeClass, LinksAreRefusedUnlessFollowedInsideAndStraysAreListed) {
    StrayClass c;
    const RunResult run = run_m3055({"grade", kAssignment, c.subs, "--out", c.dir.file("out")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const json grades = read_json(c.dir.file("out/grades.json"));
    const auto s = by_student(grades);
    // Rows: every .json in any case, every folder; pat once.
    std::vector<std::string> names;
    for (const json& student : grades["students"]) names.push_back(student["student"]);
    EXPECT_EQ(names, (std::vector<std::string>{"Upper", "alice", "copycat", "folderlink", "linkin", "linkout", "pat"}));
    EXPECT_EQ(s.at("Upper")["score"], 50);
    for (const char* link : {"linkin", "linkout"})
        EXPECT_EQ(s.at(link)["broken"], std::string(link) + ".json: a symbolic link: refused (m3055 grade "
                                          "--follow-symlinks grades links that stay inside the submissions folder)");
    EXPECT_NE(s.at("folderlink")["broken"].get<std::string>().find("folderlink/scene.json: a symbolic link: refused"),
              std::string::npos);
    EXPECT_EQ(s.at("pat")["broken"], "pat: submitted twice (as a file and as a folder): one submission a student");
    // What was not graded, listed with why, in grades.json, the report and on the console.
    const json expected_ignored = json::parse(R"j([
        {"name": ".DS_Store", "why": "hidden (its name starts with \".\")"},
        {"name": "dangling", "why": "a broken symbolic link"},
        {"name": "notes.json.txt", "why": "not a .json file nor a folder: the name does not end in .json"},
        {"name": "trailing.json ", "why": "not a .json file nor a folder: the name does not end in .json"}])j");
    EXPECT_EQ(grades["folder"]["ignored"], expected_ignored);
    const std::string html = read_text(c.dir.file("out/report.html"));
    for (const json& entry : expected_ignored) {
        EXPECT_NE(html.find("<code>" + entry["name"].get<std::string>() + "</code>"), std::string::npos) << entry;
        EXPECT_NE(run.err.find("  " + entry["name"].get<std::string>() + ": "), std::string::npos) << run.err;
    }
    EXPECT_NE(run.err.find("not graded: 4 entries of the folder"), std::string::npos) << run.err;
    // Identical files: listed together, no penalty.
    EXPECT_EQ(grades["folder"]["identical"], json::parse(R"([["alice", "copycat"]])"));
    EXPECT_EQ(s.at("copycat")["score"], 100);
    EXPECT_EQ(s.at("copycat")["notes"], json::parse(R"(["its scene file is byte-identical to that of alice"])"));
    EXPECT_NE(html.find("Byte-identical submissions"), std::string::npos);
    EXPECT_NE(run.err.find("byte-identical submissions: alice, copycat"), std::string::npos) << run.err;

    // --follow-symlinks: a link inside is graded with a note, one out still refused.
    const RunResult follow = run_m3055({"grade", kAssignment, c.subs, "--out", c.dir.file("follow"), "--follow-symlinks"});
    ASSERT_EQ(follow.exit_code, 0) << follow.err;
    const auto f = by_student(read_json(c.dir.file("follow/grades.json")));
    EXPECT_EQ(f.at("linkin")["score"], 100);
    EXPECT_EQ(f.at("linkin")["notes"][0], "linkin.json is a symbolic link to alice.json");
    EXPECT_EQ(f.at("linkout")["broken"], "linkout.json: a symbolic link out of the submissions folder: refused");
    EXPECT_EQ(f.at("folderlink")["broken"], "folderlink/scene.json: a symbolic link out of the submissions folder: refused");
}

TEST(GradeClass, RosterGivesMissingStudentsARowAndFlagsStrangers) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/alice.json"), good_scene());
    write_text(dir.file("subs/mallory.json"), good_scene());
    write_text(dir.file("subs/caf\xE9.json"), weaker_scene());
    // Saved on Windows: CRLF, a blank line, a Latin-1 name.
    write_text(dir.file("roster.txt"), "alice\r\nzed\r\n\r\ncaf\xE9\r\n");
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out"), "--roster",
                                     dir.file("roster.txt"), "--gradescope", dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const json grades = read_json(dir.file("out/grades.json"));
    const auto s = by_student(grades);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s.at("zed")["missing"], true);
    EXPECT_EQ(s.at("zed")["score"], 0);
    EXPECT_EQ(s.at("zed")["reasons"], json::parse(R"(["no submission"])"));
    EXPECT_EQ(s.at("mallory")["score"], 100);
    EXPECT_EQ(s.at("mallory")["notes"][0], "not on the roster");
    EXPECT_EQ(s.at("alice")["notes"], json::parse(R"(["its scene file is byte-identical to that of mallory"])"));
    EXPECT_EQ(s.at("caf\\xE9")["missing"], false);
    EXPECT_EQ(s.at("caf\\xE9")["score"], 50);
    const std::string csv = read_text(dir.file("out/grades.csv"));
    EXPECT_NE(csv.find("\nzed,0,100,missing,no submission,\n"), std::string::npos) << csv;
    EXPECT_NE(run.err.find("m3055: 3 submissions: 2 passed, 1 failed, 0 refused (not graded); 1 on the roster with no "
                           "submission"),
              std::string::npos)
        << run.err;
    EXPECT_NE(read_text(dir.file("out/report.html"))
                  .find("<p>3 submissions: 2 passed (at least 60 of 100 points), 1 failed, 0 refused (not graded); 1 on "
                        "the roster with no submission."),
              std::string::npos);
    // A roster that is not one: one line naming the file and the line, nothing written.
    write_text(dir.file("bad.txt"), "alice\nbob\nalice\n");
    const RunResult bad = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("bad"), "--roster",
                                     dir.file("bad.txt")});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("bad.txt:3: \"alice\" is on the roster twice"), std::string::npos) << bad.err;
    EXPECT_FALSE(file_exists(dir.file("bad/grades.json")));
}

TEST(GradeClass, NoStudentNameClashesWithAnOutputOrAnotherStudent) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    const std::vector<std::string> names = {"reference", "grades", "report", "results", "students", "diffs",
                                            "alice",     "alice-diff", "feedback"};
    for (std::size_t i = 0; i < names.size(); ++i)
        write_text(dir.file("subs/" + names[i] + ".json"), good_scene_variant(int(i)));
    write_text(dir.file("subs/bob.json"), weaker_scene());
    const RunResult run = run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out"), "--gradescope",
                                     dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    ASSERT_EQ(s.size(), names.size() + 1);
    for (const std::string& name : names) {
        EXPECT_EQ(s.at(name)["score"], 100) << name << ": " << s.at(name)["broken"];
        // Its render is its own scene's, not overwritten by anything else of the run.
        ASSERT_EQ(run_m3055({"render", "--scene", dir.file("subs/" + name + ".json"), "--out", dir.file("r.png")}).exit_code, 0);
        EXPECT_EQ(read_text(dir.file("out/students/" + name + ".png")), read_text(dir.file("r.png"))) << name;
    }
    EXPECT_TRUE(file_exists(dir.file("out/reference.png")));
    EXPECT_TRUE(file_exists(dir.file("out/diffs/alice.png")));
    EXPECT_NE(read_text(dir.file("out/diffs/bob.png")), read_text(dir.file("out/diffs/alice.png")));
    EXPECT_EQ(read_json(dir.file("out/results.json"))["tests"].size(), (names.size() + 1) * 7);
}

TEST(GradeClass, ImagesOfStudentsNoLongerInTheClassAreRemovedAndNothingElse) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/alice.json"), good_scene());
    write_text(dir.file("subs/leaver.json"), weaker_scene());
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    ASSERT_TRUE(file_exists(dir.file("out/students/leaver.png")));
    write_text(dir.file("out/notes.txt"), "the teacher's");
    write_text(dir.file("out/students/readme.txt"), "the teacher's too");
    fs::remove(dir.file("subs/leaver.json"));
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    EXPECT_FALSE(file_exists(dir.file("out/students/leaver.png")));
    EXPECT_FALSE(file_exists(dir.file("out/diffs/leaver.png")));
    EXPECT_TRUE(file_exists(dir.file("out/students/alice.png")));
    EXPECT_TRUE(file_exists(dir.file("out/notes.txt")));
    EXPECT_TRUE(file_exists(dir.file("out/students/readme.txt")));
}

TEST(GradeClass, ScoresAreRoundedToHundredthsInEveryOutput) {
    TempDir dir;
    json assignment = read_json(kAssignment);
    assignment["reference"] = kAssignment.substr(0, kAssignment.rfind('/')) + "/reference.json";
    assignment.erase("start");  // beside the worked assignment, not this copy
    assignment["image"]["points"] = 40;
    assignment["rules"] = json::parse(R"([{"rule": "light_count", "equals": 3, "points": 0.1},
                                          {"rule": "model", "is": "metal", "points": 0.2}])");
    assignment.erase("pass");
    write_text(dir.file("a.json"), assignment.dump());
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/alice.json"), good_scene());  // 40 + 0.1 + 0.2, 40.300000000000004 unrounded
    const RunResult run = run_m3055({"grade", dir.file("a.json"), dir.file("subs"), "--out", dir.file("out"),
                                     "--gradescope", dir.file("out/results.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(read_text(dir.file("out/grades.csv")).find("\nalice,40.3,40.3,pass,"), std::string::npos);
    for (const char* file : {"out/grades.json", "out/results.json", "out/report.html"})
        EXPECT_EQ(read_text(dir.file(file)).find("40.30000"), std::string::npos) << file;
    EXPECT_EQ(read_json(dir.file("out/grades.json"))["students"][0]["score"].dump(), "40.3");
    EXPECT_NE(run.err.find("alice: 40.3 / 40.3 pass"), std::string::npos) << run.err;
}

TEST(GradeClass, UsageErrorsExitTwoAndWriteNothing) {
    TempDir dir;
    const std::vector<std::vector<std::string>> usages = {
        {"grade", kAssignment, "--out", dir.file("out")},
        {"grade", kAssignment, kSubmissions, "--out", dir.file("out"), "--shard", "5/4"},
        {"grade", kAssignment, kSubmissions, "--out", dir.file("out"), "--shard", "x"},
        {"grade", kAssignment, kSubmissions, "--merge", dir.file("a"), "--out", dir.file("out")},
        {"grade", kAssignment, dir.file("no such folder"), "--out", dir.file("out")},
        {"grade", dir.file("no such assignment.json"), kSubmissions, "--out", dir.file("out")},
        {"grade", "--check", dir.file("no such assignment.json")},
        {"batch", kSubmissions + "/alice.json", kSubmissions + "/bob.json"},
        {"batch", kSubmissions, "--out", dir.file("out"), "--shard", "0/2"},
    };
    for (const auto& args : usages) {
        const RunResult run = run_m3055(args);
        EXPECT_EQ(run.exit_code, 2) << args[0] << " " << args.back() << ": " << run.err;
        EXPECT_FALSE(fs::exists(dir.file("out")));
    }
}

// Bare `m3055 grade`: the usage, and what to give, exit 2.
TEST(GradeClass, BareGradePrintsTheUsage) {
    const RunResult run = run_m3055({"grade"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("Usage: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("--merge"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("\nm3055: grade: give ASSIGNMENT.json SUBMISSIONS/ --out DIR"), std::string::npos) << run.err;
}

TEST(GradeClass, CountsInMessagesAreSingularForOne) {
    TempDir dir;
    json assignment = read_json(kAssignment);
    // A reference with two spheres, so that the rule on objects[1] is one the assignment may have.
    json reference = json::parse(good_scene());
    reference["objects"].push_back(reference["objects"][0]);
    reference["objects"][1]["center"] = {1.5, 0, 0};
    reference["objects"][1]["radius"] = 0.3;
    write_text(dir.file("reference.json"), reference.dump());
    assignment["reference"] = "reference.json";
    assignment.erase("start");
    assignment["rules"] = json::parse(R"([{"rule": "light_count", "equals": 3, "points": 10},
                                          {"rule": "model", "object": 1, "is": "metal", "points": 10}])");
    assignment.erase("pass");
    write_text(dir.file("a.json"), assignment.dump());
    json scene = json::parse(good_scene());
    scene["lights"] = json::array({scene["lights"][0]});
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/solo.json"), scene.dump());
    ASSERT_EQ(run_m3055({"grade", dir.file("a.json"), dir.file("subs"), "--out", dir.file("one"), "--shard", "1/1"}).exit_code, 0);
    const std::string reasons = read_text(dir.file("one/grades.csv"));
    EXPECT_NE(reasons.find("1 light enabled, not 3"), std::string::npos) << reasons;
    EXPECT_NE(reasons.find("(the scene has 1 object)"), std::string::npos) << reasons;
    const RunResult merged = run_m3055({"grade", "--merge", dir.file("one"), "--out", dir.file("merged")});
    EXPECT_NE(merged.err.find("merged 1 shard, 1 submission into"), std::string::npos) << merged.err;
}

// The worked assignment with `change` applied, written beside a copy of its reference.
std::string write_assignment(TempDir& dir, const std::string& name, const std::function<void(json&)>& change) {
    const std::string folder = kAssignment.substr(0, kAssignment.rfind('/'));
    if (!file_exists(dir.file("reference.json"))) fs::copy_file(folder + "/reference.json", dir.file("reference.json"));
    json assignment = read_json(kAssignment);
    assignment["reference"] = "reference.json";
    assignment.erase("start");
    change(assignment);
    write_text(dir.file(name), assignment.dump());
    return dir.file(name);
}

TEST(GradeCheck, TheWorkedAssignmentsPassTheirOwnCheck) {
    for (const std::string& assignment : {kAssignment, source_path("assignments/vase-softbox/assignment.json")}) {
        const RunResult run = run_m3055({"grade", "--check", assignment});
        EXPECT_EQ(run.exit_code, 0) << run.err;
        EXPECT_NE(run.err.find("assignment.json: 0 errors; the reference scores 100 of 100 points"), std::string::npos)
            << run.err;
    }
}

TEST(GradeCheck, EveryStructuralErrorIsOneLineNamingTheFieldAndGradeRefusesTheAssignment) {
    TempDir dir;
    const std::string bad = write_assignment(dir, "bad.json", [](json& a) {
        a["image"]["fail_levels"] = 40;
        a["rules"] = json::parse(R"([
            {"rule": "model", "is": "metall", "points": 10},
            {"rule": "range", "path": "objects[0].material.dd", "min": 0, "max": 1, "points": 10},
            {"rule": "range", "path": "objects[0].material", "min": 0, "max": 1, "points": 10},
            {"rule": "eq14", "object": 5, "within_percent": 1, "points": 10},
            {"rule": "model", "object": 1, "is": "metal", "points": 10},
            {"rule": "warmer", "light": "sun", "than": "fill", "points": 10}])");
        a.erase("pass");
    });
    const RunResult check = run_m3055({"grade", "--check", bad});
    EXPECT_EQ(check.exit_code, 1);
    for (const std::string line : {
             "bad.json: image.fail_levels: 40 allows every difference on the reference's 5-bit display (at most 31 levels)",
             "bad.json: rules[0].is: unknown model \"metall\": not one of the model names below",
             "bad.json: rules[1].path: \"objects[0].material.dd\" is not in the reference scene",
             "bad.json: rules[2].path: \"objects[0].material\" is not a number in the reference scene",
             "bad.json: rules[3].object: no objects[5] in the reference scene (it has 1 object)",
             "bad.json: rules[4].object: no objects[1] in the reference scene (it has 1 object)",
             "bad.json: rules[5].light: no light named \"sun\" in the reference scene (its lights: \"key\", \"fill\", \"back\")",
             "bad.json: 7 errors; the reference scores 40 of 100 points"})
        EXPECT_NE(check.err.find(line), std::string::npos) << line << "\n" << check.err;
    const RunResult grade = run_m3055({"grade", bad, kSubmissions, "--out", dir.file("out")});
    EXPECT_EQ(grade.exit_code, 1);
    EXPECT_NE(grade.err.find("bad.json: 7 errors in the assignment (m3055 grade --check): nothing graded"),
              std::string::npos) << grade.err;
    EXPECT_FALSE(fs::exists(dir.file("out")));
}

// Structure, ranges and meaning in one run: every problem once, the rule
// with a structural error not checked again against the reference, and
// `grade` refusing with the same lines.
TEST(GradeCheck, EveryErrorAtOnceEachOnce) {
    TempDir dir;
    const std::string bad = write_assignment(dir, "bad.json", [](json& a) {
        a["extra"] = 1;                     // structure
        a["image"]["fail_percent"] = 101;   // range
        a["rules"] = json::parse(R"([
            {"rule": "eq14", "object": 5, "within_percent": 1, "points": 10},
            {"rule": "light_count", "equals": 2.5, "points": 10},
            {"rule": "warmer", "light": "Key", "than": "fill", "points": 10}])");
        a.erase("pass");
    });
    const std::vector<std::string> lines = {
        "bad.json: extra: is not a field here\n",
        "bad.json: image.fail_percent: must be in [0, 100], got 101\n",
        "bad.json: rules[1].equals: must be a whole number, got 2.5\n",
        "bad.json: rules[0].object: no objects[5] in the reference scene (it has 1 object)\n",
        "bad.json: rules[2].light: no light named \"Key\" in the reference scene (its lights: \"key\", \"fill\", "
        "\"back\"); light names are case-sensitive\n"};
    const RunResult check = run_m3055({"grade", "--check", bad});
    EXPECT_EQ(check.exit_code, 1);
    for (const std::string& line : lines) EXPECT_EQ(count_of(check.err, line), 1u) << line << check.err;
    EXPECT_EQ(count_of(check.err, "rules[0]"), 1u) << "said once, not again as failed by the reference: " << check.err;
    EXPECT_NE(check.err.find("bad.json: 5 errors; "), std::string::npos) << check.err;
    const RunResult grade = run_m3055({"grade", bad, kSubmissions, "--out", dir.file("out")});
    EXPECT_EQ(grade.exit_code, 1);
    for (const std::string& line : lines) EXPECT_EQ(count_of(grade.err, line), 1u) << line << grade.err;
    EXPECT_FALSE(fs::exists(dir.file("out")));
}

// A start or reference file that is not there is an error naming its field;
// the other problems are still said.
TEST(GradeCheck, AMissingStartOrReferenceNamesItsField) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) {
        a["start"] = "start.json";
        a["rules"][0]["is"] = "metall";
    });
    const RunResult start = run_m3055({"grade", "--check", a});
    EXPECT_EQ(start.exit_code, 1);
    EXPECT_NE(start.err.find("a.json: start: " + dir.file("start.json") + ": cannot read file: No such file"),
              std::string::npos) << start.err;
    EXPECT_NE(start.err.find("a.json: rules[0].is: unknown model \"metall\""), std::string::npos) << start.err;
    fs::remove(dir.file("reference.json"));
    const RunResult reference = run_m3055({"grade", "--check", a});
    EXPECT_EQ(reference.exit_code, 1);
    EXPECT_NE(reference.err.find("a.json: reference: " + dir.file("reference.json") + ": cannot read file"),
              std::string::npos) << reference.err;
    EXPECT_NE(reference.err.find("a.json: start: "), std::string::npos) << reference.err;
    EXPECT_NE(reference.err.find("3 errors; the rules could not be checked against the reference"), std::string::npos)
        << reference.err;
}

// The model names an unknown one is checked against: every one, on a line of their own, never cut.
TEST(GradeCheck, ModelNamesAreListedWhole) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) { a["rules"][0]["is"] = "metall"; });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_NE(check.err.find("\nm3055: model names: highlight, translucent, metal, metal_blinn, metal_phong, lambert, "
                             "half_lambert, half_lambert_clamped, half_lambert_normalized, oren_nayar, minnaert, phong, "
                             "blinn_phong, microfacet, ward, heidrich_seidel, principled\n"),
              std::string::npos) << check.err;
}

// An "equals" rule on the conductor tells the measured gold the assignment
// asks for from an RGB gold that renders alike: the RGB one no longer scores
// full marks.
TEST(GradeCheck, AnEqualsRuleTellsMeasuredGoldFromAnRgbGold) {
    TempDir dir;
    json reference = read_json(kAssignment.substr(0, kAssignment.rfind('/')) + "/reference.json");
    reference["objects"][0]["material"].erase("color");
    reference["objects"][0]["material"]["conductor"] = "gold";
    write_text(dir.file("reference.json"), reference.dump());
    const std::string a = write_assignment(dir, "a.json", [](json& a) {
        a["image"]["fail_percent"] = 100;  // the image alone would not tell them apart
        a["image"]["points"] = 0;
        a["rules"] = json::parse(R"([{"rule": "model", "is": "metal", "points": 50},
            {"rule": "equals", "path": "objects[0].material.conductor", "value": "gold", "points": 50}])");
        a.erase("pass");
    });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 0) << check.err;
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/rgb.json"), good_scene());
    write_text(dir.file("subs/measured.json"), reference.dump());
    ASSERT_EQ(run_m3055({"grade", a, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    const auto s = by_student(read_json(dir.file("out/grades.json")));
    EXPECT_EQ(s.at("measured")["score"], 100);
    EXPECT_EQ(s.at("rgb")["score"], 50);
    EXPECT_EQ(s.at("rgb")["reasons"][0], "rules[1] (equals): objects[0].material.conductor: not in the scene, wanted \"gold\"");
}

// The "temperature" rule: its light must be one of the reference's, and
// a reference whose key is an RGB colour fails a kelvin range.
TEST(GradeCheck, TemperatureRuleNeedsALightOfTheReference) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) {
        a["rules"] = json::parse(R"([
            {"rule": "temperature", "light": "rim", "min": 3000, "max": 3400, "points": 10},
            {"rule": "temperature", "light": "key", "min": 3000, "max": 3400, "points": 10}])");
        a.erase("pass");
    });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    for (const std::string line : {
             "a.json: rules[0].light: no light named \"rim\" in the reference scene (its lights: \"key\", \"fill\", \"back\")",
             "a.json: rules[1] (temperature): the reference fails it: \"key\" has no \"temperature_k\" (an RGB colour), "
             "wanted [3000 K, 3400 K]"})
        EXPECT_NE(check.err.find(line), std::string::npos) << line << "\n" << check.err;
}

TEST(GradeCheck, ShadowRuleNeedsALightOfTheReference) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) {
        a["rules"] = json::parse(R"([{"rule": "shadow", "light": "Key", "points": 10},
                                     {"rule": "shadow", "light": "key", "points": 10}])");
        a.erase("pass");
    });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    for (const std::string line : {
             "a.json: rules[0].light: no light named \"Key\" in the reference scene (its lights: \"key\", \"fill\", "
             "\"back\"); light names are case-sensitive",
             "a.json: rules[1] (shadow): the reference fails it: \"key\" casts no shadows (its \"shadow\" is false)"})
        EXPECT_NE(check.err.find(line), std::string::npos) << line << "\n" << check.err;
}

TEST(GradeCheck, KeyToFillNeedsLightsNamedKeyAndFill) {
    TempDir dir;
    json reference = read_json(kAssignment.substr(0, kAssignment.rfind('/')) + "/reference.json");
    reference["lights"][0]["name"] = "main";
    write_text(dir.file("reference.json"), reference.dump());
    const std::string a = write_assignment(dir, "a.json", [](json&) {});
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_NE(check.err.find("key_to_fill compares the lights named \"key\" and \"fill\" (case-sensitive); the reference scene's "
                             "lights are \"main\", \"fill\", \"back\""),
              std::string::npos) << check.err;
}

TEST(GradeCheck, RulesTheReferenceFailsAreReportedAndZeroPointRulesAreFeedbackOnly) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) {
        a["rules"].push_back({{"rule", "light_count"}, {"equals", 2}, {"points", 5}});
        a["rules"].push_back({{"rule", "light_count"}, {"equals", 4}, {"points", 0}, {"name", "four lights?"}});
        a.erase("pass");
    });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_NE(check.err.find("a.json: rules[6] (light_count): the reference fails it: 3 lights enabled, not 2"),
              std::string::npos) << check.err;
    EXPECT_EQ(check.err.find("four lights?"), std::string::npos) << "a 0-point rule is feedback: " << check.err;
    EXPECT_NE(check.err.find("a.json: 0 errors; the reference scores 100 of 105 points"), std::string::npos) << check.err;
    // grade says so and grades all the same.
    const RunResult grade = run_m3055({"grade", a, kSubmissions, "--out", dir.file("out")});
    EXPECT_EQ(grade.exit_code, 0) << grade.err;
    EXPECT_NE(grade.err.find("m3055: warning: "), std::string::npos) << grade.err;
    EXPECT_TRUE(file_exists(dir.file("out/grades.json")));
}

TEST(GradeCheck, ATimeBudgetOfZeroIsRefused) {
    TempDir dir;
    const std::string a = write_assignment(dir, "a.json", [](json& a) { a["time_budget"] = 0; });
    const RunResult check = run_m3055({"grade", "--check", a});
    EXPECT_EQ(check.exit_code, 1);
    EXPECT_NE(check.err.find("a.json: time_budget: must be in (0, 3600] seconds, got 0"), std::string::npos) << check.err;
}

TEST(GradeRegion, ObjectsRegionLetsTheBackgroundChangeFreely) {
    TempDir dir;
    const std::string all = write_assignment(dir, "all.json", [](json&) {});
    const std::string objects = write_assignment(dir, "objects.json", [](json& a) { a["image"]["region"] = "objects"; });
    fs::create_directories(dir.file("subs"));
    json recoloured = json::parse(good_scene());
    recoloured["background"] = {0.6, 0.2, 0.2};
    write_text(dir.file("subs/recoloured.json"), recoloured.dump());
    write_text(dir.file("subs/weaker.json"), weaker_scene());
    ASSERT_EQ(run_m3055({"grade", all, dir.file("subs"), "--out", dir.file("all")}).exit_code, 0);
    const RunResult run = run_m3055({"grade", objects, dir.file("subs"), "--out", dir.file("objects")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto whole = by_student(read_json(dir.file("all/grades.json")));
    const auto region = by_student(read_json(dir.file("objects/grades.json")));
    // The whole picture: the new background costs the image points; the objects alone: it does not.
    EXPECT_EQ(whole.at("recoloured")["checks"][0]["ok"], false);
    EXPECT_EQ(region.at("recoloured")["checks"][0]["ok"], true) << region.at("recoloured")["checks"][0]["reason"];
    EXPECT_EQ(region.at("recoloured")["score"], 100);
    const json& c = region.at("recoloured")["comparison"];
    EXPECT_EQ(c["same_pixels"], c["pixels"]);
    EXPECT_GT(c["pixels"].get<long>(), 1000);
    EXPECT_LT(c["pixels"].get<long>(), 512 * 320 / 2) << "the sphere, not the whole display";
    // The display's own size, and which of its pixels were compared.
    EXPECT_EQ(c["width"], 512);
    EXPECT_EQ(c["height"], 320);
    EXPECT_EQ(c["region"], "objects");
    EXPECT_FALSE(whole.at("recoloured")["comparison"].contains("region"));
    const std::string reason = region.at("recoloured")["checks"][0]["reason"];
    EXPECT_EQ(reason.rfind("image: the objects' " + std::to_string(c["pixels"].get<long>()) + " pixels: 100.00 %", 0), 0u)
        << reason;
    // A wrong material still fails inside the region.
    EXPECT_EQ(region.at("weaker")["checks"][0]["ok"], false);
}

TEST(GradeRegion, RegionMustBeAllOrObjectsWithASceneReference) {
    TempDir dir;
    const std::string bad = write_assignment(dir, "bad.json", [](json& a) { a["image"]["region"] = "sphere"; });
    const RunResult run = run_m3055({"grade", "--check", bad});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_NE(run.err.find("bad.json: image.region: must be \"all\" or \"objects\", got \"sphere\""), std::string::npos)
        << run.err;
    ASSERT_EQ(run_m3055({"render", "--scene", dir.file("reference.json"), "--out", dir.file("ref.png")}).exit_code, 0);
    const std::string image = write_assignment(dir, "image.json", [](json& a) {
        a["reference"] = "ref.png";
        a["image"]["region"] = "objects";
    });
    const RunResult png = run_m3055({"grade", "--check", image});
    EXPECT_EQ(png.exit_code, 1);
    EXPECT_NE(png.err.find("image.json: image.region: \"objects\" needs a scene as the reference"), std::string::npos)
        << png.err;
}

// The page after Chromium ran its script (--dump-dom).
std::string dom_of(TempDir& dir, const std::string& page) {
    const std::string dom = dir.file("dom.html");
    const std::string command = "chromium --headless --no-sandbox --disable-gpu --user-data-dir=" + dir.file("profile") +
                                " --virtual-time-budget=5000 --dump-dom 'file://" + page + "' > " + dom + " 2>/dev/null";
    if (std::system(command.c_str()) != 0) return "";
    return read_text(dom);
}

// Drives a copy of `page` in Chromium at 1280 x 900: `script` runs after the
// page loaded and writes what it saw into <pre id="probe">; returns that text.
// `flags`: more of Chromium's command line.
std::string probe_page(TempDir& dir, const std::string& page, const std::string& script, const std::string& flags = "") {
    // Beside the page: its images are files named relative to it.
    const std::string copy = fs::path(page).parent_path().string() + "/probe.html";
    write_text(copy, read_text(page) + "<pre id=\"probe\"></pre><script>window.addEventListener('load',function(){" +
                         "var out=[];function note(x){out.push(x);}" + script +
                         "document.getElementById('probe').textContent=out.join(' ');});</script>\n");
    const std::string dom = dir.file("probe-dom.html");
    const std::string command = "chromium --headless=new --no-sandbox --disable-gpu --user-data-dir=" + dir.file("profile3") +
                                " --window-size=1280,900 --virtual-time-budget=5000 " + flags + " --dump-dom 'file://" + copy + "' > " +
                                dom + " 2>/dev/null";
    if (std::system(command.c_str()) != 0) return "";
    const std::string text = read_text(dom);
    const std::size_t begin = text.find("<pre id=\"probe\">");
    if (begin == std::string::npos) return "";
    const std::size_t from = begin + std::string("<pre id=\"probe\">").size();
    return text.substr(from, text.find("</pre>", from) - from);
}

// The magnifier: a click on a render opens it magnified by whole pixels
// (pixelated), the keys flip between the student's render, the reference and
// the difference, Esc closes it; the page is no wider than the window.
const char* kViewerProbe = R"(
var v=document.getElementById('viewer'),img=document.getElementById('viewer-img');
var row=document.querySelector('[data-student="bob"]'),ref=document.getElementById('reference-image');
function src(kind){return row.querySelector('img[data-view="'+kind+'"]').src;}
function key(k){document.dispatchEvent(new KeyboardEvent('keydown',{key:k,bubbles:true}));}
function seen(){return v.hidden?'hidden':img.src===src('render')?'render':img.src===ref.src?'reference':img.src===src('diff')?'diff':'other';}
note('closed:'+seen());
row.querySelector('img[data-view="render"]').click();
note('click:'+seen()+':'+getComputedStyle(img).imageRendering+':'+document.getElementById('viewer-scale').textContent);
note('title:'+document.getElementById('viewer-title').textContent.split(' ')[0]);
key('f');note('f:'+seen());key('d');note('d:'+seen());key('ArrowRight');note('right:'+seen());
key('3');note('3:'+seen());
v.querySelector('button[data-kind="reference"]').click();note('button:'+seen());
key('Escape');note('esc:'+seen());
note('overflow:'+(document.documentElement.scrollWidth>document.documentElement.clientWidth));
)";

TEST(GradeReport, SummaryCheckColumnsFilterAndFeedbackPagesInHeadlessChromium) {
    if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed";
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    write_text(dir.file("subs/alice.json"), good_scene());
    write_text(dir.file("subs/bob.json"), weaker_scene());
    write_text(dir.file("subs/" + std::string(200, 'L') + ".json"), good_scene_variant(1));  // one long unbroken name
    write_text(dir.file("subs/broken.json"), "{");
    write_text(dir.file("roster.txt"), "alice\nbob\nbroken\nzed\n" + std::string(200, 'L') + "\n");
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out"), "--roster",
                         dir.file("roster.txt")}).exit_code, 0);
    const std::string dom = dom_of(dir, dir.file("out/report.html"));
    ASSERT_FALSE(dom.empty());
    EXPECT_NE(dom.find("id=\"count-graded\">3<"), std::string::npos);
    EXPECT_NE(dom.find("id=\"count-refused\">1<"), std::string::npos);
    EXPECT_NE(dom.find("id=\"count-missing\">1<"), std::string::npos);
    EXPECT_NE(dom.find("id=\"mean\">62.5<"), std::string::npos);     // (100 + 50 + 100 + 0) / 4
    EXPECT_NE(dom.find("id=\"median\">75<"), std::string::npos);
    EXPECT_NE(dom.find("id=\"pass-rate\">2 of 4 (50 %)<"), std::string::npos);
    // One column and one pass rate a check (the image and six rules).
    const std::string rates = dom.substr(dom.find("id=\"check-rates\""));
    EXPECT_NE(rates.find("<td>rules[0] (model)</td><td class=\"num\">2 of 3 (67 %)</td>"), std::string::npos);
    const std::string grades = dom.substr(dom.find("<table id=\"grades\""));
    EXPECT_EQ(count_of(grades.substr(0, grades.find("</thead>")), "<th data-col"), 3u + 7u);
    EXPECT_EQ(count_of(grades, "<td class=\"check ok\""), 3u * 7u - 2u);  // bob fails the image and the model
    EXPECT_EQ(count_of(grades, "<td class=\"check no\""), 2u);
    EXPECT_EQ(count_of(grades, "data-status=\"missing\""), 1u);
    EXPECT_EQ(count_of(grades, "data-status=\"refused\""), 1u);
    // The script ran: the filter shows every row at first.
    EXPECT_NE(dom.find("id=\"shown\">5 rows<"), std::string::npos);
    // The histogram drawn by gnuplot, inline; the magnifier's parts.
    const std::string summary = dom.substr(dom.find("<section id=\"summary\""));
    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
        EXPECT_EQ(summary.find("<figure id=\"histogram\"><svg"), summary.find("id=\"histogram\"") - 8);
    }
    EXPECT_LT(summary.find("id=\"histogram\""), summary.find("<table id=\"grades\""));
    EXPECT_EQ(count_of(dom, "data-view=\"render\""), 3u);  // alice, bob and L...L: not the refused or missing
    EXPECT_EQ(count_of(dom, "data-view=\"diff\""), 3u);
    EXPECT_EQ(count_of(dom, "id=\"reference-image\""), 1u);
    EXPECT_NE(dom.find("<div id=\"viewer\" hidden=\"\""), std::string::npos);
    EXPECT_EQ(probe_page(dir, dir.file("out/report.html"), kViewerProbe),
              "closed:hidden click:render:pixelated:\u00d72 title:bob f:reference d:diff right:render 3:diff "
              "button:reference esc:hidden overflow:false");
    // A feedback page: that student's render, the reference, the difference, every check; no one else.
    const std::string page = dom_of(dir, dir.file("out/feedback/bob.html"));
    EXPECT_NE(page.find("<h2 id=\"student\">bob</h2>"), std::string::npos);
    EXPECT_EQ(count_of(page, "<img"), 4u);  // the three pictures and the magnifier's
    EXPECT_EQ(count_of(page, "data-view="), 3u);
    EXPECT_EQ(count_of(page.substr(page.find("<ul id=\"checks\"")), "<li"), 7u);
    EXPECT_EQ(page.find("alice"), std::string::npos);
    EXPECT_NE(read_text(dir.file("out/feedback/zed.html")).find("no submission"), std::string::npos);
    // The same magnifier on the feedback page.
    EXPECT_EQ(probe_page(dir, dir.file("out/feedback/bob.html"), kViewerProbe),
              "closed:hidden click:render:pixelated:\u00d72 title:bob f:reference d:diff right:render 3:diff "
              "button:reference esc:hidden overflow:false");
    // Screenshots to look at (kept when M3055_KEEP_SCREENSHOTS names a folder).
    if (const char* keep = std::getenv("M3055_KEEP_SCREENSHOTS")) {
        std::system(("chromium --headless=new --no-sandbox --disable-gpu --user-data-dir=" + dir.file("profile2") +
                     " --screenshot=" + std::string(keep) + "/report.png --window-size=1280,1000 file://" +
                     dir.file("out/report.html") + " 2>/dev/null").c_str());
    }
}

// The report links its images (students/, diffs/, reference.png) instead of
// inlining them: the page of a class stays small (a class of 1000 was 55 MB),
// each image loads as it nears the view, with its size known before.
TEST(GradeReport, ImagesAreFilesBesideThePageLoadedLazily) {
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    for (int i = 0; i < 40; ++i) write_text(dir.file("subs/s" + std::to_string(100 + i) + ".json"), good_scene_variant(i));
    write_text(dir.file("subs/with space.json"), weaker_scene());
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    const std::string page = read_text(dir.file("out/report.html"));
    EXPECT_EQ(page.find("data:image"), std::string::npos) << "an image inlined";
    EXPECT_LT(page.size(), 41u * 2000u) << "more than 2 KB a student";
    EXPECT_EQ(count_of(page, " loading=\"lazy\""), 2u * 41u);  // each render and difference image
    EXPECT_NE(page.find("<img id=\"reference-image\" alt=\"reference\" data-view=\"reference\" width=\"512\" "
                        "height=\"320\" src=\"reference.png\">"),
              std::string::npos);
    EXPECT_NE(page.find("width=\"512\" height=\"320\" loading=\"lazy\" decoding=\"async\" src=\"students/with%20space.png\""),
              std::string::npos);
    // Every image the page names is a file beside it.
    for (std::size_t at = page.find(" src=\""); at != std::string::npos; at = page.find(" src=\"", at + 1)) {
        std::string url = page.substr(at + 6, page.find('"', at + 6) - at - 6);
        if (url.rfind("data:", 0) == 0) continue;  // said above
        for (std::size_t p = url.find("%20"); p != std::string::npos; p = url.find("%20")) url.replace(p, 3, " ");
        EXPECT_TRUE(file_exists(dir.file("out/" + url))) << url;
    }
}

// In a browser's window only the images near the view are read when the page
// loads: headless Chromium reads every one (for whole-page screenshots)
// unless told to load lazy images lazily.
TEST(GradeReport, OnlyTheImagesNearTheViewAreReadAtFirst) {
    if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed";
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    for (int i = 0; i < 80; ++i) write_text(dir.file("subs/s" + std::to_string(100 + i) + ".json"), good_scene_variant(i));
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    const std::string read = probe_page(dir, dir.file("out/report.html"),
                                        "var n=0,all=0;[].forEach.call(document.querySelectorAll('img[data-view]'),"
                                        "function(i){all++;if(i.complete&&i.naturalWidth>0)n++;});note(n+' of '+all);",
                                        "--blink-settings=lazyLoadEnabled=true");
    const int images = std::atoi(read.c_str());
    EXPECT_TRUE(read.find(" of ") != std::string::npos && read.substr(read.find(" of ")) == " of 161") << read;  // 80 renders, 80 differences, the reference
    EXPECT_GE(images, 1) << read;
    EXPECT_LT(images, 161 / 2) << read << ": the rows far below the view were read too";
}

// A 240-byte name without a break (graded, refused and named in its reason,
// byte-identical to another, not graded) wraps: the page is no wider than a
// 1280-pixel window.
TEST(GradeReport, LongNamesWrapWithinA1280PixelWindow) {
    if (std::system("command -v chromium >/dev/null 2>&1") != 0) GTEST_SKIP() << "chromium is not installed";
    TempDir dir;
    fs::create_directories(dir.file("subs"));
    const std::string name(240, 'n'), other(239, 'r');
    write_text(dir.file("subs/" + name + ".json"), good_scene());
    write_text(dir.file("subs/alice.json"), good_scene());
    fs::create_directories(dir.file("subs/" + other));  // refused: "rrr.../scene.json: missing"
    write_text(dir.file("subs/" + std::string(230, 'i') + ".txt"), "not graded");
    ASSERT_EQ(run_m3055({"grade", kAssignment, dir.file("subs"), "--out", dir.file("out")}).exit_code, 0);
    EXPECT_EQ(probe_page(dir, dir.file("out/report.html"),
                         "note(document.scrollingElement.scrollWidth<=1280?'fits':'wider:'+document.scrollingElement.scrollWidth);"),
              "fits");
}

TEST(GradeClass, OutputStemsAreSafeUniqueAndBounded) {
    using grading::output_stem;
    EXPECT_EQ(output_stem("alice"), "alice");
    EXPECT_EQ(output_stem("zo\xC3\xAB"), "zo\xC3\xAB");
    EXPECT_EQ(output_stem("with space"), "with space");  // a space stays a space
    EXPECT_EQ(output_stem("a_b"), "a_b");
    // Any other byte is '_', and the name's digest keeps the stem apart from a plain one.
    const std::map<std::string, std::string> replaced = {{"caf\xE9 latin1", "caf_ latin1~"}, {"a%E9", "a_E9~"},
                                                         {"new\nline", "new_line~"},          {".hidden", "_hidden~"},
                                                         {"a\nb", "a_b~"},                    {"trailing ", "trailing_~"},
                                                         {"q?x#y", "q_x_y~"}};
    std::set<std::string> stems = {"a_b"};
    for (const auto& [name, start] : replaced) {
        const std::string stem = output_stem(name);
        EXPECT_EQ(stem.rfind(start, 0), 0u) << stem;
        EXPECT_EQ(stem.size(), start.size() + 16) << stem;
        EXPECT_TRUE(stems.insert(stem).second) << stem;
    }
    const std::string a(300, '\xE9'), b = std::string(299, '\xE9') + "x", c(300, 'c');
    for (const std::string& name : {a, b, c}) {
        EXPECT_LE(output_stem(name).size(), grading::kMaxStemBytes);
        EXPECT_TRUE(stems.insert(output_stem(name)).second);
    }
    for (const std::string& stem : stems) EXPECT_EQ(stem.find('%'), std::string::npos) << stem;
    EXPECT_EQ(grading::shown_name("caf\xE9 \"q\" \\"), "caf\\xE9 \\\"q\\\" \\\\");
}

}  // namespace
}  // namespace m3055::test
