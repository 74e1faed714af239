// Outputs that would destroy inputs, outputs that
// clash with each other however they are named, and outputs that are not
// regular files. Before anything is written every output is resolved and
// checked against every input and output of the run; a clash names both
// entries and nothing is written for either. Every case asserts the exit
// status, the message, the folder unchanged (inputs byte-identical, nothing
// created, no temporary) and bounds on time and memory.
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// `path` relative to the test's working directory (where m3055 runs).
std::string relative(const std::string& path) { return fs::relative(path, fs::current_path()).string(); }

void expect_render_refused(const TempDir& dir, const std::vector<std::string>& outputs, const std::string& line) {
    std::vector<std::string> args = {"render", "--scene", dir.file("s.json")};
    args.insert(args.end(), outputs.begin(), outputs.end());
    expect_refused(dir.path(), args, 1, "m3055: " + line + "\n");
}

// ---- Class 2, render --------------------------------------------------------

TEST(UntrustedOutput, RenderOutputThatIsTheSceneIsRefused) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    const std::string s = dir.file("s.json");
    expect_render_refused(dir, {"--out", s}, "--out " + s + ": would overwrite --scene " + s);
    expect_render_refused(dir, {"--out", relative(s)}, "--out " + relative(s) + ": would overwrite --scene " + s);
    expect_render_refused(dir, {"--out", dir.path() + "/./s.json"},
                          "--out " + dir.path() + "/./s.json: would overwrite --scene " + s);
    expect_render_refused(dir, {"--out", dir.file("o.png"), "--raw", s}, "--raw " + s + ": would overwrite --scene " + s);
    // Through a symlinked folder, and through a second (hard) link.
    fs::create_directory_symlink(dir.path(), dir.file("link"));
    expect_render_refused(dir, {"--out", dir.file("link/s.json")},
                          "--out " + dir.file("link/s.json") + ": would overwrite --scene " + s);
    fs::create_hard_link(s, dir.file("hard.json"));
    expect_render_refused(dir, {"--out", dir.file("hard.json")},
                          "--out " + dir.file("hard.json") + ": would overwrite --scene " + s);
}

TEST(UntrustedOutput, RenderOutAndRawThatAreOneFileAreRefused) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    const std::string o = dir.file("o.png");
    expect_render_refused(dir, {"--out", o, "--raw", o}, "--raw " + o + ": is the same file as --out " + o);
    expect_render_refused(dir, {"--out", o, "--raw", relative(o)},
                          "--raw " + relative(o) + ": is the same file as --out " + o);
    write_text(o, "an old image");  // existing: the same, and it survives
    expect_render_refused(dir, {"--out", o, "--raw", o}, "--raw " + o + ": is the same file as --out " + o);
}

TEST(UntrustedOutput, RenderThroughASymlinkedSceneIsRefused) {
    TempDir dir;
    write_scene(dir.file("real.json"));
    fs::create_symlink("real.json", dir.file("s.json"));
    // Writing the link's target or replacing the link itself: both destroy an input.
    expect_render_refused(dir, {"--out", dir.file("real.json")},
                          "--out " + dir.file("real.json") + ": would overwrite --scene " + dir.file("s.json"));
}

// ---- Class 2, batch ---------------------------------------------------------

// Runs `manifest` (written as m.json beside s.json and t.json) and expects
// exactly these error lines, then "[N/N] ok.png" for the one good entry.
void expect_batch_lines(const TempDir& dir, const json& manifest, const std::vector<std::string>& lines) {
    write_text(dir.file("m.json"), manifest.dump());
    const auto before = snapshot(dir.path());
    const RunResult run = run_m3055({"batch", dir.file("m.json")});
    std::string expected;
    for (const std::string& line : lines) expected += "m3055: " + dir.file("m.json") + ": " + line + "\n";
    const std::size_t total = manifest.size();
    expected += "[" + std::to_string(total) + "/" + std::to_string(total) + "] " + dir.file("ok.png") + "\n";
    expected += "m3055: " + std::to_string(total - 1) + " of " + std::to_string(total) + " scenes failed\n";
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(run.err, expected);
    EXPECT_EQ(bad_lines(run.err), "");
    expect_within(run, Bounds{60, 256});
    // Only ok.png is new; every input is byte-identical.
    auto after = snapshot(dir.path());
    EXPECT_EQ(after.erase("ok.png"), 1u);
    EXPECT_TRUE(after == before);
    fs::remove(dir.file("ok.png"));
}

const json kOk = {{"scene", "s.json"}, {"out", "ok.png"}};

TEST(UntrustedOutput, BatchOutputOverItsOwnOrALaterScene) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    write_scene(dir.file("t.json"));
    const std::string s = dir.file("s.json"), t = dir.file("t.json");
    expect_batch_lines(dir, json::array({{{"scene", "s.json"}, {"out", "s.json"}}, kOk}),
                       {"[0].out " + s + ": would overwrite [0].scene " + s});
    // The later entry even rendered, from a copy read before the write.
    expect_batch_lines(dir,
                       json::array({{{"scene", "s.json"}, {"out", "t.json"}}, {{"scene", "t.json"}, {"out", "x.png"}}, kOk}),
                       {"[0].out " + t + ": would overwrite [1].scene " + t,
                        "[1].scene " + t + ": would be overwritten by [0].out " + t});
    expect_batch_lines(dir, json::array({{{"scene", "s.json"}, {"out", "a.png"}, {"raw", "m.json"}}, kOk}),
                       {"[0].raw " + dir.file("m.json") + ": would overwrite the manifest " + dir.file("m.json")});
}

TEST(UntrustedOutput, BatchOutputsNamedTwiceAnotherWay) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    fs::create_directory(dir.file("real"));
    fs::create_directory_symlink("real", dir.file("link"));
    const std::string a = dir.file("a.png");
    expect_batch_lines(dir,
                       json::array({{{"scene", "s.json"}, {"out", a}}, {{"scene", "s.json"}, {"out", "a.png"}}, kOk}),
                       {"[0].out " + a + ": is the same file as [1].out " + a, "[1].out " + a + ": is the same file as [0].out " + a});
    expect_batch_lines(dir,
                       json::array({{{"scene", "s.json"}, {"out", "real/x.png"}},
                                    {{"scene", "s.json"}, {"out", "link/x.png"}}, kOk}),
                       {"[0].out " + dir.file("real/x.png") + ": is the same file as [1].out " + dir.file("link/x.png"),
                        "[1].out " + dir.file("link/x.png") + ": is the same file as [0].out " + dir.file("real/x.png")});
    expect_batch_lines(dir, json::array({{{"scene", "s.json"}, {"out", "b.png"}, {"raw", "./b.png"}}, kOk}),
                       {"[0].raw " + dir.path() + "/./b.png: is the same file as [0].out " + dir.file("b.png")});
}

// ---- Class 3: outputs that are not regular files ---------------------------

TEST(UntrustedOutput, DevicesFifosFoldersAndLinksAreNotReplaced) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    const std::string why = ", not a regular file (outputs go only to regular files or new names)";
    struct stat null_before {};
    ASSERT_EQ(stat("/dev/null", &null_before), 0);
    expect_render_refused(dir, {"--out", "/dev/null"}, "--out /dev/null: cannot write: it is a character device" + why);
    struct stat null_after {};
    ASSERT_EQ(stat("/dev/null", &null_after), 0);
    EXPECT_TRUE(S_ISCHR(null_after.st_mode));
    EXPECT_EQ(null_before.st_ino, null_after.st_ino);
    ASSERT_EQ(mkfifo(dir.file("fifo").c_str(), 0644), 0);
    expect_render_refused(dir, {"--out", dir.file("fifo")}, "--out " + dir.file("fifo") + ": cannot write: it is a FIFO" + why);
    fs::create_directory(dir.file("folder.png"));
    expect_render_refused(dir, {"--out", dir.file("o.png"), "--raw", dir.file("folder.png")},
                          "--raw " + dir.file("folder.png") + ": cannot write: it is a folder" + why);
    write_text(dir.file("target"), "keep");
    fs::create_symlink("target", dir.file("link.png"));
    expect_render_refused(dir, {"--out", dir.file("link.png")},
                          "--out " + dir.file("link.png") + ": cannot write: it is a symbolic link" + why);
    expect_batch_lines(dir, json::array({{{"scene", "s.json"}, {"out", "fifo"}}, kOk}),
                       {"[0].out " + dir.file("fifo") + ": cannot write: it is a FIFO" + why});
}

TEST(UntrustedOutput, LongestNamesWorkAndLongerOnesAreOneLine) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    for (const std::size_t length : {254, 255}) {
        const std::string png = dir.file(std::string(length - 4, 'p') + ".png");
        const std::string pfm = dir.file(std::string(length - 4, 'p') + ".pfm");
        const RunResult run = run_m3055({"render", "--scene", dir.file("s.json"), "--out", png, "--raw", pfm});
        EXPECT_EQ(run.exit_code, 0) << run.err;
        EXPECT_TRUE(fs::exists(png));
        EXPECT_TRUE(fs::exists(pfm));
    }
    EXPECT_EQ(snapshot(dir.path()).size(), 5u);  // no temporary left
    const std::string too_long = dir.file(std::string(256, 'q'));
    const RunResult run = expect_refused(dir.path(), {"render", "--scene", dir.file("s.json"), "--out", too_long}, 1,
                                         "m3055: --out *…*: cannot write: File name too long\n");
    EXPECT_LE(run.err.size(), 301u);
}

}  // namespace
}  // namespace m3055::test
