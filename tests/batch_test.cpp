// `m3055 batch`: one process, many scenes; each output byte-identical to
// `m3055 render`; bad scenes skipped and reported; bad manifests rejected
// before anything is rendered.
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

// A copy of scenes/NAME with the display resized, written to `path`.
void write_scene(const std::string& path, const std::string& name, int width, int height) {
    nlohmann::json doc = nlohmann::json::parse(read_text(source_path("scenes/" + name)));
    doc["display"]["width"] = width;
    doc["display"]["height"] = height;
    write_text(path, doc.dump(2));
}

TEST(Batch, OutputsAreByteIdenticalToRender) {
    TempDir dir;
    // Sizes change between scenes, so the reused renderer must resize its targets;
    // fig09 has a translucent pass, fig10 metals, fig05 highlights.
    write_scene(dir.file("a.json"), "fig05.json", 512, 320);
    write_scene(dir.file("b.json"), "fig09.json", 97, 61);
    write_scene(dir.file("c.json"), "fig10.json", 512, 320);
    write_text(dir.file("m.json"), R"([
        {"scene": "a.json", "out": "a.png", "raw": "a.pfm"},
        {"scene": "b.json", "out": "b.png", "raw": "b.pfm"},
        {"scene": "c.json", "out": "c.png"}])");
    const RunResult batch = run_m3055({"batch", dir.file("m.json")});
    ASSERT_EQ(batch.exit_code, 0) << batch.err;
    EXPECT_FALSE(file_exists(dir.file("c.pfm")));
    for (const std::string name : {"a", "b", "c"}) {
        const bool raw = name != "c";
        std::vector<std::string> args = {"render", "--scene", dir.file(name + ".json"), "--out",
                                         dir.file(name + "_render.png")};
        if (raw) args.insert(args.end(), {"--raw", dir.file(name + "_render.pfm")});
        const RunResult render = run_m3055(args);
        ASSERT_EQ(render.exit_code, 0) << render.err;
        EXPECT_EQ(read_text(dir.file(name + ".png")), read_text(dir.file(name + "_render.png"))) << name;
        if (raw) {
            EXPECT_EQ(read_text(dir.file(name + ".pfm")), read_text(dir.file(name + "_render.pfm"))) << name;
        }
    }
}

TEST(Batch, BadSceneIsReportedAndSkippedOthersStillRender) {
    TempDir dir;
    write_scene(dir.file("good1.json"), "spec_example.json", 64, 40);
    write_scene(dir.file("good2.json"), "fig10.json", 64, 40);
    nlohmann::json bad = nlohmann::json::parse(read_text(source_path("scenes/spec_example.json")));
    bad["objects"][0]["material"]["m"] = -3;
    write_text(dir.file("bad.json"), bad.dump());
    write_text(dir.file("m.json"), R"([
        {"scene": "good1.json", "out": "1.png"},
        {"scene": "bad.json", "out": "bad.png"},
        {"scene": "missing.json", "out": "missing.png"},
        {"scene": "good2.json", "out": "2.png"}])");
    const RunResult result = run_m3055({"batch", dir.file("m.json")});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_TRUE(file_exists(dir.file("1.png")));
    EXPECT_TRUE(file_exists(dir.file("2.png")));
    EXPECT_FALSE(file_exists(dir.file("bad.png")));
    EXPECT_FALSE(file_exists(dir.file("missing.png")));
    // One line each, naming the file and the JSON path.
    EXPECT_NE(result.err.find("bad.json: objects[0].material.m: must be in [0, 10000], got -3\n"), std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("missing.json"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("2 of 4 scenes failed"), std::string::npos) << result.err;
}

TEST(Batch, AreaLightsAndShadowsRenderAsRenderDrawsThem) {
    // The samples' per-pixel rotation depends on the pixel and light alone, so a
    // batch, whatever it drew before, gives the render's bytes.
    TempDir dir;
    write_scene(dir.file("plain.json"), "spec_example.json", 64, 40);
    nlohmann::json lit = nlohmann::json::parse(read_text(dir.file("plain.json")));
    lit["lights"][0]["shadow"] = true;
    lit["lights"].push_back({{"type", "sky"}, {"intensity", 0.3}, {"shadow", true}});
    lit["lights"].push_back(
        {{"type", "rect"}, {"position", {0, 3, 2}}, {"normal", {0, -1, -0.5}}, {"size", {1, 0.5}}, {"intensity", 2}});
    write_text(dir.file("lit.json"), lit.dump());
    write_text(dir.file("m.json"), R"([{"scene": "plain.json", "out": "plain.png"}, {"scene": "lit.json", "out": "lit.png"}])");
    const RunResult batch = run_m3055({"batch", dir.file("m.json")});
    ASSERT_EQ(batch.exit_code, 0) << batch.err;
    const RunResult render =
        run_m3055({"render", "--scene", dir.file("lit.json"), "--out", dir.file("lit_render.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(read_text(dir.file("lit.png")), read_text(dir.file("lit_render.png")));
    EXPECT_NE(read_text(dir.file("lit.png")), read_text(dir.file("plain.png")));
}

TEST(Batch, PathsAreRelativeToTheManifestsFolder) {
    TempDir dir;
    fs::create_directories(dir.file("jobs"));
    fs::create_directories(dir.file("scenes"));
    fs::create_directories(dir.file("out"));
    write_scene(dir.file("scenes/s.json"), "spec_example.json", 32, 20);
    write_text(dir.file("jobs/m.json"), R"([{"scene": "../scenes/s.json", "out": "../out/s.png", "raw": "s.pfm"}])");
    // The test's working directory is not the manifest's folder.
    ASSERT_NE(fs::current_path(), fs::path(dir.file("jobs")));
    const RunResult result = run_m3055({"batch", dir.file("jobs/m.json")});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(file_exists(dir.file("out/s.png")));
    EXPECT_TRUE(file_exists(dir.file("jobs/s.pfm")));
}

// A manifest error names the manifest and the JSON path, and nothing is rendered.
void expect_manifest_error(const std::string& manifest, const std::string& message) {
    TempDir dir;
    write_scene(dir.file("s.json"), "spec_example.json", 32, 20);
    write_text(dir.file("m.json"), manifest);
    const RunResult result = run_m3055({"batch", dir.file("m.json")});
    EXPECT_NE(result.exit_code, 0) << manifest;
    EXPECT_EQ(result.err, "m3055: " + dir.file("m.json") + ": " + message + "\n") << manifest;
    EXPECT_FALSE(file_exists(dir.file("first.png"))) << manifest;
}

TEST(Batch, BadManifestIsRejectedBeforeRendering) {
    const std::string first = R"({"scene": "s.json", "out": "first.png"})";
    expect_manifest_error("[" + first + R"(, {"scene": "s.json"}])", "[1].out: is required");
    expect_manifest_error("[" + first + R"(, {"out": "x.png"}])", "[1].scene: is required");
    expect_manifest_error("[" + first + R"(, {"scene": "s.json", "out": 7}])", "[1].out: must be a string, got 7");
    expect_manifest_error("[" + first + R"(, {"scene": "s.json", "out": "y.png", "rwa": "y.pfm"}])",
                          "[1].rwa: unknown key (expected scene, out, raw)");
    expect_manifest_error("[" + first + ", 3]", "[1]: must be an object, got 3");
    expect_manifest_error(first, "must be a JSON array of {\"scene\", \"out\", \"raw\"} objects");
    expect_manifest_error("[" + first, "invalid JSON: parse error at line 1, column 41: syntax error while parsing "
                                       "array - unexpected end of input; expected ']'");
}

// Two entries writing one file: both are errors naming each other, neither is
// written, and the rest of the batch still renders (tests/untrusted_output_test.cpp
// has the other ways two names can be one file).
TEST(Batch, EntriesWritingOneFileAreBothSkipped) {
    TempDir dir;
    write_scene(dir.file("s.json"), "spec_example.json", 32, 20);
    write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": "first.png"},
        {"scene": "s.json", "out": "other.png"}, {"scene": "s.json", "out": "first.png"}])");
    const RunResult result = run_m3055({"batch", dir.file("m.json")});
    EXPECT_EQ(result.exit_code, 1);
    const std::string m = dir.file("m.json"), first = dir.file("first.png");
    // Entries that cannot be rendered are reported first, before anything is drawn.
    EXPECT_EQ(result.err, "m3055: " + m + ": [0].out " + first + ": is the same file as [2].out " + first + "\n" +
                              "m3055: " + m + ": [2].out " + first + ": is the same file as [0].out " + first +
                              "\n" + "[3/3] " + dir.file("other.png") + "\n" + "m3055: 2 of 3 scenes failed\n");
    EXPECT_FALSE(file_exists(first));
    EXPECT_TRUE(file_exists(dir.file("other.png")));
}

TEST(Batch, MissingManifestIsOneLine) {
    TempDir dir;
    const RunResult result = run_m3055({"batch", dir.file("none.json")});
    EXPECT_NE(result.exit_code, 0);
    EXPECT_EQ(result.err, "m3055: " + dir.file("none.json") + ": cannot read file: No such file or directory\n");
}

}  // namespace
}  // namespace m3055::test
