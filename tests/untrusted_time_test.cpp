// One legal scene must not stall a class. `--scene-timeout`
// gives render and batch a per-scene time budget, checked by the renderer
// between draw chunks: a scene over it is one line and skipped, the batch goes
// on, and every scene within it gives the same bytes as without a budget.
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

TEST(SceneTimeout, RenderStopsAStallingSceneWithOneLine) {
    TempDir dir;
    write_stalling_scene(dir.file("stall.json"));
    write_text(dir.file("o.png"), "old");
    const RunResult run = expect_refused(
        dir.path(), {"render", "--scene", dir.file("stall.json"), "--out", dir.file("o.png"), "--scene-timeout", "2"},
        1,
        "m3055: " + dir.file("stall.json") +
            ": over its time budget: not drawn within 2 s (--scene-timeout 2); nothing written\n",
        Bounds{20, 512});
    EXPECT_GE(run.seconds, 2.0);
}

// One screen-filling sphere at 8192 x 8192 under 16 lights is a single draw of
// a minute: it is cut into bands, so the budget holds there too.
TEST(SceneTimeout, HugeSingleDrawsAreBanded) {
    TempDir dir;
    write_stalling_scene(dir.file("huge.json"), 8192, 8192, 3);
    const RunResult run = expect_refused(
        dir.path(), {"render", "--scene", dir.file("huge.json"), "--out", dir.file("o.png"), "--scene-timeout", "3"},
        1,
        "m3055: " + dir.file("huge.json") +
            ": over its time budget: not drawn within 3 s (--scene-timeout 3); nothing written\n",
        Bounds{20, 2600});
}

TEST(SceneTimeout, BatchSkipsTheSceneOverBudgetAndGoesOn) {
    TempDir dir;
    write_scene(dir.file("quick.json"));
    write_stalling_scene(dir.file("stall.json"));
    write_text(dir.file("m.json"), R"([{"scene": "quick.json", "out": "a.png"},
        {"scene": "stall.json", "out": "stall.png", "raw": "stall.pfm"}, {"scene": "quick.json", "out": "b.png"}])");
    const RunResult run = run_m3055({"batch", dir.file("m.json"), "--scene-timeout", "2"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, "[1/3] " + dir.file("a.png") + "\nm3055: " + dir.file("stall.json") +
                           ": over its time budget: not drawn within 2 s (--scene-timeout 2)\n[3/3] " +
                           dir.file("b.png") + "\nm3055: 1 of 3 scenes failed\n");
    EXPECT_EQ(bad_lines(run.err), "");
    expect_within(run, Bounds{30, 512});
    EXPECT_TRUE(fs::exists(dir.file("a.png")));
    EXPECT_TRUE(fs::exists(dir.file("b.png")));
    EXPECT_EQ(read_text(dir.file("a.png")), read_text(dir.file("b.png")));
    EXPECT_FALSE(fs::exists(dir.file("stall.png")));
    EXPECT_FALSE(fs::exists(dir.file("stall.pfm")));
    EXPECT_EQ(snapshot(dir.path()).size(), 5u);  // no temporary
}

TEST(SceneTimeout, BatchHasADefaultBudget) {
    const RunResult help = run_m3055({"batch", "--help"});
    EXPECT_NE(help.out.find("--scene-timeout FLOAT:NONNEGATIVE=30"), std::string::npos) << help.out;
}

// Chunked draws (any budget) give the same bytes as one draw call (no budget):
// many overlapping translucent spheres (many chunks), a few huge ones under 16
// lights (bands), and meshes, opaque and translucent.
TEST(SceneTimeout, ChunkedRendersAreByteIdentical) {
    TempDir dir;
    write_stalling_scene(dir.file("overlap.json"), 256, 160, 600);
    write_stalling_scene(dir.file("bands.json"), 1024, 1024, 2);
    nlohmann::json floor = nlohmann::json::parse(read_text(source_path("scenes/three_point_floor.json")));
    floor["display"] = {{"width", 1024}, {"height", 640}, {"bits", 5}};
    for (auto& object : floor["objects"])
        if (object["shape"] == "torus" || object["shape"] == "cube")
            object["material"] = {{"model", "translucent"}, {"color", {0.3, 0.6, 0.9}}};
    write_text(dir.file("meshes.json"), floor.dump());
    for (const std::string name : {"overlap", "bands", "meshes"}) {
        const std::string scene = dir.file(name + ".json");
        const RunResult plain = run_m3055({"render", "--scene", scene, "--out", dir.file(name + "_1.png"), "--raw",
                                           dir.file(name + "_1.pfm")});
        const RunResult chunked = run_m3055({"render", "--scene", scene, "--out", dir.file(name + "_2.png"), "--raw",
                                             dir.file(name + "_2.pfm"), "--scene-timeout", "1000"});
        ASSERT_EQ(plain.exit_code, 0) << plain.err;
        ASSERT_EQ(chunked.exit_code, 0) << chunked.err;
        EXPECT_TRUE(read_text(dir.file(name + "_1.png")) == read_text(dir.file(name + "_2.png"))) << name;
        EXPECT_TRUE(read_text(dir.file(name + "_1.pfm")) == read_text(dir.file(name + "_2.pfm"))) << name;
    }
}

}  // namespace
}  // namespace m3055::test
