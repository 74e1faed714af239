// The explorer under a virtual X server (xvfb-run): a scripted session must
// save a screenshot byte-identical to `m3055 render` of the saved scene, show
// panels and the emulated display in its window, and sleep when idle.
#include "image/image.h"
#include "test_paths.h"
#include "models/model_table.h"
#include "scene/load.h"
#include "scene/presets.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>


namespace m3055 {
namespace {

using test::TempDir;

// xvfb-run on $PATH, or "" when there is none.
std::string find_xvfb_run() {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const std::string candidate = dir + "/xvfb-run";
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return "";
}

struct ExplorerRun {
    int exit_code = -1;
    std::string out, err;
};

// Runs `m3055 explore ARGS` under xvfb-run in `cwd` (the script's relative paths land there).
// With `timeout_seconds` > 0 the run is killed after that long (exit code 124).
ExplorerRun run_explorer(const std::string& cwd, const std::vector<std::string>& args, int timeout_seconds = 0) {
    const std::string out_path = cwd + "/explore.stdout", err_path = cwd + "/explore.stderr";
    // A 1500 x 940 window (the size the checks' positions are for; the default is the screen's work area).
    std::vector<std::string> argv = {find_xvfb_run(), "-a", "-s", "-screen 0 1600x1000x24",
                                     M3055_BINARY, "explore", "--window-size", "1500", "940"};
    if (timeout_seconds > 0)
        argv.insert(argv.begin(), {"/usr/bin/timeout", "-k", "5", std::to_string(timeout_seconds)});
    argv.insert(argv.end(), args.begin(), args.end());
    const pid_t pid = fork();
    if (pid == 0) {
        if (chdir(cwd.c_str()) != 0) _exit(127);
        const int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out, 1);
        dup2(err, 2);
        std::vector<char*> c_argv;
        for (std::string& a : argv) c_argv.push_back(a.data());
        c_argv.push_back(nullptr);
        execv(c_argv[0], c_argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ExplorerRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.out = test::read_text(out_path);
    run.err = test::read_text(err_path);
    return run;
}

// Where `shot` appears 1:1 inside `window` (searching the right of the panel),
// or {-1, -1}. Exact byte comparison: the window shows the display texture
// with nearest-neighbour sampling at a whole-pixel scale.
std::pair<int, int> find_exact(const Rgb8Image& window, const Rgb8Image& shot, int x_from) {
    auto px = [](const Rgb8Image& im, int x, int y, int c) {
        return im.pixels[(static_cast<std::size_t>(y) * im.width + x) * 3 + c];
    };
    for (int oy = 0; oy + shot.height <= window.height; ++oy) {
        for (int ox = x_from; ox + shot.width <= window.width; ++ox) {
            bool same = true;
            for (int y = 0; y < shot.height && same; ++y) {
                for (int x = 0; x < shot.width && same; ++x) {
                    for (int c = 0; c < 3 && same; ++c) same = px(window, ox + x, oy + y, c) == px(shot, x, y, c);
                }
            }
            if (same) return {ox, oy};
        }
    }
    return {-1, -1};
}

class Explorer : public ::testing::Test {
protected:
    void SetUp() override {
        if (find_xvfb_run().empty()) GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb)";
    }
};

TEST_F(Explorer, ScriptedSessionSavesWhatRenderWritesAndShowsPanelsAndDisplay) {
    TempDir dir;
    const ExplorerRun run = run_explorer(dir.path(), {"--script", test::source_path("tests/data/explore_script.txt"),
                                              "--exit-after-script", "--stats", "stats.json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;

    // The scene JSON holds the scripted changes.
    ASSERT_TRUE(test::file_exists(dir.file("shot.png")));
    ASSERT_TRUE(test::file_exists(dir.file("shot.json"))) << "screenshot writes the JSON beside the PNG";
    EXPECT_EQ(test::read_text(dir.file("shot.json")), test::read_text(dir.file("scene.json")));
    const auto scene = nlohmann::json::parse(test::read_text(dir.file("scene.json")));
    EXPECT_EQ(scene["display"]["bits"], 4);
    ASSERT_EQ(scene["lights"].size(), 3u);  // paper preset (2) + one added
    EXPECT_DOUBLE_EQ(scene["lights"][2]["intensity"].get<double>(), 0.3);
    const auto& lobes = scene["objects"][1]["material"]["lobes"];
    double peak = scene["objects"][1]["material"]["d"].get<double>();
    for (const auto& lobe : lobes) peak += lobe["w"].get<double>() / std::pow(lobe["m"].get<double>(), 2);
    EXPECT_NEAR(peak, 1.0, 1e-9) << "the eq. 14 rescale";
    EXPECT_NE(lobes[0]["w"].get<double>(), 0.02) << "the rescale changed the weight set before it";
    EXPECT_NE(scene["camera"]["position"], nlohmann::json::array({0, 0, 10})) << "orbit moved the camera";

    // Byte-identical to the headless renderer's PNG of the saved scene.
    const auto render = test::run_m3055({"render", "--scene", dir.file("shot.json"), "--out", dir.file("render.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(test::read_text(dir.file("shot.png")), test::read_text(dir.file("render.png")));

    // Idle: no input for 2 s, at most a couple of frames drawn.
    EXPECT_TRUE(std::regex_search(run.out, std::regex("idle 2\\.0 s: [0-9]+ frames drawn"))) << run.out;
    const auto stats = nlohmann::json::parse(test::read_text(dir.file("stats.json")));
    ASSERT_EQ(stats["idle"].size(), 1u);
    EXPECT_LE(stats["idle"][0]["frames"].get<int>(), 2) << run.out;
    EXPECT_GE(stats["frames"].get<int>(), 10) << "one frame per script line at least";
    EXPECT_EQ(stats["script_errors"], 0);
    // Each frame that rendered the changed scene, its time (scripts/bench-web reads them).
    const auto& frame_ms = stats["render_frame_ms"];
    ASSERT_TRUE(frame_ms.is_array());
    EXPECT_GE(frame_ms.size(), 5u) << "the script's edits render";
    EXPECT_LE(frame_ms.size(), stats["renders"].get<std::size_t>()) << "one a rendering frame at most";
    for (const auto& ms : frame_ms) EXPECT_GT(ms.get<double>(), 0.0);

    // The window capture: panels on the left, the emulated display (A and B) on the right.
    const Rgb8Image window = read_png(dir.file("window.png"));
    const Rgb8Image shot = read_png(dir.file("shot.png"));
    EXPECT_EQ(window.width, 1500);
    EXPECT_EQ(window.height, 940);
    const auto [ax, ay] = find_exact(window, shot, 300);
    ASSERT_GE(ax, 0) << "the screenshot's pixels appear 1:1 in the window (compare mode: scale 1)";
    // Panel side: text and widgets give many colours and a share of bright (text) pixels.
    std::set<int> colours;
    long bright = 0, total = 0;
    for (int y = 0; y < window.height; ++y) {
        for (int x = 0; x < std::min(ax - 20, 420); ++x) {
            const std::uint8_t* p = &window.pixels[(static_cast<std::size_t>(y) * window.width + x) * 3];
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
            bright += (p[0] + p[1] + p[2]) > 3 * 170;
            ++total;
        }
    }
    EXPECT_GT(colours.size(), 50u) << "panels: widgets and anti-aliased text";
    EXPECT_GT(bright, total / 200) << "panels: text";
    EXPECT_LT(bright, total / 4);
    // B sits to the right of A and differs from it (metal_blinn instead of metal).
    long differing = 0;
    for (int y = 0; y < shot.height; ++y) {
        for (int x = 0; x < shot.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const int bx = ax + shot.width + 8 + x;
                differing += bx < window.width &&
                             window.pixels[(static_cast<std::size_t>(ay + y) * window.width + bx) * 3 + c] !=
                                 shot.pixels[(static_cast<std::size_t>(y) * shot.width + x) * 3 + c];
            }
        }
    }
    EXPECT_GT(differing, 1000) << "compare: B shows a different material";
}

TEST_F(Explorer, BadSceneShowsAnErrorAndKeepsRunning) {
    TempDir dir;
    test::write_text(dir.file("bad.json"), R"({"objects": [{"shape": "sphere", "radius": -1}]})");
    test::write_text(dir.file("script.txt"), "save before.json\nload bad.json\nload missing.json\n"
                                             "key f1\ncapture nopanels.png\nsave after.json\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    // The bad loads left the scene alone.
    EXPECT_EQ(test::read_text(dir.file("before.json")), test::read_text(dir.file("after.json")));
    // F1 hid the panels: the left of the window is plain background now.
    const Rgb8Image window = read_png(dir.file("nopanels.png"));
    std::set<int> colours;
    for (int y = 100; y < 800; ++y) {
        for (int x = 0; x < 200; ++x) {
            const std::uint8_t* p = &window.pixels[(static_cast<std::size_t>(y) * window.width + x) * 3];
            colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
        }
    }
    EXPECT_LE(colours.size(), 3u);
}

// A script whose last command is `idle` still ends: the frame after the idle
// takes --capture-window and the explorer exits (it used to wait for input forever;
// `timeout` turns a regression into a failure instead of a hung suite).
TEST_F(Explorer, ScriptEndingOnIdleWritesTheCaptureAndExits) {
    TempDir dir;
    test::write_text(dir.file("script.txt"), "idle 0.3\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script",
                                                      "--capture-window", "window.png"},
                                         /*timeout_seconds=*/120);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_GT(read_png(dir.file("window.png")).width, 0);
}

TEST_F(Explorer, ScriptErrorsNameTheLineAndFailTheRun) {
    TempDir dir;
    test::write_text(dir.file("script.txt"), "# comment\nset objects[0].material.m -3\nfly away\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    EXPECT_NE(run.exit_code, 0);
    EXPECT_NE(run.err.find("script.txt:2: "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("objects[0].material.m"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("script.txt:3: unknown command 'fly'"), std::string::npos) << run.err;
}

// The Objects panel's shapes (explore/shapes.h): add each shape,
// change a sphere's shape; the saved scene loads and renders as the window shows it.
TEST_F(Explorer, AddsEveryShapeAndChangesAShape) {
    TempDir dir;
    test::write_text(dir.file("script.txt"), "figure spec_example\nadd_object cube\nadd_object cylinder\n"
                                             "add_object torus\nadd_object plane\nselect_object 0\nshape torus\n"
                                             "screenshot shot.png\nsave scene.json\nadd_object teapot\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    EXPECT_NE(run.exit_code, 0) << "the last line is an error";
    EXPECT_NE(run.err.find("script.txt:10: unknown shape 'teapot'"), std::string::npos) << run.err;
    const Scene scene = load_scene_file(dir.file("scene.json"), LoadContext::trusted());
    ASSERT_EQ(scene.objects.size(), 5u);
    const Shape expected[] = {Shape::torus, Shape::cube, Shape::cylinder, Shape::torus, Shape::plane};
    for (int i = 0; i < 5; ++i) EXPECT_EQ(scene.objects[i].shape, expected[i]) << i;
    // The floor is under the other objects.
    for (int i = 0; i < 4; ++i) EXPECT_GT(scene.objects[i].center.y, scene.objects[4].center.y);
    const test::RunResult render =
        test::run_m3055({"render", "--scene", dir.file("scene.json"), "--out", dir.file("render.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(test::read_text(dir.file("render.png")), test::read_text(dir.file("shot.png")));
}

// The Material panel's model selector lists every model of the table (it is
// built from it), and choosing each one through the selector's own code path
// gives a material the scene file format accepts.
TEST_F(Explorer, ModelSelectorListsEveryModelOfTheTable) {
    TempDir dir;
    std::string script = "print_models\n";
    for (const ModelSpec& model : model_table().models())
        script += "model " + model.name + "\nsave " + model.name + ".json\n";
    test::write_text(dir.file("script.txt"), script);
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    for (const ModelSpec& model : model_table().models()) {
        EXPECT_NE(run.out.find("model " + model.name + "\t" + model.label + "\n"), std::string::npos) << model.name;
        EXPECT_EQ(
            load_scene_file(dir.file(model.name + ".json"), LoadContext::trusted()).objects[0].material.model_name(),
            model.name);
    }
}

TEST_F(Explorer, BadStartingSceneIsAOneLineErrorNotACrash) {
    TempDir dir;
    test::write_text(dir.file("bad.json"), "{ not json");
    const ExplorerRun run = run_explorer(dir.path(), {"--scene", dir.file("bad.json")});
    EXPECT_NE(run.exit_code, 0);
    EXPECT_NE(run.err.find("bad.json"), std::string::npos) << run.err;
}

// Undo/redo (250 named steps), digit keys against unsaved edits and Ctrl+digit
// are unit tests of the explorer's logic without a window:
// tests/explore_undo_test.cpp and tests/explore_keys_test.cpp.

// F12 writes the next free NAME-0001.png (+ JSON) in the chosen folder and
// never overwrites; the PNG is what `m3055 render` writes for the JSON.
TEST_F(Explorer, F12WritesTheNextFreeNumberedScreenshot) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("shots"));
    test::write_text(dir.file("shots/m3055-0001.png"), "not mine");
    test::write_text(dir.file("script.txt"), "screenshot_dir shots\nkey f12\nset objects[0].material.m 3\nkey f12\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(test::read_text(dir.file("shots/m3055-0001.png")), "not mine");
    for (const std::string n : {"0002", "0003"}) {
        const std::string png = dir.file("shots/m3055-" + n + ".png"), json = dir.file("shots/m3055-" + n + ".json");
        ASSERT_TRUE(test::file_exists(png) && test::file_exists(json)) << n;
        const auto render = test::run_m3055({"render", "--scene", json, "--out", dir.file("r.png")});
        ASSERT_EQ(render.exit_code, 0) << render.err;
        EXPECT_EQ(test::read_text(png), test::read_text(dir.file("r.png"))) << n;
    }
    EXPECT_EQ(
        load_scene_file(dir.file("shots/m3055-0003.json"), LoadContext::trusted()).objects[0].material.number("m"),
        3.0);
}

// The pixel probe's numbers are the headless render's: the linear
// value of the --raw PFM, the PNG value and its display level; a click picks
// the object under it (the Material panel then edits it).
TEST_F(Explorer, PixelProbeEqualsTheHeadlessRender) {
    TempDir dir;
    test::write_text(dir.file("script.txt"), "figure fig10\nprobe 256 160\nprobe 100 160\nprobe 3 3\n"
                                             "click 420 160\nsave scene.json\nprint_state\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto render = test::run_m3055({"render", "--scene", dir.file("scene.json"), "--out", dir.file("r.png"),
                                         "--raw", dir.file("r.pfm")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const RgbFloatImage raw = read_pfm(dir.file("r.pfm"));
    const Rgb8Image png = read_png(dir.file("r.png"));
    const Scene scene = load_scene_file(dir.file("scene.json"), LoadContext::trusted());
    std::istringstream lines(run.out);
    int probes = 0;
    for (std::string line; std::getline(lines, line);) {
        int x = 0, y = 0, level[3], value[3];
        double linear[3];
        if (std::sscanf(line.c_str(), "probe pixel (%d, %d)\tlinear %lf %lf %lf\tlevel %d %d %d\tpng %d %d %d", &x, &y,
                        &linear[0], &linear[1], &linear[2], &level[0], &level[1], &level[2], &value[0], &value[1],
                        &value[2]) != 11)
            continue;
        ++probes;
        for (int c = 0; c < 3; ++c) {
            const float expected = raw.pixels[(std::size_t(raw.height - 1 - y) * raw.width + x) * 3 + c];
            EXPECT_NEAR(linear[c], expected, 1e-5 * std::max(1.0f, std::abs(expected))) << line;
            EXPECT_EQ(value[c], png.pixels[(std::size_t(y) * png.width + x) * 3 + c]) << line;
            // docs/spec.md#2-display: level = floor(c (2^bits - 1) + 0.5), clamped (no dithering here).
            const int top = (1 << scene.display.bits) - 1;
            EXPECT_EQ(level[c], std::clamp(int(std::floor(expected * top + 0.5)), 0, top)) << line;
        }
        if (x == 256) EXPECT_NE(line.find("object 1 (metal)"), std::string::npos) << line;
        if (x == 3) EXPECT_NE(line.find("background"), std::string::npos) << line;
        if (x != 3) EXPECT_NE(line.find("N.L "), std::string::npos) << line;
    }
    EXPECT_EQ(probes, 3) << run.out;
    EXPECT_NE(run.out.find("\tselected=2\n"), std::string::npos) << "the click on the right sphere: " << run.out;
}

// The softbox preset at 160 x 100 (its refine takes seconds, not 20), as
// softbox.json in `dir`.
void write_small_softbox(const TempDir& dir) {
    std::string scene = test::read_text(test::source_path("scenes/softbox_three_point.json"));
    scene = std::regex_replace(scene, std::regex("\"width\": 512"), "\"width\": 160");
    scene = std::regex_replace(scene, std::regex("\"height\": 320"), "\"height\": 100");
    test::write_text(dir.file("softbox.json"), scene);
}

// With area lights the display shows a fast preview while edits come, and
// once input stops it refines to exactly `m3055 render`'s pixels.
TEST_F(Explorer, AreaLightPreviewRefinesToTheRendersPixels) {
    TempDir dir;
    write_small_softbox(dir);
    test::write_text(dir.file("script.txt"), "load softbox.json\nset lights[0].size[0] 2.2\nsave_display preview.png\n"
                                             "settle 300\nsave_display refined.png\nsave scene.json\nscreenshot shot.png\n"
                                             "compare on\nsettle 300\nsave_display refined_split.png\n"
                                             "screenshot shot_split.png\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto render = test::run_m3055({"render", "--scene", dir.file("scene.json"), "--out", dir.file("r.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const Rgb8Image rendered = read_png(dir.file("r.png")), preview = read_png(dir.file("preview.png")),
                    refined = read_png(dir.file("refined.png"));
    ASSERT_EQ(rendered.width, 160);
    ASSERT_EQ(preview.width, 160) << "the preview keeps the display's size";
    EXPECT_NE(preview.pixels, rendered.pixels) << "while edits come, a fast preview";
    EXPECT_EQ(refined.pixels, rendered.pixels) << "refined: the render's pixels, byte for byte";
    // In the A/B split too: a read-out once refined keeps the refined pixels.
    EXPECT_EQ(read_png(dir.file("refined_split.png")).pixels, rendered.pixels) << "refined in the split";
    // A screenshot of a refined display writes its pixels (not drawn again): the render's, in the split too.
    EXPECT_EQ(read_png(dir.file("shot.png")).pixels, rendered.pixels) << "screenshot once refined";
    EXPECT_EQ(read_png(dir.file("shot_split.png")).pixels, rendered.pixels) << "screenshot once refined, in the split";
}

// F12 on a preview draws the render's pixels for the screenshot; the display,
// alone on screen, then shows them and is refined: no refine draws them again
// (20 s for the softbox at 512 x 320 on llvmpipe).
TEST_F(Explorer, ScreenshotOfAPreviewLeavesTheDisplayRefined) {
    TempDir dir;
    write_small_softbox(dir);
    test::write_text(dir.file("script.txt"), "load softbox.json\nset lights[0].size[0] 2.2\nprint_state\n"
                                             "screenshot shot.png\nprint_state\nsave_display after.png\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::size_t first = run.out.find("state title="), second = run.out.find("state title=", first + 1);
    ASSERT_NE(second, std::string::npos) << run.out;
    const std::string before = run.out.substr(first, second - first), after = run.out.substr(second);
    EXPECT_NE(before.find("busy=refining"), std::string::npos) << "a preview first: " << before;
    EXPECT_NE(after.find("busy=\t"), std::string::npos) << "refined by the screenshot: " << after;
    const auto render = test::run_m3055({"render", "--scene", dir.file("shot.json"), "--out", dir.file("r.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const Rgb8Image rendered = read_png(dir.file("r.png"));
    EXPECT_EQ(read_png(dir.file("shot.png")).pixels, rendered.pixels) << "the screenshot: the render's pixels";
    EXPECT_EQ(read_png(dir.file("after.png")).pixels, rendered.pixels) << "the display after it: the same";
}

// Light names (the scene format's optional "name"): the three-point presets
// name theirs, the Lights panel edits them, a save keeps them.
TEST_F(Explorer, LightNamesAreEditedAndKeptOnSave) {
    TempDir dir;
    test::write_text(dir.file("script.txt"), "light_preset three_point_white\nlight_name 2 rim\tlight\n"
                                             "light_name 1\nsave named.json\nload named.json\nsave again.json\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto doc = nlohmann::json::parse(test::read_text(dir.file("named.json")));
    EXPECT_EQ(doc["lights"][0]["name"], "key");
    EXPECT_FALSE(doc["lights"][1].contains("name")) << "an empty name is no name";
    EXPECT_EQ(doc["lights"][2]["name"], "rimlight") << "the tab (a control character) is dropped";
    EXPECT_EQ(test::read_text(dir.file("named.json")), test::read_text(dir.file("again.json")));
}

// The A/B read-outs: B differs from A in one parameter (the middle
// sphere's second lobe). The count of pixels on another level, the difference
// pane's image and the scanline profile equal direct computations on two
// headless renders of the same scenes.
TEST_F(Explorer, CompareReadoutsEqualTheHeadlessRenders) {
    TempDir dir;
    test::write_text(dir.file("script.txt"),
                     "figure fig10\nselect_object 1\ncopy_b\nset objects[1].material.lobes[1].m 0.25\n"
                     "compare on\ncompare_diff on\ndiff_scale 4\nprint_compare\nsave_difference diff4.png\n"
                     "diff_scale auto\nprint_compare\nsave_difference diff_auto.png\nprint_profile 170\n"
                     "save scene.json\ncapture window.png\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    // A: the saved scene; B: the same with the lobe copied into B before the edit.
    const auto ra = test::run_m3055({"render", "--scene", dir.file("scene.json"), "--out", dir.file("a.png")});
    const auto rb = test::run_m3055({"render", "--scene", dir.file("scene.json"), "--set",
                                     "objects[1].material.lobes[1].m=0.4", "--out", dir.file("b.png")});
    ASSERT_EQ(ra.exit_code, 0) << ra.err;
    ASSERT_EQ(rb.exit_code, 0) << rb.err;
    const Rgb8Image a = read_png(dir.file("a.png")), b = read_png(dir.file("b.png"));
    long differing = 0;
    int largest = 0;
    for (std::size_t p = 0; p < a.pixels.size(); p += 3) {
        bool any = false;
        for (std::size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c]));
            any |= d != 0;  // one PNG value per level: another byte is another level
            largest = std::max(largest, d);
        }
        differing += any;
    }
    ASSERT_GT(differing, 0) << "B must differ for the test to mean anything";
    const int automatic = 255 / largest;
    const std::string pixels = " pixels=" + std::to_string(a.pixels.size() / 3);
    EXPECT_NE(run.out.find("compare differing=" + std::to_string(differing) + pixels + " scale=4\n"), std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find("compare differing=" + std::to_string(differing) + pixels + " scale=" +
                           std::to_string(automatic) + "\n"),
              std::string::npos)
        << run.out;
    for (const auto& [file, scale] : {std::make_pair("diff4.png", 4), std::make_pair("diff_auto.png", automatic)}) {
        const Rgb8Image diff = read_png(dir.file(file));
        ASSERT_EQ(diff.pixels.size(), a.pixels.size()) << file;
        long wrong = 0;
        for (std::size_t i = 0; i < a.pixels.size(); ++i)
            wrong += diff.pixels[i] != std::min(255, std::abs(int(a.pixels[i]) - int(b.pixels[i])) * scale);
        EXPECT_EQ(wrong, 0) << file;
    }
    // The window (1500 x 940): A and B side by side and the difference pane
    // under A, all three 1:1 (the largest whole magnification that fits).
    const Rgb8Image window = read_png(dir.file("window.png"));
    const auto at_a = find_exact(window, a, 300), at_b = find_exact(window, b, 300);
    const auto at_diff = find_exact(window, read_png(dir.file("diff_auto.png")), 300);
    ASSERT_GE(at_a.first, 0);
    ASSERT_GE(at_b.first, 0);
    ASSERT_GE(at_diff.first, 0);
    EXPECT_EQ(at_b.second, at_a.second);
    EXPECT_GT(at_b.first, at_a.first + a.width);
    EXPECT_EQ(at_diff.first, at_a.first);
    EXPECT_GT(at_diff.second, at_a.second + a.height);
    // The profiles of row 170, A's and B's (dashed in the plot): the levels
    // whose PNG values the headless renders have there (they differ there).
    const std::size_t row_bytes = std::size_t(a.width) * 3, row_170 = 170 * row_bytes;
    ASSERT_FALSE(std::equal(a.pixels.begin() + long(row_170), a.pixels.begin() + long(row_170 + row_bytes),
                            b.pixels.begin() + long(row_170)));
    for (const auto& [name, image] : {std::make_pair(std::string("profile"), &a), std::make_pair(std::string("profile_b"), &b)}) {
        const std::regex profile_line(name + " row 170 bits 5\tR([ 0-9]+)\tG([ 0-9]+)\tB([ 0-9]+)\n");
        std::smatch match;
        ASSERT_TRUE(std::regex_search(run.out, match, profile_line)) << name << "\n" << run.out;
        for (int c = 0; c < 3; ++c) {
            std::istringstream levels(match[c + 1].str());
            int x = 0;
            for (int level; levels >> level; ++x) {
                ASSERT_LT(x, image->width);
                EXPECT_EQ(std::lround(level * 255.0 / 31.0), image->pixels[(std::size_t(170) * image->width + x) * 3 + c])
                    << name << " " << x;
            }
            EXPECT_EQ(x, image->width) << "one level per column";
        }
    }
}

// A .brdf file opened on an object (File > Open BRDF's action) is watched: a
// save with a GLSL error shows the error with the file's own line and keeps
// the last good image; the fixed file reloads, changes the image and keeps the
// value set before. A parse error likewise names its line.
TEST_F(Explorer, OpenedBrdfIsWatchedAndAnErrorKeepsTheLastGoodImage) {
    TempDir dir;
    const std::string good = test::read_text(test::source_path("tests/data/brdf/blinn_phong.brdf"));
    const std::string spec_line = "    float spec = pow(max(dot(N, H), 0), shininess);";
    const std::size_t at = good.find(spec_line);
    ASSERT_NE(at, std::string::npos);
    const int line = 1 + static_cast<int>(std::count(good.begin(), good.begin() + long(at), '\n'));
    std::string broken = good, unparsable = good, fixed = good;
    broken.replace(at, spec_line.size(), "    float spec = pow(max(dot(N, H), no_such_thing), shininess);");
    const std::size_t param_at = unparsable.find("float shininess 0 10000 32");
    const int param_line = 1 + static_cast<int>(std::count(good.begin(), good.begin() + long(param_at), '\n'));
    unparsable.replace(param_at, 26, "float shininess 0 10000 -5");
    fixed.replace(fixed.find("return kd / PI"), 14, "return 0.5 * kd / PI");
    test::write_text(dir.file("mine.brdf"), good);
    test::write_text(dir.file("broken.brdf"), broken);
    test::write_text(dir.file("unparsable.brdf"), unparsable);
    test::write_text(dir.file("fixed.brdf"), fixed);
    test::write_text(dir.file("script.txt"),
                     "open_brdf mine.brdf\nset objects[0].material.params.shininess 7\nscreenshot good.png\n"
                     "replace_file broken.brdf mine.brdf\nidle 1.2\nprint_brdf\nscreenshot still.png\n"
                     "replace_file unparsable.brdf mine.brdf\nidle 1.2\nprint_brdf\n"
                     "replace_file fixed.brdf mine.brdf\nidle 1.2\nprint_brdf\nscreenshot fixed.png\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<std::string> reports;
    std::istringstream lines(run.out);
    for (std::string l; std::getline(lines, l);)
        if (l.rfind("brdf error=", 0) == 0) reports.push_back(l);
    ASSERT_EQ(reports.size(), 3u) << run.out;
    EXPECT_NE(reports[0].find("mine.brdf:" + std::to_string(line) + ": error:"), std::string::npos) << reports[0];
    EXPECT_NE(reports[0].find("no_such_thing"), std::string::npos) << reports[0];
    EXPECT_NE(reports[0].find("status=not reloaded mine.brdf: an error"), std::string::npos) << reports[0];
    EXPECT_NE(reports[1].find("mine.brdf:" + std::to_string(param_line) + ": shininess: DEFAULT -5"), std::string::npos)
        << reports[1];
    EXPECT_EQ(reports[2], "brdf error=\tstatus=reloaded mine.brdf\terror=\tbusy=")
        << "fixed: the error is gone, and the window's own render (general programs) works";
    // The last good version kept rendering; the fixed one changed the image.
    EXPECT_EQ(test::read_text(dir.file("good.png")), test::read_text(dir.file("still.png")));
    EXPECT_NE(test::read_text(dir.file("good.png")), test::read_text(dir.file("fixed.png")));
    const auto scene = nlohmann::json::parse(test::read_text(dir.file("fixed.json")));
    EXPECT_EQ(scene["objects"][0]["material"]["params"]["shininess"], 7.0) << "the value set before is kept";
    const auto render = test::run_m3055({"render", "--scene", dir.file("fixed.json"), "--out", dir.file("r.png")});
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(test::read_text(dir.file("fixed.png")), test::read_text(dir.file("r.png")));
}

// A changed .brdf file is reloaded (checked, its programs compiled: seconds
// on llvmpipe) only once the explorer is idle, as a waiting specialization
// is compiled: while input keeps coming, frames keep drawing the last
// version and say "reloading", so no input waits for the compile.
TEST_F(Explorer, AChangedBrdfFileIsReloadedWhenIdleNotWhileInputComes) {
    TempDir dir;
    const std::string good = test::read_text(test::source_path("tests/data/brdf/blinn_phong.brdf"));
    std::string fixed = good;
    fixed.replace(fixed.find("return kd / PI"), 14, "return 0.5 * kd / PI");
    test::write_text(dir.file("mine.brdf"), good);
    test::write_text(dir.file("fixed.brdf"), fixed);
    // 120 frames of orbiting (one a script line): longer than two poll periods of the watcher.
    std::string script = "open_brdf mine.brdf\nidle 0.3\nreplace_file fixed.brdf mine.brdf\n";
    for (int i = 0; i < 120; ++i) script += i % 2 ? "orbit 1 0\n" : "orbit -1 0\n";
    script += "print_brdf\nidle 1.5\nprint_brdf\n";
    test::write_text(dir.file("script.txt"), script);
    const ExplorerRun run = run_explorer(dir.path(), {"--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    std::vector<std::string> reports;
    std::istringstream lines(run.out);
    for (std::string l; std::getline(lines, l);)
        if (l.rfind("brdf error=", 0) == 0) reports.push_back(l);
    ASSERT_EQ(reports.size(), 2u) << run.out;
    EXPECT_NE(reports[0].find("busy=reloading mine.brdf..."), std::string::npos)
        << "not while input kept coming: " << reports[0];
    EXPECT_NE(reports[1].find("status=reloaded"), std::string::npos) << "once idle: " << reports[1];
    EXPECT_EQ(reports[1].substr(reports[1].size() - 5), "busy=") << "nothing waits: " << reports[1];
}

// `explore --assignment A.json SCENE.json` shows the score and the
// reasons `m3055 grade` gives (both run grading::grade_one): for a worked
// submission, after an edit that breaks a rule, and for the scene saved with
// Ctrl+S to submit.
struct ShownGrade {
    double score = -1;
    std::vector<std::string> reasons;
};

std::vector<ShownGrade> shown_grades(const std::string& out) {
    std::vector<ShownGrade> grades;
    std::istringstream lines(out);
    const std::regex head(R"(grade score=([0-9.]+) max=([0-9.]+) passed=(yes|no))");
    for (std::string line; std::getline(lines, line);) {
        std::istringstream fields(line);
        std::string first;
        std::smatch m;
        if (!std::getline(fields, first, '\t') || !std::regex_match(first, m, head)) continue;
        ShownGrade g;
        g.score = std::stod(m[1]);
        for (std::string reason; std::getline(fields, reason, '\t');) g.reasons.push_back(reason);
        grades.push_back(g);
    }
    return grades;
}

nlohmann::json graded_student(const std::string& assignment, const std::string& submissions, const std::string& out,
                              const std::string& student) {
    const test::RunResult run = test::run_m3055({"grade", assignment, submissions, "--out", out});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json grades = nlohmann::json::parse(test::read_text(out + "/grades.json"));
    for (const auto& s : grades["students"])
        if (s["student"] == student) return s;
    ADD_FAILURE() << student << " not in " << out << "/grades.json";
    return {};
}

TEST_F(Explorer, AssignmentShowsTheScoreAndReasonsGradeGives) {
    TempDir dir;
    const std::string folder = test::source_path("assignments/three-point"), assignment = folder + "/assignment.json";
    std::filesystem::create_directories(dir.file("mine"));
    std::filesystem::copy_file(folder + "/submissions/dave.json", dir.file("mine/dave.json"));
    // dave: metal_blinn, not metal. Then d = 0.5 breaks the range rule too, and Ctrl+S saves.
    test::write_text(dir.file("script.txt"), "print_grade\nset objects[0].material.d 0.5\nprint_grade\nkey ctrl+s\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--assignment", assignment, dir.file("mine/dave.json"),
                                                      "--script", dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::vector<ShownGrade> shown = shown_grades(run.out);
    ASSERT_EQ(shown.size(), 2u) << run.out;

    const nlohmann::json dave = graded_student(assignment, folder + "/submissions", dir.file("out"), "dave");
    EXPECT_EQ(shown[0].score, dave["score"].get<double>());
    EXPECT_EQ(shown[0].reasons, dave["reasons"].get<std::vector<std::string>>());

    EXPECT_LT(shown[1].score, shown[0].score);
    bool range_reason = false;
    for (const std::string& r : shown[1].reasons) range_reason |= r.find("objects[0].material.d = 0.5") != std::string::npos;
    EXPECT_TRUE(range_reason) << run.out;

    const nlohmann::json saved = graded_student(assignment, dir.file("mine"), dir.file("out2"), "dave");
    EXPECT_EQ(saved["score"].get<double>(), shown[1].score);
    EXPECT_EQ(saved["reasons"].get<std::vector<std::string>>(), shown[1].reasons);
}

// With no scene, the student starts from a copy of the assignment's "start"
// scene (never the reference: that would score full marks untouched).
// A first practice names the file to submit before it exists: the start
// scene, written there by Ctrl+S. A .brdf material scores 0 with grade's
// reason unless --allow-brdf and the scene is a folder submission's
// scene.json, as `m3055 grade` has them.
TEST_F(Explorer, AssignmentNewSceneFileAndBrdfPermissionAsGradeHasThem) {
    TempDir dir;
    const std::string assignment = test::source_path("assignments/three-point/assignment.json");
    test::write_text(dir.file("new.txt"), "print_state\nkey ctrl+s\n");
    const ExplorerRun fresh = run_explorer(dir.path(), {"--assignment", assignment, "mine.json", "--script",
                                                        dir.file("new.txt"), "--exit-after-script"});
    ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
    EXPECT_EQ(load_scene_file(dir.file("mine.json"), LoadContext::trusted()).lights.size(), 1u)
        << "the start scene, saved where named";

    std::filesystem::copy_file(test::source_path("tests/data/brdf/lambert.brdf"), dir.file("lambert.brdf"));
    nlohmann::json scene = nlohmann::json::parse(test::read_text(dir.file("mine.json")));
    scene["objects"][0]["material"] = {{"model", "brdf"}, {"file", "lambert.brdf"}};
    test::write_text(dir.file("brdf.json"), scene.dump());
    // The same scene as a folder submission (NAME/scene.json beside its .brdf).
    std::filesystem::create_directory(dir.file("pat"));
    std::filesystem::copy_file(dir.file("lambert.brdf"), dir.file("pat/lambert.brdf"));
    test::write_text(dir.file("pat/scene.json"), scene.dump());
    test::write_text(dir.file("grade.txt"), "print_grade\n");
    struct Try {
        const char* scene;
        bool allow;
        const char* expected;  // in the first reason, or in the output when graded
    };
    for (const Try& t : {Try{"brdf.json", false, "objects[0].material.file: a .brdf file is code"},
                         Try{"brdf.json", true, "a submission that names a file (a .brdf material, a model) is a folder"},
                         Try{"pat/scene.json", true, "objects[0] is lambert (.brdf), not metal"}}) {
        std::vector<std::string> args = {"--assignment", assignment, t.scene, "--script", dir.file("grade.txt"),
                                         "--exit-after-script"};
        if (t.allow) args.push_back("--allow-brdf");
        const ExplorerRun run = run_explorer(dir.path(), args);
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const std::vector<ShownGrade> shown = shown_grades(run.out);
        ASSERT_EQ(shown.size(), 1u) << run.out;
        const bool graded = std::string(t.scene) == "pat/scene.json";
        if (graded) {
            // Graded: the rules see the file's model, named as people read it.
            EXPECT_NE(run.out.find(t.expected), std::string::npos) << run.out;
        } else {
            ASSERT_FALSE(shown[0].reasons.empty()) << run.out;
            EXPECT_NE(shown[0].reasons[0].find(t.expected), std::string::npos) << run.out;
            EXPECT_EQ(shown[0].score, 0.0) << t.scene;
        }
    }
}

TEST_F(Explorer, AssignmentWithoutASceneStartsFromACopyOfItsStart) {
    TempDir dir;
    const std::string folder = test::source_path("assignments/three-point");
    test::write_text(dir.file("script.txt"), "print_state\nprint_grade\nsave copy.json\n");
    const ExplorerRun run = run_explorer(dir.path(), {"--assignment", folder + "/assignment.json", "--script",
                                                      dir.file("script.txt"), "--exit-after-script"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("state title=start.json (copy)"), std::string::npos) << run.out;
    EXPECT_EQ(load_scene_file(dir.file("copy.json"), LoadContext::trusted()).lights.size(), 1u);
    const std::vector<ShownGrade> shown = shown_grades(run.out);
    ASSERT_EQ(shown.size(), 1u) << run.out;
    EXPECT_LT(shown[0].score, 100.0);
}

}  // namespace
}  // namespace m3055
