// Untrusted scene files and manifests, read by `render` and `batch`:
// crashes, inputs that are not regular files, memory before validation,
// error lines, a NUL in a path and numbers in messages. Every case asserts the exit status, the message,
// that no file is created or changed and no temporary is left, and bounds on
// time and peak memory (untrusted_harness.h). Outputs: untrusted_output_test.
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Writes `head`, then `item` repeated until the file has about `bytes`, then `tail`.
void write_repeated(const std::string& path, const std::string& head, const std::string& item, std::size_t bytes,
                    const std::string& tail) {
    std::ofstream file(path, std::ios::binary);
    file << head;
    std::string block;
    while (block.size() < (1 << 20)) block += item;
    std::size_t written = head.size();
    while (written + block.size() + tail.size() <= bytes) {
        file << block;
        written += block.size();
    }
    while (written + item.size() + tail.size() <= bytes) {
        file << item;
        written += item.size();
    }
    file << tail;
}

std::string render_args_error(const TempDir& dir, const std::string& scene, const std::string& message,
                              const Bounds& bounds = {}) {
    return expect_refused(dir.path(), {"render", "--scene", scene, "--out", dir.file("o.png")}, 1,
                          "m3055: " + message + "\n", bounds)
        .err;
}

// A manifest [good scene, SCENE]: the scene's line, the good one rendered.
void expect_batch_skips(const TempDir& dir, const std::string& scene, const std::string& line,
                        const Bounds& bounds = {}) {
    write_scene(dir.file("good.json"));
    write_text(dir.file("m.json"), json::array({{{"scene", "good.json"}, {"out", "good.png"}},
                                                {{"scene", scene}, {"out", "bad.png"}}})
                                       .dump());
    const RunResult run = run_m3055({"batch", dir.file("m.json")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(glob_match("m3055: " + line + "\n[2/2] " + dir.file("good.png") + "\nm3055: 1 of 2 scenes failed\n",
                           run.err))
        << run.err;
    EXPECT_EQ(bad_lines(run.err), "");
    expect_within(run, bounds);
    EXPECT_TRUE(fs::exists(dir.file("good.png")));
    EXPECT_FALSE(fs::exists(dir.file("bad.png")));
    fs::remove(dir.file("good.png"));
}

// ---- Class 1: no input may crash the program --------------------------------

TEST(UntrustedInput, DeeplyNestedManifestEntryIsOneLine) {
    TempDir dir;
    write_text(dir.file("m.json"), "[" + std::string(200000, '[') + std::string(200000, ']') + "]");
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": [0][0][0]*: nested deeper than 64 levels\n");
    write_text(dir.file("m.json"),
               R"([{"scene": )" + std::string(100000, '[') + std::string(100000, ']') + R"(, "out": "o.png"}])");
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": [0].scene[0][0]*: nested deeper than 64 levels\n");
}

TEST(UntrustedInput, DeeplyNestedSceneIsOneLine) {
    TempDir dir;
    write_text(dir.file("deep.json"), "{\"objects\": " + std::string(300000, '[') + std::string(300000, ']') + "}");
    render_args_error(dir, dir.file("deep.json"), dir.file("deep.json") + ": objects[0][0]*: nested deeper than 64 levels");
    expect_batch_skips(dir, "deep.json", dir.file("deep.json") + ": objects[0][0]*: nested deeper than 64 levels");
}

// ---- Class 4: inputs that are not regular files -------------------------------

TEST(UntrustedInput, SceneLinkedToDevZeroIsRefusedAtOnce) {
    TempDir dir;
    fs::create_symlink("/dev/zero", dir.file("zero.json"));
    const std::string line =
        dir.file("zero.json") + ": cannot read file: it is a character device, not a regular file";
    render_args_error(dir, dir.file("zero.json"), line, Bounds{10, 64});
    expect_batch_skips(dir, "zero.json", line, Bounds{30, 256});
}

TEST(UntrustedInput, ManifestThatIsDevZeroOrAFifoIsRefusedAtOnce) {
    TempDir dir;
    expect_refused(dir.path(), {"batch", "/dev/zero"}, 1,
                   "m3055: /dev/zero: cannot read file: it is a character device, not a regular file\n", Bounds{10, 64});
    fs::create_symlink("/dev/zero", dir.file("m.json"));
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": cannot read file: it is a character device, not a regular file\n",
                   Bounds{10, 64});
    ASSERT_EQ(mkfifo(dir.file("fifo.json").c_str(), 0644), 0);
    expect_refused(dir.path(), {"batch", dir.file("fifo.json")}, 1,
                   "m3055: " + dir.file("fifo.json") + ": cannot read file: it is a FIFO, not a regular file\n",
                   Bounds{10, 64});
}

// Nobody writes to the FIFO: reading it would wait forever, and nothing after
// it would render.
TEST(UntrustedInput, SceneThatIsAFifoDoesNotBlockTheBatch) {
    TempDir dir;
    ASSERT_EQ(mkfifo(dir.file("fifo.json").c_str(), 0644), 0);
    render_args_error(dir, dir.file("fifo.json"), dir.file("fifo.json") + ": cannot read file: it is a FIFO, not a regular file",
                      Bounds{10, 64});
    expect_batch_skips(dir, "fifo.json", dir.file("fifo.json") + ": cannot read file: it is a FIFO, not a regular file",
                       Bounds{30, 256});
}

TEST(UntrustedInput, SceneThatIsAFolder) {
    TempDir dir;
    fs::create_directory(dir.file("folder.json"));
    render_args_error(dir, dir.file("folder.json"),
                      dir.file("folder.json") + ": cannot read file: it is a folder, not a regular file");
}

// ---- Class 5: memory before validation -------------------------------------

TEST(UntrustedInput, HundredMegabyteFilesAreRefusedBySizeBeforeReading) {
    TempDir dir;
    write_repeated(dir.file("numbers.json"), "{\"objects\": [", "0,", 100 << 20, "0]}");
    write_repeated(dir.file("empty.json"), "{\"objects\": [", "{},", 100 << 20, "{}]}");
    for (const std::string name : {"numbers.json", "empty.json"}) {
        const std::string size = std::to_string(fs::file_size(dir.file(name)));
        const std::string line =
            dir.file(name) + ": too large: " + size + " bytes, more than the 16 MiB an input file may have";
        render_args_error(dir, dir.file(name), line, Bounds{10, 64});
        expect_batch_skips(dir, name, line, Bounds{30, 256});
    }
    write_repeated(dir.file("m.json"), "[", R"({"scene": "good.json", "out": "x.png"},)", 100 << 20,
                   R"({"scene": "good.json", "out": "y.png"}])");
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": too large: " + std::to_string(fs::file_size(dir.file("m.json"))) +
                       " bytes, more than the 16 MiB an input file may have\n",
                   Bounds{10, 64});
}

// Files under 16 MiB whose parsed form would be huge: refused before it is built.
TEST(UntrustedInput, SmallFilesThatWouldParseHugeAreRefusedCheaply) {
    TempDir dir;
    const std::size_t limit = (std::size_t(16) << 20) - 16;
    write_repeated(dir.file("empty.json"), "{\"objects\": [", "{},", limit, "{}]}");
    write_repeated(dir.file("numbers.json"), "{\"objects\": [", "0,", limit, "0]}");
    for (const std::string name : {"empty.json", "numbers.json"}) {
        const std::string line = dir.file(name) +
                                 ": too large: parsed, it would take more than 192 MiB of memory (too many objects, "
                                 "keys or values)";
        render_args_error(dir, dir.file(name), line, Bounds{20, 96});
        expect_batch_skips(dir, name, line, Bounds{30, 256});
    }
    write_repeated(dir.file("m.json"), "[", "{},", limit, "{}]");
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") +
                       ": too large: parsed, it would take more than 192 MiB of memory (too many objects, keys or "
                       "values)\n",
                   Bounds{20, 96});
}

// The costliest rejection: a legal-looking scene just under the parsed-size
// limit, refused at its very last object. Still under 256 MiB, in render and
// in batch after a scene was drawn (batch loads every scene before it makes
// its GL context).
TEST(UntrustedInput, LateRejectionOfTheLargestSceneStaysUnder256MiB) {
    TempDir dir;
    json scene = json::parse(read_text(source_path("scenes/spec_example.json")));
    const json sphere = {{"shape", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0.01},
                         {"material", {{"model", "metal"}, {"color", {1, 1, 1}},
                                       {"lobes", json::array({{{"w", 0.1}, {"m", 0.2}}, {{"w", 0.1}, {"m", 0.2}},
                                                              {{"w", 0.1}, {"m", 0.2}}, {{"w", 0.1}, {"m", 0.2}}})}}}};
    scene["objects"] = json::array();
    for (int i = 0; i < 80000; ++i) scene["objects"].push_back(sphere);
    scene["objects"][79999]["radius"] = -1;
    write_text(dir.file("late.json"), scene.dump());
    const std::string line = dir.file("late.json") + ": objects[79999].radius: must be in (0, 1000000], got -1";
    render_args_error(dir, dir.file("late.json"), line, Bounds{30, 256});
    expect_batch_skips(dir, "late.json", line, Bounds{60, 256});
}

// Finished images wait for the encoders bounded by memory, not only by their
// number: four 4096 x 4096 scenes with --raw (300 MB of images each) peak as
// one does, where they used to be in memory together (six 8192 x 8192 ones
// reached 4.66 GiB).
TEST(UntrustedInput, BatchBoundsTheImagesInFlightByMemory) {
    TempDir dir;
    write_scene(dir.file("big.json"), "spec_example.json", 4096, 4096);
    json manifest = json::array();
    for (int i = 0; i < 4; ++i)
        manifest.push_back({{"scene", "big.json"}, {"out", std::to_string(i) + ".png"}, {"raw", std::to_string(i) + ".pfm"}});
    write_text(dir.file("m.json"), manifest.dump());
    const RunResult one = run_m3055({"render", "--scene", dir.file("big.json"), "--out", dir.file("one.png"), "--raw",
                                     dir.file("one.pfm")});
    ASSERT_EQ(one.exit_code, 0) << one.err;
    const RunResult four = run_m3055({"batch", dir.file("m.json")});
    ASSERT_EQ(four.exit_code, 0) << four.err;
    std::printf("peak memory: one 4096^2 --raw render %.0f MiB, a batch of four %.0f MiB\n", one.peak_rss_mib,
                four.peak_rss_mib);
    EXPECT_LE(four.peak_rss_mib, one.peak_rss_mib + 128 * kSanitizerSlack);
    for (int i = 0; i < 4; ++i)
        EXPECT_TRUE(read_text(dir.file(std::to_string(i) + ".pfm")) == read_text(dir.file("one.pfm"))) << i;
}

// ---- Class 6: one line of valid UTF-8, at most 300 bytes ---------------------

TEST(UntrustedInput, ScenesInOtherEncodings) {
    TempDir dir;
    const std::string good = read_text(source_path("scenes/spec_example.json"));
    std::string utf16 = "\xFF\xFE";
    for (const char c : good) utf16 += std::string(1, c) + '\0';
    write_text(dir.file("utf16.json"), utf16);
    render_args_error(dir, dir.file("utf16.json"),
                      dir.file("utf16.json") + ": is UTF-16 text (it starts with a byte order mark); save it as UTF-8");
    std::string latin1 = good;
    latin1.replace(latin1.find("\"highlight\""), 11, "\"highl\xE9ght\"");
    write_text(dir.file("latin1.json"), latin1);
    render_args_error(dir, dir.file("latin1.json"),
                      dir.file("latin1.json") + ": invalid JSON: parse error at line *: syntax error while parsing "
                                                "value - invalid string: ill-formed UTF-8 byte; last read: '\"highl\\xE9*'");
    std::string key = good;
    key.replace(key.find("\"radius\""), 8, "\"r\xE9" "dius\"");
    write_text(dir.file("latin1key.json"), key);
    render_args_error(dir, dir.file("latin1key.json"),
                      dir.file("latin1key.json") + ": invalid JSON: parse error at line *: syntax error while parsing "
                                                   "object key - invalid string: ill-formed UTF-8 byte; last read: "
                                                   "'\"r\\xE9*'; expected string literal");
}

TEST(UntrustedInput, HugeTokensAreCut) {
    TempDir dir;
    const std::string good = read_text(source_path("scenes/spec_example.json"));
    std::string digits = good;
    digits.replace(digits.find("\"radius\": 1.0"), 13, "\"radius\": 1" + std::string(1000000, '0'));
    write_text(dir.file("digits.json"), digits);
    render_args_error(dir, dir.file("digits.json"),
                      dir.file("digits.json") + ": invalid JSON: number overflow parsing '100000000000000000*0000'");
    std::string open_string = good.substr(0, good.find("\"radius\"")) + "\"radius\": \"" + std::string(1000000, 'a');
    write_text(dir.file("string.json"), open_string);
    render_args_error(dir, dir.file("string.json"),
                      dir.file("string.json") + ": invalid JSON: parse error at line *: syntax error while parsing "
                                                "value - invalid string: missing closing quote; last read: "
                                                "'\"aaaaaaaaaaaaaaaaa…aaaaaaaaaaaaaaaaa*'");
}

TEST(UntrustedInput, TenMegabyteManifestValueIsCut) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": ")" + std::string(10 << 20, 'x') + "\"}]");
    // A 10 MB name is no name a folder can hold: refused before anything is rendered.
    const RunResult run = run_m3055({"batch", dir.file("m.json")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(bad_lines(run.err), "");
    EXPECT_LT(run.err.size(), 400u);
    json array = json::array();
    for (int i = 0; i < 2000000; ++i) array.push_back(i);
    write_text(dir.file("m.json"), json::array({{{"scene", array}, {"out", "o.png"}}}).dump());
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": [0].scene: must be a string, got [0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,1…\n");
}

TEST(UntrustedInput, NamesAndKeysWithNewlinesOrBadBytesAreQuoted) {
    TempDir dir;
    render_args_error(dir, dir.file("two\nlines.json"),
                      "\"" + dir.file("two\\nlines.json") + "\": cannot read file: No such file or directory");
    render_args_error(dir, dir.file("caf\xE9.json"),
                      "\"" + dir.file("caf\\xE9.json") + "\": cannot read file: No such file or directory");
    const std::string deep = dir.file(std::string(3000, 'd') + "/s.json");
    const std::string err = render_args_error(dir, deep, "*…*/s.json: cannot read file: *");
    EXPECT_LE(err.size(), 301u);
    write_scene(dir.file("s.json"));
    write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": "o.png", "new\nline": 1}])");
    expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                   "m3055: " + dir.file("m.json") + ": [0][\"new\\nline\"]: unknown key (expected scene, out, raw)\n");
    json scene = json::parse(read_text(source_path("scenes/spec_example.json")));
    scene["objects"][0]["material"]["\u202Eevil\nkey"] = 1;
    write_text(dir.file("key.json"), scene.dump());
    render_args_error(dir, dir.file("key.json"),
                      dir.file("key.json") + ": objects[0].material[\"\\u202Eevil\\nkey\"]: unknown key");
}

// ---- Class 9: a NUL in a manifest path --------------------------------------

TEST(UntrustedInput, NulInAManifestPathIsAnErrorNamingTheEntry) {
    TempDir dir;
    write_scene(dir.file("s0.json"));
    for (const std::string key : {"scene", "out", "raw"}) {
        json entry = {{"scene", "s0.json"}, {"out", "o.png"}};
        entry[key] = key == "scene" ? std::string("s0.json\0.evil", 13) : std::string("o.png\0.evil", 11);
        write_text(dir.file("m.json"), json::array({{{"scene", "s0.json"}, {"out", "first.png"}}, entry}).dump());
        expect_refused(dir.path(), {"batch", dir.file("m.json")}, 1,
                       "m3055: " + dir.file("m.json") + ": [1]." + key + ": must not hold a NUL character, got \"" +
                           (key == "scene" ? "s0.json" : "o.png") + "\\u0000.evil\"\n");
    }
}

// ---- Class 11: numbers in messages are what was read ---------------------------

TEST(UntrustedInput, NumbersInMessagesAreNotRoundedIntoTheRange) {
    TempDir dir;
    const auto with = [&](const std::string& what, const std::string& value) {
        std::string text = read_text(source_path("scenes/spec_example.json"));
        text.replace(text.find(what), what.size(), value);
        write_text(dir.file("n.json"), text);
        return dir.file("n.json");
    };
    render_args_error(dir, with("\"center\": [0, 0, 0]", "\"center\": [0, 0, -1000000.0000001]"),
                      dir.file("n.json") + ": objects[0].center[2]: must be in [-1000000, 1000000], got -1000000.0000001");
    render_args_error(dir, with("\"center\": [0, 0, 0]", "\"center\": [0, 0, 1000000.0000000001]"),
                      dir.file("n.json") +
                          ": objects[0].center[2]: must be in [-1000000, 1000000], got 1000000.0000000001");
    render_args_error(dir, with("\"center\": [0, 0, 0]", "\"center\": [0, 0, -9007199254740993]"),
                      dir.file("n.json") +
                          ": objects[0].center[2]: must be in [-1000000, 1000000], got -9007199254740993");
    render_args_error(dir, with("\"width\": 512", "\"width\": 8192.000000000002"),
                      dir.file("n.json") + ": display.width: must be a whole number, got 8192.000000000002");
}

}  // namespace
}  // namespace m3055::test
