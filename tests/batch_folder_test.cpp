// `m3055 batch --out DIR` over folders and glob patterns, `--report` and
// `--shard K/N`: outputs named after the scenes, byte-identical to
// `m3055 render`, a report line per scene, and shards that cover every scene once.
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <set>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Three small scenes and one broken one in `dir`/scenes.
void write_scenes(const TempDir& dir) {
    fs::create_directories(dir.file("scenes"));
    json scene = json::parse(read_text(source_path("scenes/spec_example.json")));
    scene["display"] = {{"width", 64}, {"height", 40}, {"bits", 5}};
    for (const char* name : {"a", "b", "c"}) {
        scene["background"] = {name[0] == 'a' ? 0.1 : 0.2, 0.1, name[0] == 'c' ? 0.3 : 0.1};
        write_text(dir.file(std::string("scenes/") + name + ".json"), scene.dump());
    }
    write_text(dir.file("scenes/broken.json"), "{");
    write_text(dir.file("scenes/notes.txt"), "not a scene");
}

TEST(BatchFolder, FolderInputNamesOutputsAfterScenesAndReports) {
    TempDir dir;
    write_scenes(dir);
    const RunResult run = run_m3055({"batch", dir.file("scenes"), "--out", dir.file("out"), "--raw", "--report",
                                     dir.file("report.json")});
    EXPECT_EQ(run.exit_code, 1) << "broken.json fails: " << run.err;
    for (const char* name : {"a", "b", "c"}) {
        const std::string scene = dir.file(std::string("scenes/") + name + ".json");
        ASSERT_EQ(run_m3055({"render", "--scene", scene, "--out", dir.file("r.png"), "--raw", dir.file("r.pfm")}).exit_code, 0);
        EXPECT_EQ(read_text(dir.file("r.png")), read_text(dir.file(std::string("out/") + name + ".png"))) << name;
        EXPECT_EQ(read_text(dir.file("r.pfm")), read_text(dir.file(std::string("out/") + name + ".pfm"))) << name;
    }
    const json report = json::parse(read_text(dir.file("report.json")));
    ASSERT_EQ(report.size(), 4u);
    std::map<std::string, json> by_scene;
    for (const json& entry : report) by_scene[fs::path(entry["scene"].get<std::string>()).stem().string()] = entry;
    EXPECT_EQ(by_scene["a"]["status"], "ok");
    EXPECT_EQ(by_scene["a"]["out"], dir.file("out/a.png"));
    EXPECT_GE(by_scene["a"]["seconds"].get<double>(), 0.0);
    EXPECT_EQ(by_scene["broken"]["status"], "failed");
    EXPECT_NE(by_scene["broken"]["message"].get<std::string>().find("invalid JSON"), std::string::npos);
    EXPECT_FALSE(file_exists(dir.file("out/notes.png")));
}

// Mesa's shader cache of a batch is its --out's, not the user's home's (a
// .brdf is code); a manifest has no one folder: with --allow-brdf, no cache.
TEST(BatchFolder, MesasShaderCacheIsKeptInOutOrSwitchedOff) {
    TempDir dir;
    write_scenes(dir);
    run_m3055({"batch", dir.file("scenes"), "--out", dir.file("out")});
    EXPECT_TRUE(fs::is_directory(dir.file("out/.shader-cache/mesa_shader_cache")));
    EXPECT_TRUE(file_exists(dir.file("out/a.png")));
    if (std::system("strace -qq -o /dev/null true >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "strace cannot run here: the manifest's run is not traced";
    write_text(dir.file("manifest.json"), R"([{"scene": "scenes/a.json", "out": "m.png"}])");
    // LeakSanitizer cannot run under ptrace (the sanitizer tree): leaks are checked untraced elsewhere.
    const std::string command = "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" strace -f -qq -e "
                                "trace=open,openat,creat -o " +
                                dir.file("trace") + " " + M3055_BINARY + " batch --allow-brdf " +
                                dir.file("manifest.json") + " 2>/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_TRUE(file_exists(dir.file("m.png")));
    EXPECT_EQ(read_text(dir.file("trace")).find("mesa_shader_cache"), std::string::npos) << "the cache was used";
}

TEST(BatchFolder, GlobPatternsAndShardsCoverEverySceneOnce) {
    TempDir dir;
    write_scenes(dir);
    std::set<std::string> seen;
    for (int k = 1; k <= 2; ++k) {
        const std::string out = dir.file("shard" + std::to_string(k));
        const RunResult run = run_m3055({"batch", dir.file("scenes/[abc].json"), "--out", out, "--shard",
                                         std::to_string(k) + "/2"});
        EXPECT_EQ(run.exit_code, 0) << run.err;
        for (const auto& entry : fs::directory_iterator(out))
            if (entry.path().filename() != ".shader-cache") EXPECT_TRUE(seen.insert(entry.path().filename()).second);
    }
    EXPECT_EQ(seen, (std::set<std::string>{"a.png", "b.png", "c.png"}));
    const RunResult none = run_m3055({"batch", dir.file("scenes/z*.json"), "--out", dir.file("z")});
    EXPECT_EQ(none.exit_code, 1);
    EXPECT_NE(none.err.find("matches no file"), std::string::npos) << none.err;
    // The report may not overwrite a scene.
    const RunResult clash = run_m3055({"batch", dir.file("scenes/a.json"), "--out", dir.file("o"), "--report",
                                       dir.file("scenes/a.json")});
    EXPECT_EQ(clash.exit_code, 1);
    EXPECT_NE(clash.err.find("--report"), std::string::npos) << clash.err;
}

}  // namespace
}  // namespace m3055::test
